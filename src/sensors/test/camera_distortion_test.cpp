// Lens distortion as gazebo_plugins' distortion test judges it, made exact: a camera with
// <distortion> and an undistorted twin at the same place look at a checkerboard. Every edge of the
// board that the distorted image shows (sub-pixel crossings of the mid-level along rows and
// columns), taken back through the CameraInfo the camera publishes (K and D, OpenCV's plumb_bob
// inverted as cv::undistortPoints does), lies on the straight line the board's edge makes in the
// undistorted image (known from the board's geometry, checked on the twin's image); and each of
// D's five coefficients, changed by +-0.01, puts the edges farther off. Undistorting the whole
// image with K and D (cv::undistort) gives back the twin's picture. Barrel (k1 < 0, borderCrop
// false as the plugin's test world has it) and pincushion with tangential terms.
// MECHSIM_TEST_IMAGES=DIR writes the pictures as PNG.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "physics/image_png.hpp"
#include "sensor_test_util.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sensors {
namespace {

constexpr int kSide = 400;         // pixels: a square image, as the plugin's test uses
constexpr double kFov = 1.2;       // rad
constexpr int kTiles = 16;         // per side, 0.2 m each
constexpr double kTile = 0.2;      // m
constexpr double kBoardX = 2.1;    // the board's joint, from the base (its face 5 mm nearer)
constexpr double kCameraX = 0.1;   // laser_link, from the base

// A 3.2 m checkerboard of 0.2 m squares standing 2 m ahead of the camera on laser_link (0.3 m
// above the base, like the board's centre), facing it: a massless link of box visuals.
std::string checkerboard() {
  std::string visuals;
  for (int i = 0; i < kTiles; ++i) {
    for (int j = 0; j < kTiles; ++j) {
      const bool white = (i + j) % 2 == 0;
      const double y = (i - (kTiles - 1) / 2.0) * kTile, z = (j - (kTiles - 1) / 2.0) * kTile;
      visuals += "<visual><origin xyz=\"0 " + std::to_string(y) + " " + std::to_string(z) +
                 "\"/><geometry><box size=\"0.01 0.2 0.2\"/></geometry><material name=\"" + (white ? "w" : "k") +
                 "\"><color rgba=\"" + (white ? "1 1 1 1" : "0 0 0 1") + "\"/></material></visual>";
    }
  }
  return "<joint name=\"board_joint\" type=\"fixed\"><parent link=\"base\"/><child link=\"board\"/><origin xyz=\"" +
         std::to_string(kBoardX) + " 0 0.3\"/></joint>\n<link name=\"board\">" + visuals + "</link>\n";
}

std::string camera(const std::string& name, const std::string& distortion, const std::string& d_params) {
  return R"(<gazebo reference="laser_link"><sensor type="camera" name=")" + name + R"("><update_rate>10</update_rate>
  <camera><horizontal_fov>)" + std::to_string(kFov) + "</horizontal_fov><image><width>" + std::to_string(kSide) +
         "</width><height>" + std::to_string(kSide) + R"(</height></image><clip><near>0.02</near><far>30</far></clip>)" +
         distortion + R"(</camera><plugin name="c" filename="libgazebo_ros_camera.so"><cameraName>)" + name +
         "</cameraName>" + d_params + "<borderCrop>false</borderCrop></plugin></sensor></gazebo>\n";
}

struct Pictures {
  CameraImage distorted, plain;
};

Pictures take(const std::array<double, 5>& D) {  // k1 k2 t1 t2 k3, as CameraInfo orders them
  const auto num = [](double v) { return std::to_string(v); };
  const std::string sdf = "<distortion><k1>" + num(D[0]) + "</k1><k2>" + num(D[1]) + "</k2><k3>" + num(D[4]) + "</k3><p1>" +
                          num(D[2]) + "</p1><p2>" + num(D[3]) + "</p2><center>0.5 0.5</center></distortion>";
  const std::string plugin = "<distortionK1>" + num(D[0]) + "</distortionK1><distortionK2>" + num(D[1]) +
                             "</distortionK2><distortionK3>" + num(D[4]) + "</distortionK3><distortionT1>" + num(D[2]) +
                             "</distortionT1><distortionT2>" + num(D[3]) + "</distortionT2>";
  const description::RobotModel robot =
      test::parse(test::robot_urdf(checkerboard() + camera("camera_distorted", sdf, plugin) + camera("camera_plain", "", "")));
  physics::BuildOptions o;
  o.world.ground_plane = false;
  o.world.gravity = 0.0;
  auto model = test::build(robot, 0.0, o);
  physics::Physics physics(model);
  SensorSet set(robot.sensors, model, 1);
  set.set_enabled(0, true);
  set.set_enabled(1, true);
  set.sample_all(physics, 0.0);
  Pictures p;
  p.distorted = std::get<CameraReading>(set.reading(0).value).images.at(0);
  p.plain = std::get<CameraReading>(set.reading(1).value).images.at(0);
  return p;
}

