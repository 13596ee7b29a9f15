// ray / gpu_ray sensors: Gazebo's ray sensor on Physics::cast_rays, and what its ROS plugins make
// of the rays: gazebo_ros_laser's scan, gazebo_ros_range's shortest ray, gazebo_ros_block_laser's
// point cloud.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/transform.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

namespace {

struct RayState : ChannelState {
  std::vector<description::Vec3> directions_W;  // scratch: this sample's ray directions
  std::vector<double> hits;                     // scratch: distances from the sensor origin
  std::vector<int> geoms;                       // scratch: the geom each ray hit (-1: none)
};

double step_of(int count, const description::RayAxis& a) {
  return count > 1 ? (a.max_angle - a.min_angle) / (count - 1) : 0.0;
}

// The rays cast along one axis: Gazebo's physical rays (<samples>) for the plugins that read
// them (range, block laser), or the scan's ranges (samples x resolution: mechsim casts those
// instead of interpolating).
int rays_along(const description::RaySpec& ray, const description::RayAxis& a) {
  return ray.output == description::RayOutput::Scan ? a.count() : std::max(1, a.samples);
}

}  // namespace

RaySensor::RaySensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix)
    : Sensor(spec, prefix), ray_(std::get<description::RaySpec>(this->spec().details)) {
  RaySensor::bind(model);
  nh_ = rays_along(ray_, ray_.horizontal);
  nv_ = rays_along(ray_, ray_.vertical);
  const double dh = step_of(nh_, ray_.horizontal), dv = step_of(nv_, ray_.vertical);
  directions_S_.reserve(static_cast<std::size_t>(nh_) * static_cast<std::size_t>(nv_));
  for (int j = 0; j < nv_; ++j) {
    // Vertical angles turn the ray up towards +z (Gazebo: pitch = -vertical angle).
    const double pitch = ray_.vertical.min_angle + j * dv;
    for (int i = 0; i < nh_; ++i) {
      const double yaw = ray_.horizontal.min_angle + i * dh;
      directions_S_.push_back({std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)});
    }
  }
  layout_.angle_min = ray_.horizontal.min_angle;
  layout_.angle_max = ray_.horizontal.max_angle;
  layout_.angle_increment = dh;
  layout_.vertical_angle_min = ray_.vertical.min_angle;
  layout_.vertical_angle_max = ray_.vertical.max_angle;
  layout_.vertical_angle_increment = dv;
  layout_.horizontal_count = nh_;
  layout_.vertical_count = nv_;
  layout_.range_min = ray_.range_min;
  layout_.range_max = ray_.range_max;
  layout_.scan_time = spec.update_rate > 0.0 ? 1.0 / spec.update_rate : 0.0;
}

void RaySensor::bind(const physics::PhysicsModel& model) {
  link_ = resolve_link(model);
  // Gazebo's ray sensor does not see its own link; the link lives in this MuJoCo body (with any
  // massless links merged into it, as Gazebo lumps fixed links).
  filter_ = physics::make_ray_filter(model, model.links()[link_].body,
                                     ray_.gpu ? physics::RayTargets::Visual : physics::RayTargets::Collision);
}

std::unique_ptr<SensorState> RaySensor::make_state(Rng rng) const {
  auto state = std::make_unique<RayState>();
  state->rng = std::move(rng);
  state->channels.push_back(start_noise(ray_.noise, state->rng));  // one bias for all rays
  state->directions_W.resize(directions_S_.size());
  state->hits.resize(directions_S_.size());
  state->geoms.resize(directions_S_.size());
  return state;
}

void RaySensor::sample(const physics::Physics& physics, double time, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<RayState&>(base);
  const description::Pose X_WS = physics::compose(physics.link_pose(link_), spec().pose);
  for (std::size_t k = 0; k < directions_S_.size(); ++k)
    state.directions_W[k] = physics::rotate(X_WS.orientation, directions_S_[k]);
  physics.cast_rays(filter_, X_WS.position, state.directions_W.data(), state.directions_W.size(), ray_.range_min,
                    ray_.range_max, state.hits.data(), state.geoms.data());
  switch (ray_.output) {
    case description::RayOutput::Scan: fill_scan(physics, time, state, out); break;
    case description::RayOutput::Range: fill_range(state, out); break;
    case description::RayOutput::PointCloud: fill_cloud(physics, state, out); break;
  }
}

void RaySensor::fill_scan(const physics::Physics& physics, double time, ChannelState& base, SensorOutput& out) const {
  auto& state = static_cast<RayState&>(base);
  if (!std::holds_alternative<LaserScan>(out)) {
    out = layout_;
    std::get<LaserScan>(out).ranges.resize(directions_S_.size());
    std::get<LaserScan>(out).intensities.assign(directions_S_.size(), 0.0f);
  }
  LaserScan& scan = std::get<LaserScan>(out);
  const double dt = state.last_sample >= 0.0 ? time - state.last_sample : 0.0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < state.hits.size(); ++k) {
    double r = state.hits[k];
    // As Gazebo's RaySensor (REP 117): at or beyond the maximum +inf, at or below the minimum
    // -inf; noise only on the others, clamped to the limits.
    if (r >= ray_.range_max) {
      r = kInf;
    } else if (r <= ray_.range_min) {
      r = -kInf;
    } else if (ray_.noise.active()) {
      r = std::clamp(apply_noise(ray_.noise, state.channels[0], r, k == 0 ? dt : 0.0, state.rng), ray_.range_min,
                     ray_.range_max);
    }
    scan.ranges[k] = static_cast<float>(r);
    // Gazebo reports each ray's retro-reflectivity: the laser_retro of the shape it hit.
    scan.intensities[k] = static_cast<float>(physics.model().geom_laser_retro(state.geoms[k]));
  }
}

