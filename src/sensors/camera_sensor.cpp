// Camera sensors: Gazebo's camera, depth and multicamera sensors rendered by physics::Renderer
// (sensors/README.md, "Cameras").
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "physics/transform.hpp"
#include "sensors/render_hub.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kNoiseTable = 1u << 16;  // power of two

// One output pixel of a distorted image: bilinear interpolation in the rendered image between the
// byte `at` (top left), its right neighbour `at + du` and the row below `at + dv`, weights a, b.
struct Tap {
  std::uint32_t at = 0;
  std::uint16_t du = 0, dv = 0;
  float a = 0.0f, b = 0.0f;
};

// One output pixel of bilinear resampling, 8-bit RGB, a channel at a time: a convex combination of
// levels, in [0, 255], rounded half up.
void resample_pixel(const Tap& t, const std::uint8_t* src, std::uint8_t* out) {
  const std::uint8_t* p = src + t.at;
  for (int c = 0; c < 3; ++c) {
    const float top = p[c] + t.a * static_cast<float>(p[c + t.du] - p[c]);
    const float bottom = p[c + t.dv] + t.a * static_cast<float>(p[c + t.dv + t.du] - p[c + t.dv]);
    out[c] = static_cast<std::uint8_t>(top + t.b * (bottom - top) + 0.5f);
  }
}

#if defined(__SSE2__)
__m128 four_levels(const std::uint8_t* p) {
  std::int32_t word;
  std::memcpy(&word, p, 4);
  const __m128i zero = _mm_setzero_si128();
  const __m128i bytes = _mm_cvtsi32_si128(word);
  return _mm_cvtepi32_ps(_mm_unpacklo_epi16(_mm_unpacklo_epi8(bytes, zero), zero));
}

// Bilinear resampling through `map` (`src` holds src_size bytes): one pixel's three channels in one
// SSE2 vector (the fourth lane wasted), the same float operations in the same order as
// resample_pixel, so the bytes are the same (checked against it on 1280x720 random images and
// maps); 2.1x faster than a channel at a time (8.7 -> 4.1 ms a 1280x720 image). Taps whose 4-byte
// reads would pass the end of `src` (the bottom-right pixel) and the last pixel go the scalar way.
void resample(const std::vector<Tap>& map, const std::uint8_t* src, std::size_t src_size, std::uint8_t* dst) {
  const std::size_t n = map.size();
  if (n == 0) return;
  const __m128 half = _mm_set1_ps(0.5f);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Tap& t = map[k];
    if (static_cast<std::size_t>(t.at) + t.dv + t.du + 4 > src_size) {
      resample_pixel(t, src, dst + 3 * k);
      continue;
    }
    const std::uint8_t* p = src + t.at;
    const __m128 a = _mm_set1_ps(t.a), b = _mm_set1_ps(t.b);
    const __m128 p00 = four_levels(p), p01 = four_levels(p + t.du), p10 = four_levels(p + t.dv),
                 p11 = four_levels(p + t.dv + t.du);
    const __m128 top = _mm_add_ps(p00, _mm_mul_ps(a, _mm_sub_ps(p01, p00)));
    const __m128 bottom = _mm_add_ps(p10, _mm_mul_ps(a, _mm_sub_ps(p11, p10)));
    const __m128 v = _mm_add_ps(_mm_add_ps(top, _mm_mul_ps(b, _mm_sub_ps(bottom, top))), half);
    const __m128i i32 = _mm_cvttps_epi32(v);  // truncation, as the scalar cast; in [0, 255]
    const __m128i i8 = _mm_packus_epi16(_mm_packs_epi32(i32, i32), _mm_setzero_si128());
    const std::int32_t word = _mm_cvtsi128_si32(i8);
    std::memcpy(dst + 3 * k, &word, 4);  // its fourth byte is the next pixel's first, written next
  }
  resample_pixel(map[n - 1], src, dst + 3 * (n - 1));
}
#else
void resample(const std::vector<Tap>& map, const std::uint8_t* src, std::size_t /*src_size*/, std::uint8_t* dst) {
  for (std::size_t k = 0; k < map.size(); ++k) resample_pixel(map[k], src, dst + 3 * k);
}
#endif

