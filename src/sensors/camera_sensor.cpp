// Camera sensors: Gazebo's camera, depth and multicamera sensors rendered by physics::Renderer
// (sensors/README.md, "Cameras").
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/transform.hpp"
#include "sensors/render_hub.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kNoiseTable = 1u << 16;  // power of two

struct CameraState : SensorState {
  std::vector<physics::Frame> frames;  // scratch: one render per lens
  std::vector<float> noise;            // seeded normal draws (colour levels), see README
  // Per lens with distortion: for each output pixel, its source (u, v) in the rendered image.
  // Made at the lens's first frame: a 1280x720 map takes tens of ms, and most runs never render.
  std::vector<std::vector<float>> undistort;
};

// SDF's camera looks along +x with +z up; the optical frame has z forward, x right, y down.
const description::Quat kOptical = physics::quat_from_rpy(-kPi / 2, 0.0, -kPi / 2);

// OpenCV's plumb_bob inverted by fixed-point iteration: the undistorted normalised point whose
// distortion is (xd, yd).
void undistort_point(const description::DistortionSpec& d, double xd, double yd, double& x, double& y) {
  x = xd;
  y = yd;
  for (int i = 0; i < 20; ++i) {
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    const double dx = 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x);
    const double dy = d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y;
    x = (xd - dx) / radial;
    y = (yd - dy) / radial;
  }
}

std::uint8_t bilinear(const std::vector<std::uint8_t>& rgb, int w, int h, float u, float v, int c) {
  u = std::clamp(u, 0.0f, static_cast<float>(w - 1));
  v = std::clamp(v, 0.0f, static_cast<float>(h - 1));
  const int u0 = static_cast<int>(u), v0 = static_cast<int>(v);
  const int u1 = std::min(u0 + 1, w - 1), v1 = std::min(v0 + 1, h - 1);
  const float a = u - static_cast<float>(u0), b = v - static_cast<float>(v0);
  auto at = [&](int uu, int vv) { return static_cast<float>(rgb[(static_cast<std::size_t>(vv) * w + uu) * 3 + c]); };
  const float top = at(u0, v0) * (1 - a) + at(u1, v0) * a, bottom = at(u0, v1) * (1 - a) + at(u1, v1) * a;
  return static_cast<std::uint8_t>(std::lround(std::clamp(top * (1 - b) + bottom * b, 0.0f, 255.0f)));
}

}  // namespace

CameraSensor::CameraSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model)
    : Sensor(spec), camera_(std::get<description::CameraSpec>(this->spec().details)) {
  link_ = resolve_link(model);
  if (camera_.lenses.empty()) throw SensorError(spec.where() + ": a camera sensor without a <camera>");
  for (const description::CameraLens& l : camera_.lenses) {
    Lens lens;
    physics::CameraView& v = lens.view;
    v.width = l.width;
    v.height = l.height;
    // The plugin's intrinsics are what CameraInfo reports; mechsim renders through them, so the
    // image and K/P agree (Gazebo renders from the FOV whatever the plugin says).
    const double f = camera_.focal_length > 0.0 ? camera_.focal_length : l.width / (2.0 * std::tan(l.horizontal_fov / 2.0));
    v.fx = v.fy = f;
    v.cx = camera_.cx > 0.0 ? camera_.cx : (l.width + 1.0) / 2.0;
    v.cy = camera_.cy > 0.0 ? camera_.cy : (l.height + 1.0) / 2.0;
    v.near = l.near;
    v.far = l.far;
    if (const std::string bad = physics::check_view(v); !bad.empty())
      throw SensorError(spec.where() + ": camera '" + l.name + "' cannot be rendered: " + bad);
    lens.X_LC = physics::compose(spec.pose, physics::compose(l.pose, {{0, 0, 0}, kOptical}));

    CameraInfo& info = lens.info;
    info.width = l.width;
    info.height = l.height;
    info.D = camera_.ros_distortion;
    info.K = {f, 0, v.cx, 0, f, v.cy, 0, 0, 1};
    info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double cx_prime = camera_.cx_prime > 0.0 ? camera_.cx_prime : v.cx;
    // gazebo_ros_multicamera gives the hack baseline to its right camera; the others to theirs.
    const bool right = camera_.lenses.size() == 1 || l.name.find("right") != std::string::npos;
    const double baseline = right ? camera_.hack_baseline : 0.0;
    info.P = {f, 0, cx_prime, -f * baseline, 0, f, v.cy, 0, 0, 0, 1, 0};

    lenses_.push_back(std::move(lens));
  }
}