// gazebo_ros_range: the shortest of the sensor's raw rays (a ray that hits nothing within the
// maximum counts as the maximum), plus N(0, gaussianNoise) when below the maximum, capped there.
void RaySensor::fill_range(ChannelState& base, SensorOutput& out) const {
  auto& state = static_cast<RayState&>(base);
  if (!std::holds_alternative<RangeReading>(out)) {
    RangeReading r;
    r.radiation = ray_.radiation;
    r.field_of_view = ray_.fov;
    r.min_range = ray_.range_min;
    r.max_range = ray_.range_max;
    out = r;
  }
  RangeReading& r = std::get<RangeReading>(out);
  double shortest = ray_.range_max;
  for (const double h : state.hits) shortest = std::min(shortest, h);
  if (shortest < ray_.range_max && ray_.plugin_noise > 0.0)
    shortest = std::min(shortest + ray_.plugin_noise * standard_normal(state.rng), ray_.range_max);
  r.range = shortest;
}

// gazebo_ros_block_laser: samples x resolution points per axis, each interpolated between the
// (up to) four raw rays around it as the plugin does: the range bilinearly (each ray capped at
// max - min), the intensity as the mean of the four rays' retro-reflectivity, the direction
// half-way between the rays that bound it, and the point's z negated (the plugin's sign:
// z = -r sin(vertical angle)). Noise N(0, gaussianNoise) on each coordinate, except for points
// at the cap, and on every intensity.
void RaySensor::fill_cloud(const physics::Physics& physics, ChannelState& base, SensorOutput& out) const {
  auto& state = static_cast<RayState&>(base);
  if (!std::holds_alternative<PointCloudReading>(out)) out = PointCloudReading{};
  PointCloudReading& cloud = std::get<PointCloudReading>(out);
  const int range_count = ray_.horizontal.count(), vertical_range_count = ray_.vertical.count();
  const std::size_t n = static_cast<std::size_t>(range_count) * static_cast<std::size_t>(vertical_range_count);
  cloud.points.resize(n);
  cloud.intensities.resize(n);
  const double cap = ray_.range_max - ray_.range_min;
  const auto range_of = [&](int ray) { return std::min(state.hits[static_cast<std::size_t>(ray)], cap); };
  const auto retro_of = [&](int ray) { return physics.model().geom_laser_retro(state.geoms[static_cast<std::size_t>(ray)]); };
  const double y_step = nh_ > 1 ? (ray_.horizontal.max_angle - ray_.horizontal.min_angle) / (nh_ - 1) : 0.0;
  const double p_step = nv_ > 1 ? (ray_.vertical.max_angle - ray_.vertical.min_angle) / (nv_ - 1) : 0.0;
  const double sigma = ray_.plugin_noise;
  const auto noise = [&]() { return sigma > 0.0 ? sigma * standard_normal(state.rng) : 0.0; };
  std::size_t k = 0;
  for (int j = 0; j < vertical_range_count; ++j) {
    double vb = vertical_range_count == 1 ? 0.0 : static_cast<double>(j) * (nv_ - 1) / (vertical_range_count - 1);
    const int vja = static_cast<int>(std::floor(vb));
    const int vjb = std::min(vja + 1, nv_ - 1);
    vb -= std::floor(vb);
    const double p_angle = 0.5 * (vja + vjb) * p_step + ray_.vertical.min_angle;
    for (int i = 0; i < range_count; ++i, ++k) {
      double hb = range_count == 1 ? 0.0 : static_cast<double>(i) * (nh_ - 1) / (range_count - 1);
      const int hja = static_cast<int>(std::floor(hb));
      const int hjb = std::min(hja + 1, nh_ - 1);
      hb -= std::floor(hb);
      const int j1 = hja + vja * nh_, j2 = hjb + vja * nh_, j3 = hja + vjb * nh_, j4 = hjb + vjb * nh_;
      const double r = (1 - vb) * ((1 - hb) * range_of(j1) + hb * range_of(j2)) + vb * ((1 - hb) * range_of(j3) + hb * range_of(j4));
      const double intensity = 0.25 * (retro_of(j1) + retro_of(j2) + retro_of(j3) + retro_of(j4));
      const double y_angle = 0.5 * (hja + hjb) * y_step + ray_.horizontal.min_angle;
      Vec3 p{r * std::cos(p_angle) * std::cos(y_angle), r * std::cos(p_angle) * std::sin(y_angle), -r * std::sin(p_angle)};
      if (std::abs(cap - r) >= 1e-6) p = {p.x + noise(), p.y + noise(), p.z + noise()};
      cloud.points[k] = p;
      cloud.intensities[k] = static_cast<float>(intensity + noise());
    }
  }
}

}  // namespace mechsim::sensors