// One run of noise: dst = src + noise, clamped to the levels (vectorised by the compiler; the
// pointers never overlap but may be equal, which the in-place instance tells it).
template <bool kInPlace>
void noise_run(const std::uint8_t* __restrict src, std::uint8_t* __restrict dst, const std::int16_t* __restrict noise,
               std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const int v = (kInPlace ? dst[i] : src[i]) + noise[i];
    dst[i] = static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
  }
}

// dst = src + noise (src == dst: in place), the noise read from `table` (a power of two long) from
// `at` on, wrapping: in runs of the table's contiguous entries.
void add_noise(const std::uint8_t* src, std::uint8_t* dst, std::size_t n, const std::vector<std::int16_t>& table,
               std::size_t at) {
  const std::size_t size = table.size();
  at &= size - 1;
  while (n > 0) {
    const std::size_t run = std::min(n, size - at);
    if (src == dst) noise_run<true>(nullptr, dst, table.data() + at, run);
    else noise_run<false>(src, dst, table.data() + at, run);
    src += run;
    dst += run;
    n -= run;
    at = 0;
  }
}

struct CameraState : SensorState {
  std::vector<std::int16_t> noise;  // seeded normal draws rounded to colour levels, see README
  // Per lens with distortion: for each output pixel, where it comes from in the rendered image.
  // Made at the lens's first frame: a 1280x720 map takes tens of ms, and most runs never render.
  std::vector<std::vector<Tap>> undistort;
};

// SDF's camera looks along +x with +z up; the optical frame has z forward, x right, y down.
const description::Quat kOptical = physics::quat_from_rpy(-kPi / 2, 0.0, -kPi / 2);

// Brown's model (OpenCV's plumb_bob: Gazebo's Distortion::Distort) inverted by fixed-point
// iteration: the undistorted normalised point whose distortion is (xd, yd).
void distort_point(const description::DistortionSpec& d, double x, double y, double& xd, double& yd) {
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  xd = x * radial + 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x);
  yd = y * radial + d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y;
}

// False when no point distorts to (xd, yd) (beyond the largest radius a barrel reaches).
bool undistort_point(const description::DistortionSpec& d, double xd, double yd, double& x, double& y) {
  x = xd;
  y = yd;
  for (int i = 0; i < 20; ++i) {
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    if (!(radial > 0.0)) return false;
    const double dx = 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x);
    const double dy = d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y;
    x = (xd - dx) / radial;
    y = (yd - dy) / radial;
  }
  double cx = 0, cy = 0;
  distort_point(d, x, y, cx, cy);
  return std::abs(cx - xd) + std::abs(cy - yd) < 1e-6 * (1.0 + std::abs(xd) + std::abs(yd));
}

}  // namespace

void CameraSensor::bind(const physics::PhysicsModel& model) { link_ = resolve_link(model); }

