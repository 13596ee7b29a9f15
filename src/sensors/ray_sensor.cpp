// ray / gpu_ray sensors: Gazebo's ray sensor on Physics::cast_rays.
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
};

double step_of(const description::RayAxis& a) {
  return a.count() > 1 ? (a.max_angle - a.min_angle) / (a.count() - 1) : 0.0;
}

}  // namespace

RaySensor::RaySensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix)
    : Sensor(spec, prefix), ray_(std::get<description::RaySpec>(this->spec().details)) {
  RaySensor::bind(model);
  const int nh = ray_.horizontal.count(), nv = ray_.vertical.count();
  const double dh = step_of(ray_.horizontal), dv = step_of(ray_.vertical);
  directions_S_.reserve(static_cast<std::size_t>(nh) * static_cast<std::size_t>(nv));
  for (int j = 0; j < nv; ++j) {
    // Vertical angles turn the ray up towards +z (Gazebo: pitch = -vertical angle).
    const double pitch = ray_.vertical.min_angle + j * dv;
    for (int i = 0; i < nh; ++i) {
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
  layout_.horizontal_count = nh;
  layout_.vertical_count = nv;
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
  return state;
}

void RaySensor::sample(const physics::Physics& physics, double time, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<RayState&>(base);
  if (!std::holds_alternative<LaserScan>(out)) {
    out = layout_;
    std::get<LaserScan>(out).ranges.resize(directions_S_.size());
    std::get<LaserScan>(out).intensities.assign(directions_S_.size(), 0.0f);
  }
  LaserScan& scan = std::get<LaserScan>(out);
  const description::Pose X_WS = physics::compose(physics.link_pose(link_), spec().pose);
  for (std::size_t k = 0; k < directions_S_.size(); ++k)
    state.directions_W[k] = physics::rotate(X_WS.orientation, directions_S_[k]);
  physics.cast_rays(filter_, X_WS.position, state.directions_W.data(), state.directions_W.size(), ray_.range_min,
                    ray_.range_max, state.hits.data());
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
  }
}

}  // namespace mechsim::sensors