double level(const CameraImage& im, int u, int v) {
  const std::uint8_t* p = &im.rgb[(static_cast<std::size_t>(v) * im.info.width + u) * 3];
  return (p[0] + p[1] + p[2]) / 3.0;
}

// An edge of the image: where the level crosses the middle between the board's dark and light,
// to a sub-pixel position along a row (vertical edge) or a column (horizontal edge).
struct Crossing {
  double u = 0.0, v = 0.0;
  bool vertical = true;  // the board edge it lies on runs vertically in the image
};

std::vector<Crossing> crossings(const CameraImage& im, int border) {
  double lo = 255, hi = 0;
  for (int v = border; v < im.info.height - border; ++v)
    for (int u = border; u < im.info.width - border; ++u) lo = std::min(lo, level(im, u, v)), hi = std::max(hi, level(im, u, v));
  const double mid = 0.5 * (lo + hi);
  std::vector<Crossing> out;
  for (int v = border; v < im.info.height - border; ++v) {
    for (int u = border; u + 1 < im.info.width - border; ++u) {
      const double a = level(im, u, v) - mid, b = level(im, u + 1, v) - mid;
      if ((a < 0) != (b < 0)) out.push_back({u + a / (a - b), static_cast<double>(v), true});
      const double c = level(im, v, u) - mid, d = level(im, v, u + 1) - mid;  // along column v
      if ((c < 0) != (d < 0)) out.push_back({static_cast<double>(v), u + c / (c - d), false});
    }
  }
  return out;
}

// cv::undistortPoints: the ideal pixel whose plumb_bob distortion through K and D is (u, v).
std::array<double, 2> undistort_point(const CameraInfo& info, const std::array<double, 5>& D, double u, double v) {
  const double fx = info.K[0], cx = info.K[2], fy = info.K[4], cy = info.K[5];
  const double xd = (u - cx) / fx, yd = (v - cy) / fy;
  double x = xd, y = yd;
  for (int i = 0; i < 50; ++i) {
    const double r2 = x * x + y * y, radial = 1 + r2 * (D[0] + r2 * (D[1] + r2 * D[4]));
    x = (xd - 2 * D[2] * x * y - D[3] * (r2 + 2 * x * x)) / radial;
    y = (yd - D[2] * (r2 + 2 * y * y) - 2 * D[3] * x * y) / radial;
  }
  return {fx * x + cx, fy * y + cy};
}

// Where the board's edges are in the undistorted image: one coordinate per line (the camera looks
// along +x, image right is -y, image down is -z).
std::vector<double> edge_lines(const CameraInfo& info, bool vertical) {
  const double depth = kBoardX - 0.005 - kCameraX;
  const double f = vertical ? info.K[0] : info.K[4], c = vertical ? info.K[2] : info.K[5];
  std::vector<double> lines;
  for (int k = 0; k <= kTiles; ++k) lines.push_back(c - f * (k - kTiles / 2.0) * kTile / depth);
  return lines;
}

double nearest(const std::vector<double>& lines, double x) {
  double best = 1e9;
  for (const double l : lines) best = std::min(best, std::abs(x - l));
  return best;
}

struct Lines {
  std::vector<double> vertical, horizontal;  // u of the vertical edges, v of the horizontal ones
};

// The board's edge lines as the undistorted twin shows them: each geometric line moved to the
// mean of the twin's crossings near it. The render has no multisampling, so an edge falls on a
// pixel boundary: each line is off its geometric place by up to half a pixel, the same in the
// twin and (resampled) in the distorted image, which renders the same picture.
Lines measured_lines(const CameraImage& plain) {
  Lines out{edge_lines(plain.info, true), edge_lines(plain.info, false)};
  for (const bool vertical : {true, false}) {
    std::vector<double>& lines = vertical ? out.vertical : out.horizontal;
    std::vector<double> sum(lines.size(), 0.0), count(lines.size(), 0.0);
    for (const Crossing& c : crossings(plain, kSide / 10)) {
      if (c.vertical != vertical) continue;
      const double x = vertical ? c.u : c.v;
      for (std::size_t k = 0; k < lines.size(); ++k)
        if (std::abs(x - lines[k]) < 1.0) sum[k] += x, count[k] += 1;
    }
    for (std::size_t k = 0; k < lines.size(); ++k)
      if (count[k] > 0) lines[k] = sum[k] / count[k];
  }
  return out;
}

// RMS distance (px) of the image's edge crossings, undistorted through K and D, from `lines`;
// crossings within 2 px of a line across them (corners) are left out.
double edge_rms(const CameraImage& im, const std::array<double, 5>& D, const Lines& lines, std::size_t* used = nullptr) {
  double sum = 0;
  std::size_t n = 0;
  for (const Crossing& c : crossings(im, kSide / 10)) {
    const auto [u, v] = undistort_point(im.info, D, c.u, c.v);
    const double along = c.vertical ? nearest(lines.vertical, u) : nearest(lines.horizontal, v);
    const double across = c.vertical ? nearest(lines.horizontal, v) : nearest(lines.vertical, u);
    if (across < 2.0) continue;
    sum += along * along;
    ++n;
  }
  if (used != nullptr) *used = n;
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 1e9;
}