namespace {

std::vector<float> undistort_map(const description::DistortionSpec& d, const physics::CameraView& v) {
  std::vector<float> map(static_cast<std::size_t>(v.width) * v.height * 2);
  const double f = v.fx;
  for (int r = 0; r < v.height; ++r) {
    for (int c = 0; c < v.width; ++c) {
      double x = 0, y = 0;
      undistort_point(d, (c - v.cx) / f, (r - v.cy) / f, x, y);
      const std::size_t k = (static_cast<std::size_t>(r) * v.width + c) * 2;
      map[k] = static_cast<float>(f * x + v.cx);
      map[k + 1] = static_cast<float>(f * y + v.cy);
    }
  }
  return map;
}

}  // namespace

std::pair<int, int> CameraSensor::render_size() const {
  int w = 0, h = 0;
  for (const Lens& l : lenses_) {
    w = std::max(w, l.view.width);
    h = std::max(h, l.view.height);
  }
  return {w, h};
}

std::unique_ptr<SensorState> CameraSensor::make_state(Rng rng) const {
  auto state = std::make_unique<CameraState>();
  state->rng = std::move(rng);
  state->frames.resize(lenses_.size());
  state->undistort.resize(lenses_.size());
  const description::NoiseSpec& n = camera_.lenses.front().noise;
  if (n.stddev > 0.0 || n.mean != 0.0) {
    state->noise.resize(kNoiseTable);
    for (float& x : state->noise) x = static_cast<float>(255.0 * (n.mean + n.stddev * standard_normal(state->rng)));
  }
  return state;
}

void CameraSensor::sample(const physics::Physics& physics, double, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<CameraState&>(base);
  if (!std::holds_alternative<CameraReading>(out)) {
    CameraReading r;
    for (std::size_t i = 0; i < lenses_.size(); ++i) {
      CameraImage im;
      im.name = camera_.lenses[i].name;
      im.info = lenses_[i].info;
      r.images.push_back(std::move(im));
    }
    out = std::move(r);
  }
  CameraReading& reading = std::get<CameraReading>(out);
  physics::Renderer* renderer = state.render != nullptr ? state.render->scene(physics) : nullptr;
  if (renderer == nullptr) {
    reading.error = state.render != nullptr ? state.render->error() : "no renderer attached to the camera";
    return;
  }
  const description::Pose X_WL = physics.link_pose(link_);
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < lenses_.size(); ++i) {
    const Lens& lens = lenses_[i];
    physics::CameraView view = lens.view;
    view.X_WC = physics::compose(X_WL, lens.X_LC);
    physics::Frame& frame = state.frames[i];
    renderer->render(view, frame, true, camera_.depth);
    state.render->count_render();
    CameraImage& im = reading.images[i];
    const std::size_t n = static_cast<std::size_t>(view.width) * view.height;
    im.rgb.resize(n * 3);
    std::vector<float>& undistort = state.undistort[i];
    const description::DistortionSpec& distortion = camera_.lenses[i].distortion;
    if (undistort.empty() && distortion.active()) undistort = undistort_map(distortion, lens.view);
    if (undistort.empty()) {
      std::copy(frame.rgb.begin(), frame.rgb.end(), im.rgb.begin());
    } else {
      for (std::size_t k = 0; k < n; ++k)
        for (int c = 0; c < 3; ++c)
          im.rgb[k * 3 + c] = bilinear(frame.rgb, view.width, view.height, undistort[2 * k], undistort[2 * k + 1], c);
    }
    if (!state.noise.empty()) {
      // A random start in the table per frame (one draw), so frames differ and stay reproducible.
      std::size_t at = static_cast<std::size_t>(uniform01(state.rng) * kNoiseTable);
      for (std::uint8_t& px : im.rgb) {
        const float v = static_cast<float>(px) + state.noise[at++ & (kNoiseTable - 1)];
        px = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 255.0f)));
      }
    }
    if (!camera_.depth) continue;
    im.depth.resize(n);
    im.points.resize(n * 3);
    const float lo = static_cast<float>(camera_.point_cloud_cutoff), hi = static_cast<float>(camera_.point_cloud_cutoff_max);
    const double f = view.fx;
    for (int r = 0; r < view.height; ++r) {
      for (int c = 0; c < view.width; ++c) {
        const std::size_t k = static_cast<std::size_t>(r) * view.width + c;
        const float z = frame.depth[k];
        float* p = &im.points[k * 3];
        if (z > lo && z < hi) {
          im.depth[k] = z;
          p[0] = static_cast<float>((c - view.cx) * z / f);
          p[1] = static_cast<float>((r - view.cy) * z / f);
          p[2] = z;
        } else {
          im.depth[k] = p[0] = p[1] = p[2] = kNaN;
        }
      }
    }
  }
  reading.error.clear();
}

}  // namespace mechsim::sensors