CameraSensor::CameraSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model,
                           const std::string& prefix)
    : Sensor(spec, prefix), camera_(std::get<description::CameraSpec>(this->spec().details)) {
  CameraSensor::bind(model);
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
    lens.render = v;
    lens.render_X_LC = lens.X_LC;
    lens.render_depth = camera_.depth;

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

// Gazebo 11's distortion (rendering::Distortion) as a map: each pixel of the distorted image
// `out` takes the point of the ideal (undistorted) image that Brown's model moves there. Gazebo
// works in normalised texture coordinates u = x / W, v = y / H about `center`, scaling both by
// T / f (T = max(W, H), f = the FOV's focal length), so the coefficients are OpenCV's plumb_bob in
// pixels for a square image (for another shape the vertical axis is scaled by H, not W, as there).
// A barrel-distorted image is cropped (scaled about its middle by the distortion of the corners,
// taken without the T / f scaling, as Gazebo does) unless <borderCrop> is false. Points whose
// source lies outside the ideal image take the image's top-left pixel, as Gazebo's unset map
// entries (0, 0) do. mechsim renders through the plugin's K, so the ideal image's middle is the
// principal point; the source is then projected through `src`'s intrinsics (a shared render).
std::vector<Tap> undistort_map(const description::DistortionSpec& d, double hfov, const physics::CameraView& out,
                               const physics::CameraView& src) {
  std::vector<Tap> map(static_cast<std::size_t>(out.width) * out.height);
  const int w = src.width, h = src.height;
  const double W = out.width, H = out.height, T = std::max(W, H);
  const double f = W / (2.0 * std::tan(hfov / 2.0));
  double scale_x = 1.0, scale_y = 1.0;
  if (d.crop && d.k1 < 0.0) {
    const auto corner = [&](double u, double v, double& du, double& dv) {
      const double x = u - d.center_x, y = v - d.center_y, r2 = x * x + y * y;
      const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
      du = d.center_x + x * radial + d.p2 * (r2 + 2 * x * x) + 2 * d.p1 * x * y;
      dv = d.center_y + y * radial + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y;
    };
    double ax, ay, bx, by;
    corner(0.0, 0.0, ax, ay);
    corner(1.0, 1.0, bx, by);
    if (bx - ax > 1e-7 && by - ay > 1e-7) scale_x = bx - ax, scale_y = by - ay;
  }
  // The distortion centre in pixels: Gazebo's 0.5 is the image's middle, here the principal point.
  const double ccx = out.cx + (d.center_x - 0.5) * W, ccy = out.cy + (d.center_y - 0.5) * H;
  const double kx = T / W / f, ky = T / H / f;  // pixels -> Gazebo's normalised units
  for (int r = 0; r < out.height; ++r) {
    for (int c = 0; c < out.width; ++c) {
      const double mx = out.cx + (c - out.cx) * scale_x, my = out.cy + (r - out.cy) * scale_y;
      double x = 0, y = 0;
      const bool found = undistort_point(d, (mx - ccx) * kx, (my - ccy) * ky, x, y);
      const double px = ccx + x / kx, py = ccy + y / ky;
      float u = 0.0f, v = 0.0f;
      if (found && px >= -0.5 && px <= W - 0.5 && py >= -0.5 && py <= H - 0.5) {
        u = std::clamp(static_cast<float>(src.fx * (px - out.cx) / out.fx + src.cx), 0.0f, static_cast<float>(w - 1));
        v = std::clamp(static_cast<float>(src.fy * (py - out.cy) / out.fy + src.cy), 0.0f, static_cast<float>(h - 1));
      }
      const int u0 = static_cast<int>(u), v0 = static_cast<int>(v);
      Tap& t = map[static_cast<std::size_t>(r) * out.width + c];
      t.at = static_cast<std::uint32_t>((static_cast<std::size_t>(v0) * w + u0) * 3);
      t.du = u0 + 1 < w ? 3 : 0;
      t.dv = static_cast<std::uint16_t>(v0 + 1 < h ? w * 3 : 0);
      t.a = u - static_cast<float>(u0);
      t.b = v - static_cast<float>(v0);
    }
  }
  return map;
}

bool same_pose(const description::Pose& p, const description::Pose& q) {
  constexpr double kTol = 1e-12;
  return std::abs(p.position.x - q.position.x) < kTol && std::abs(p.position.y - q.position.y) < kTol &&
         std::abs(p.position.z - q.position.z) < kTol && std::abs(p.orientation.w - q.orientation.w) < kTol &&
         std::abs(p.orientation.x - q.orientation.x) < kTol && std::abs(p.orientation.y - q.orientation.y) < kTol &&
         std::abs(p.orientation.z - q.orientation.z) < kTol;
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

int CameraSensor::share_renders_with(const CameraSensor& other) {
  // A depth camera's depth and points come from the render itself, not resampled: never shared.
  if (&other == this || camera_.depth || other.link_ != link_ || other.spec().update_rate != spec().update_rate) return 0;
  int shared = 0;
  for (std::size_t i = 0; i < lenses_.size(); ++i) {
    Lens& mine = lenses_[i];
    if (!camera_.lenses[i].distortion.active() || mine.render.cx != mine.view.cx || mine.render.cy != mine.view.cy)
      continue;  // resampled anyway, and not sharing yet
    for (std::size_t j = 0; j < other.lenses_.size(); ++j) {
      const Lens& theirs = other.lenses_[j];
      const physics::CameraView &a = mine.view, &b = theirs.view;
      if (other.camera_.lenses[j].distortion.active() || a.width != b.width || a.height != b.height || a.fx != b.fx ||
          a.fy != b.fy || a.near != b.near || a.far != b.far || !same_pose(mine.X_LC, theirs.X_LC))
        continue;
      mine.render = b;
      mine.render_X_LC = theirs.X_LC;
      mine.render_depth = theirs.render_depth;
      ++shared;
      break;
    }
  }
  return shared;
}

std::unique_ptr<SensorState> CameraSensor::make_state(Rng rng) const {
  auto state = std::make_unique<CameraState>();
  state->rng = std::move(rng);
  state->undistort.resize(lenses_.size());
  const description::NoiseSpec& n = camera_.lenses.front().noise;
  if (n.stddev > 0.0 || n.mean != 0.0) {
    state->noise.resize(kNoiseTable);
    for (std::int16_t& x : state->noise) {
      const double levels = std::clamp(255.0 * (n.mean + n.stddev * standard_normal(state->rng)), -255.0, 255.0);
      x = static_cast<std::int16_t>(std::lround(levels));
    }
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
  if (state.render == nullptr) {
    reading.error = "no renderer attached to the camera";
    return;
  }
  const description::Pose X_WL = physics.link_pose(link_);
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < lenses_.size(); ++i) {
    const Lens& lens = lenses_[i];
    physics::CameraView view = lens.view;
    view.X_WC = physics::compose(X_WL, lens.X_LC);
    physics::CameraView render = lens.render;
    render.X_WC = physics::compose(X_WL, lens.render_X_LC);
    const physics::Frame* rendered = state.render->frame(physics, render, lens.render_depth || camera_.depth);
    if (rendered == nullptr) {
      reading.error = state.render->error();
      return;
    }
    const physics::Frame& frame = *rendered;
    CameraStages& stages = state.render->stages();
    physics::StageTimer timer;
    ++stages.images;
    CameraImage& im = reading.images[i];
    const std::size_t n = static_cast<std::size_t>(view.width) * view.height;
    im.rgb.resize(n * 3);
    std::vector<Tap>& undistort = state.undistort[i];
    const description::DistortionSpec& distortion = camera_.lenses[i].distortion;
    if (undistort.empty() && distortion.active())
      undistort = undistort_map(distortion, camera_.lenses[i].horizontal_fov, lens.view, lens.render);
    // The noise's start in its table: one draw per frame, so frames differ and stay reproducible.
    const std::size_t noise_at = state.noise.empty() ? 0 : static_cast<std::size_t>(uniform01(state.rng) * kNoiseTable);
    if (undistort.empty() && state.noise.empty()) {
      std::copy(frame.rgb.begin(), frame.rgb.begin() + static_cast<std::ptrdiff_t>(n * 3), im.rgb.begin());
      stages.resample += timer.lap();
    } else if (undistort.empty()) {
      // The render copied and noised in one pass (the noise stage's time).
      add_noise(frame.rgb.data(), im.rgb.data(), n * 3, state.noise, noise_at);
    } else {
      resample(undistort, frame.rgb.data(), frame.rgb.size(), im.rgb.data());
      stages.resample += timer.lap();
      if (!state.noise.empty()) add_noise(im.rgb.data(), im.rgb.data(), n * 3, state.noise, noise_at);
    }
    stages.noise += timer.lap();
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
    stages.points += timer.lap();
  }
  reading.error.clear();
}

}  // namespace mechsim::sensors