double channel(const CameraImage& im, double u, double v, int c) {
  const int w = im.info.width, h = im.info.height;
  u = std::clamp(u, 0.0, w - 1.0);
  v = std::clamp(v, 0.0, h - 1.0);
  const int u0 = std::min(static_cast<int>(u), w - 2), v0 = std::min(static_cast<int>(v), h - 2);
  const double a = u - u0, b = v - v0;
  const auto at = [&](int x, int y) { return static_cast<double>(im.rgb[(static_cast<std::size_t>(y) * w + x) * 3 + c]); };
  return (1 - b) * ((1 - a) * at(u0, v0) + a * at(u0 + 1, v0)) + b * ((1 - a) * at(u0, v0 + 1) + a * at(u0 + 1, v0 + 1));
}

// cv::undistort of `distorted` through K and D: each output pixel samples the input where
// plumb_bob moves its ideal position.
CameraImage undistort(const CameraImage& distorted, const std::array<double, 5>& D) {
  CameraImage out = distorted;
  const auto& K = distorted.info.K;
  const double fx = K[0], cx = K[2], fy = K[4], cy = K[5];
  for (int v = 0; v < out.info.height; ++v) {
    for (int u = 0; u < out.info.width; ++u) {
      const double x = (u - cx) / fx, y = (v - cy) / fy, r2 = x * x + y * y;
      const double radial = 1 + r2 * (D[0] + r2 * (D[1] + r2 * D[4]));
      const double xd = x * radial + 2 * D[2] * x * y + D[3] * (r2 + 2 * x * x);
      const double yd = y * radial + D[2] * (r2 + 2 * y * y) + 2 * D[3] * x * y;
      for (int c = 0; c < 3; ++c)
        out.rgb[(static_cast<std::size_t>(v) * out.info.width + u) * 3 + c] =
            static_cast<std::uint8_t>(std::lround(channel(distorted, fx * xd + cx, fy * yd + cy, c)));
    }
  }
  return out;
}

void save(const std::string& name, const CameraImage& im) {
  const char* dir = std::getenv("MECHSIM_TEST_IMAGES");
  if (dir == nullptr) return;
  physics::save_rgb_png(std::filesystem::path(dir) / (name + ".png"), im.info.width, im.info.height, im.rgb);
}

void expect_edges_straight_through_camera_info(const std::string& name, const std::array<double, 5>& truth) {
  const Pictures p = take(truth);
  ASSERT_FALSE(p.distorted.rgb.empty());
  const CameraInfo& info = p.distorted.info;
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(info.D[i], truth[i], 1e-9) << "D[" << i << "]";
  save(name + "_distorted", p.distorted);
  save(name + "_plain", p.plain);
  save(name + "_undistorted", undistort(p.distorted, info.D));

  // The twin's image shows the board's edges where its geometry puts them, to the pixel grid.
  const Lines geometric{edge_lines(info, true), edge_lines(info, false)}, lines = measured_lines(p.plain);
  std::size_t plain_used = 0, used = 0;
  const double plain = edge_rms(p.plain, {}, geometric, &plain_used);
  EXPECT_LT(plain, 0.35) << plain_used << " crossings";
  for (std::size_t k = 0; k < lines.vertical.size(); ++k) {
    EXPECT_NEAR(lines.vertical[k], geometric.vertical[k], 0.5);
    EXPECT_NEAR(lines.horizontal[k], geometric.horizontal[k], 0.5);
  }
  const double own = edge_rms(p.distorted, info.D, lines, &used);
  const double none = edge_rms(p.distorted, {}, lines);
  std::printf("%s: edges of the undistorted twin %.3f px RMS off the board's geometric lines (%zu crossings); of the "
              "distorted image through CameraInfo's D %.3f px off the twin's lines (%zu), through no D %.3f px\n",
              name.c_str(), plain, plain_used, own, used, none);
  EXPECT_GT(used, 2000u);
  EXPECT_LT(own, 0.15) << "undistorted through CameraInfo, the edges are straight and in place";
  EXPECT_GT(none, 10 * own) << "the distortion is visible at all";
  for (std::size_t i = 0; i < 5; ++i) {
    for (const double change : {0.01, -0.01}) {
      std::array<double, 5> other = info.D;
      other[i] += change;
      const double off = edge_rms(p.distorted, other, lines);
      EXPECT_GT(off, own) << "D[" << i << "] changed by " << change << " fits the image as well";
      std::printf("  D[%zu] %+.2f: %.3f px\n", i, change, off);
    }
  }
}

TEST(CameraDistortion, BarrelEdgesAreStraightThroughCameraInfo) {
  expect_edges_straight_through_camera_info("barrel", {-0.15, -0.02, 0.0, 0.0, -0.01});
}

TEST(CameraDistortion, PincushionWithTangentialEdgesAreStraightThroughCameraInfo) {
  expect_edges_straight_through_camera_info("pincushion", {0.1, 0.02, 0.002, -0.003, 0.0});
}

}  // namespace
}  // namespace mechsim::sensors
