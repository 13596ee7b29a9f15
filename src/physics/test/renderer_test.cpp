// The offscreen renderer against the pinhole model: a box's outline where its corners project,
// depth of a fronto-parallel wall in metres, depth pixels back-projected onto the box's faces,
// stereo disparity f b / Z, and a machine whose EGL is broken.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "physics/renderer.hpp"
#include "physics/transform.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using description::Pose;
using description::Vec3;

constexpr double kPi = 3.14159265358979323846;

// The optical frame of a camera at `p` looking along world +x (z_C = x_W, x_C = -y_W, y_C = -z_W):
// the rotation of URDF's optical joint, rpy (-pi/2, 0, -pi/2).
Pose looking_along_x(Vec3 p) { return {p, quat_from_rpy(-kPi / 2, 0.0, -kPi / 2)}; }

CameraView view(Vec3 at, int w, int h, double hfov) {
  CameraView v;
  v.X_WC = looking_along_x(at);
  v.width = w;
  v.height = h;
  v.fx = v.fy = w / (2.0 * std::tan(hfov / 2));
  v.cx = (w - 1) / 2.0 + 7.0;  // off-centre principal point: the image must follow it
  v.cy = (h - 1) / 2.0 - 5.0;
  v.near = 0.05;
  v.far = 50.0;
  return v;
}

// The world: boxes only (no ground), the test robot parked far behind the camera.
std::shared_ptr<const PhysicsModel> world(const std::vector<WorldBox>& boxes) {
  BuildOptions o;
  o.world.ground_plane = false;
  o.world.gravity = 0.0;
  o.world.boxes = boxes;
  o.spawn.x = -100.0;
  return test::build(test::box_urdf(), o);
}

WorldBox box(const std::string& name, Vec3 centre, Vec3 size, double yaw = 0.0, double roll = 0.0) {
  WorldBox b;
  b.name = name;
  b.pose = {centre, quat_from_rpy(roll, 0.0, yaw)};
  b.size = size;
  return b;
}

// u, v of a world point through the view (the pinhole model CameraInfo's P describes).
std::array<double, 3> project(const CameraView& v, Vec3 p_W) {
  const Vec3 p = rotate(quat_conjugate(v.X_WC.orientation),
                        {p_W.x - v.X_WC.position.x, p_W.y - v.X_WC.position.y, p_W.z - v.X_WC.position.z});
  return {v.fx * p.x / p.z + v.cx, v.fy * p.y / p.z + v.cy, p.z};
}

// Signed distance (pixels) of (u, v) from a convex polygon's boundary: > 0 inside.
double inside_distance(const std::vector<std::array<double, 2>>& hull, double u, double v) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const auto& a = hull[i];
    const auto& b = hull[(i + 1) % hull.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    d = std::min(d, (ex * (v - a[1]) - ey * (u - a[0])) / std::hypot(ex, ey));
  }
  return d;
}

std::vector<std::array<double, 2>> convex_hull(std::vector<std::array<double, 2>> p) {
  std::sort(p.begin(), p.end());
  std::vector<std::array<double, 2>> h(2 * p.size());
  std::size_t k = 0;
  auto cross = [](const auto& o, const auto& a, const auto& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

class RendererTest : public ::testing::Test {
 protected:
  Frame render(const std::shared_ptr<const PhysicsModel>& model, const CameraView& v) {
    Frame f;
    render(model, v, f, true);
    return f;
  }
  // The spawn state of `model` through `v` into `f` (depth too when `depth`), in a renderer of its own.
  RenderStats render(const std::shared_ptr<const PhysicsModel>& model, const CameraView& v, Frame& f, bool depth) {
    RenderSettings s;
    s.max_width = v.width;
    s.max_height = v.height;
    Renderer r(model, s);
    Physics p(model);
    r.update_scene(p);
    return r.render(v, f, true, depth);
  }
};

// The silhouette of a box turned 0.5 rad in yaw and 0.3 in roll is the hull of its projected
// corners: every pixel whose centre is more than 1 px inside the hull is drawn, every one more
// than 1 px outside is not, and the silhouette's extreme columns and rows are within 1 px of the
// extreme projected corners.
TEST_F(RendererTest, BoxCornersProjectThroughTheIntrinsics) {
  const Vec3 c{3.0, 0.25, -0.15}, size{0.6, 0.4, 0.5};
  const WorldBox b = box("target", c, size, 0.5, 0.3);
  auto model = world({b});
  const CameraView v = view({0, 0, 0}, 640, 480, 1.2);
  const Frame f = render(model, v);
  std::vector<std::array<double, 2>> corners;
  for (int i = 0; i < 8; ++i) {
    const Vec3 local{(i & 1 ? 0.5 : -0.5) * size.x, (i & 2 ? 0.5 : -0.5) * size.y, (i & 4 ? 0.5 : -0.5) * size.z};
    const Vec3 r = rotate(b.pose.orientation, local);
    const auto uv = project(v, {c.x + r.x, c.y + r.y, c.z + r.z});
    corners.push_back({uv[0], uv[1]});
  }
  const auto hull = convex_hull(corners);
  int wrong = 0, drawn = 0;
  double umin = 1e9, umax = -1e9, vmin = 1e9, vmax = -1e9;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const bool hit = std::isfinite(f.depth[static_cast<std::size_t>(y * f.width + x)]);
      const double d = inside_distance(hull, x, y);
      if ((d > 1.0 && !hit) || (d < -1.0 && hit)) ++wrong;
      if (hit) {
        ++drawn;
        umin = std::min(umin, double(x));
        umax = std::max(umax, double(x));
        vmin = std::min(vmin, double(y));
        vmax = std::max(vmax, double(y));
      }
    }
  double cu_min = 1e9, cu_max = -1e9, cv_min = 1e9, cv_max = -1e9;
  for (const auto& p : corners) {
    cu_min = std::min(cu_min, p[0]);
    cu_max = std::max(cu_max, p[0]);
    cv_min = std::min(cv_min, p[1]);
    cv_max = std::max(cv_max, p[1]);
  }
  EXPECT_GT(drawn, 5000);
  EXPECT_EQ(wrong, 0);
  EXPECT_NEAR(umin, cu_min, 1.0);
  EXPECT_NEAR(umax, cu_max, 1.0);
  EXPECT_NEAR(vmin, cv_min, 1.0);
  EXPECT_NEAR(vmax, cv_max, 1.0);
  RecordProperty("extreme_error_px", std::to_string(std::max({std::abs(umin - cu_min), std::abs(umax - cu_max),
                                                              std::abs(vmin - cv_min), std::abs(vmax - cv_max)})));
  // Colour where drawn, background elsewhere.
  const std::size_t centre = static_cast<std::size_t>((std::lround(corners[0][1] + corners[7][1]) / 2) * f.width +
                                                      std::lround(corners[0][0] + corners[7][0]) / 2);
  EXPECT_TRUE(std::isfinite(f.depth[centre]));
  ASSERT_EQ(f.rgb.size(), static_cast<std::size_t>(640 * 480 * 3));
}

// A wall facing the camera 0.5, 4 and 20 m away: every pixel's depth is the distance within 1 %
// (measured: far less).
TEST_F(RendererTest, FrontoParallelWallDepthInMetres) {
  auto model = world({box("wall", {20.5, 0, 0}, {1.0, 200.0, 200.0})});
  RenderSettings s;
  s.max_width = 320;
  s.max_height = 240;
  Renderer r(model, s);
  Physics p(model);
  r.update_scene(p);
  for (double distance : {0.5, 4.0, 20.0}) {
    const CameraView v = view({20.0 - distance, 0, 0}, 320, 240, 1.5);
    Frame f;
    r.render(v, f);
    double worst = 0.0;
    for (float z : f.depth) worst = std::max(worst, std::abs(z - distance) / distance);
    EXPECT_LT(worst, 0.01) << "wall at " << distance << " m";
    RecordProperty("wall_" + std::to_string(int(distance * 10)) + "dm_worst_rel", std::to_string(worst));
  }
}

// Depth pixels back-projected through the intrinsics land on the turned box's surface: within
// 1 cm of one of its faces (and inside the box's outline).
TEST_F(RendererTest, BackProjectedDepthLiesOnTheSurface) {
  const Vec3 c{2.5, -0.2, 0.1}, size{0.5, 0.7, 0.4};
  const WorldBox b = box("target", c, size, 0.7, 0.2);
  auto model = world({b});
  const CameraView v = view({0, 0, 0}, 400, 300, 1.2);
  const Frame f = render(model, v);
  double worst = 0.0;
  int points = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const float z = f.depth[static_cast<std::size_t>(y * f.width + x)];
      if (!std::isfinite(z)) continue;
      const Vec3 p_C{(x - v.cx) / v.fx * z, (y - v.cy) / v.fy * z, z};
      const Vec3 r = rotate(v.X_WC.orientation, p_C);
      const Vec3 d = rotate(quat_conjugate(b.pose.orientation), {r.x - c.x, r.y - c.y, r.z - c.z});
      // Distance to the box surface for a point near it: the largest excess over the half sizes.
      const double e = std::max({std::abs(d.x) - size.x / 2, std::abs(d.y) - size.y / 2, std::abs(d.z) - size.z / 2});
      worst = std::max(worst, std::abs(e));
      ++points;
    }
  EXPECT_GT(points, 3000);
  EXPECT_LT(worst, 0.01);
  RecordProperty("surface_worst_m", std::to_string(worst));
}

// Two views 0.12 m apart along x_C see a wall's vertical edge shifted by f b / Z pixels.
TEST_F(RendererTest, StereoDisparityMatchesTheBaseline) {
  const double Z = 3.0, baseline = 0.12;
  // A wall from y = -10 to y = 0.4 (world), its left edge at y = 0.4, facing the cameras.
  auto model = world({box("wall", {Z + 0.5, -4.8, 0}, {1.0, 10.4, 4.0})});
  CameraView left = view({0, baseline / 2, 0}, 640, 480, 1.2);
  CameraView right = view({0, -baseline / 2, 0}, 640, 480, 1.2);
  auto edge = [&](const CameraView& v) {
    const Frame f = render(model, v);
    // Sub-pixel edge: the first covered column on the middle row, refined by the coverage of
    // the rows around it (anti-aliasing is off, so count covered pixels over 100 rows).
    long covered = 0;
    for (int y = f.height / 2 - 50; y < f.height / 2 + 50; ++y)
      for (int x = 0; x < f.width; ++x) covered += std::isfinite(f.depth[static_cast<std::size_t>(y * f.width + x)]) ? 0 : 1;
    return static_cast<double>(covered) / 100.0 - 0.5;  // u of the edge: columns left of it are empty
  };
  const double ul = edge(left), ur = edge(right);
  const double expected = left.fx * baseline / Z;
  EXPECT_NEAR(ul - ur, expected, 0.5) << "left edge " << ul << ", right edge " << ur;
  RecordProperty("disparity_px", std::to_string(ul - ur));
  RecordProperty("expected_px", std::to_string(expected));
}

// Geoms whose bounding spheres lie outside the view are not drawn (one behind the camera, one far
// to its left), one straddling the image's edge is, and the image is the one of a world without
// the two left out, pixel for pixel.
TEST_F(RendererTest, GeomsOutsideTheViewAreLeftOutAndTheImageIsTheSame) {
  const CameraView v = view({0, 0, 0}, 160, 120, 1.0);
  const std::vector<WorldBox> seen = {box("front", {3, 0, 0}, {0.5, 0.5, 0.5}),
                                      box("edge", {3, -1.5, 0}, {0.6, 0.6, 0.6})};
  std::vector<WorldBox> all = seen;
  all.push_back(box("behind", {-3, 0, 0}, {0.5, 0.5, 0.5}));
  all.push_back(box("left", {3, 6, 0}, {0.5, 0.5, 0.5}));
  Frame with_all, with_seen;
  const RenderStats a = render(world(all), v, with_all, true);
  const RenderStats b = render(world(seen), v, with_seen, true);
  EXPECT_EQ(a.culled - b.culled, 2);
  EXPECT_EQ(a.geoms, b.geoms);
  EXPECT_TRUE(with_all.rgb == with_seen.rgb);
  EXPECT_TRUE(with_all.depth == with_seen.depth);
  // The edge box is drawn: its near face (x = 2.7) fills the rightmost column (world -y) somewhere.
  const std::size_t w = static_cast<std::size_t>(v.width);
  int edge_pixels = 0;
  for (std::size_t row = 0; row < static_cast<std::size_t>(v.height); ++row)
    edge_pixels += std::abs(with_all.depth[row * w + w - 1] - 2.7f) < 0.05f;
  EXPECT_GT(edge_pixels, 10);
}

TEST_F(RendererTest, ImpossibleViewsAreErrors) {
  auto model = world({box("b", {3, 0, 0}, {1, 1, 1})});
  CameraView v = view({0, 0, 0}, 64, 48, 1.0);
  EXPECT_EQ(check_view(v), "");
  v.width = 0;
  EXPECT_NE(check_view(v).find("width and height must be > 0"), std::string::npos);
  v.width = 64;
  v.near = 2.0;
  v.far = 1.0;
  EXPECT_NE(check_view(v).find("near < far"), std::string::npos);
  v.far = 10.0;
  RenderSettings s;
  s.max_width = 32;
  s.max_height = 32;
  Renderer r(model, s);
  Physics p(model);
  r.update_scene(p);
  Frame f;
  EXPECT_THROW(r.render(v, f), std::invalid_argument);  // larger than the buffer
}

// EGL pointed at a vendor library that does not exist: the renderer says so and throws
// RenderUnavailable (the caller runs on without cameras). In a fresh process, because EGL reads
// its vendors once.
TEST(RendererEgl, BrokenEglIsReportedNotFatal) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/mechsim_no_such_vendor.json", 1);
        auto model = world({});
        try {
          Renderer r(model);
        } catch (const RenderUnavailable& e) {
          std::fprintf(stderr, "unavailable: %s\n", e.what());
          std::exit(3);
        }
        std::exit(0);
      },
      ::testing::ExitedWithCode(3), "unavailable: .*EGL");
}

}  // namespace
}  // namespace mechsim::physics

namespace mechsim::physics {
namespace {

// A rolling 10 m x 10 m height field (5 cm cells) seen from 1.5 m up, looking down 30 degrees:
// drawn from render tiles at their levels of detail, the depth image keeps every terrain pixel of
// the full height field (no cracks between levels), is within 0.5 % of it where the terrain is
// nearer than 4 m, and draws fewer cells.
TEST(RendererTerrain, TilesFollowTheHeightField) {
  Heightmap h;
  h.rows = h.cols = 201;
  h.size_x = h.size_y = 10.0;
  for (std::size_t r = 0; r < h.rows; ++r)
    for (std::size_t c = 0; c < h.cols; ++c)
      h.heights.push_back(static_cast<float>(0.2 * std::sin(0.9 * static_cast<double>(c) * h.cell_x()) *
                                             std::cos(0.7 * static_cast<double>(r) * h.cell_y())));
  BuildOptions o;
  o.world.kind = WorldSpec::Kind::Heightmap;
  o.world.terrain = h;
  o.world.gravity = 0.0;
  o.spawn.x = -100.0;
  auto plain = test::build(test::box_urdf(), o);
  o.render_terrain = true;
  auto tiled = test::build(test::box_urdf(), o);
  CameraView v;
  v.X_WC = {{-4.5, -0.3, 1.5}, quat_multiply(quat_from_rpy(0.0, 0.5, 0.1), quat_from_rpy(-kPi / 2, 0.0, -kPi / 2))};
  v.width = 320;
  v.height = 240;
  v.fx = v.fy = 200.0;
  v.cx = 159.5;
  v.cy = 119.5;
  v.near = 0.05;
  v.far = 60.0;
  RenderSettings s;
  s.max_width = 320;
  s.max_height = 240;
  Frame full, tiles;
  RenderStats st_full, st_tiles;
  {
    Renderer r(plain, s);
    Physics p(plain);
    r.update_scene(p);
    st_full = r.render(v, full);
  }
  {
    Renderer r(tiled, s);
    Physics p(tiled);
    r.update_scene(p);
    st_tiles = r.render(v, tiles);
  }
  int terrain = 0, missing = 0, near = 0;
  double worst_near = 0.0;
  for (std::size_t i = 0; i < full.depth.size(); ++i) {
    if (!std::isfinite(full.depth[i])) continue;
    ++terrain;
    if (!std::isfinite(tiles.depth[i])) ++missing;
    if (full.depth[i] < 4.0f && std::isfinite(tiles.depth[i])) {
      ++near;
      worst_near = std::max(worst_near, double(std::abs(tiles.depth[i] - full.depth[i]) / full.depth[i]));
    }
  }
  EXPECT_GT(terrain, 30000);
  EXPECT_GT(near, 5000);
  EXPECT_LE(missing, terrain / 2000);  // silhouettes of coarse far tiles may differ by a pixel; cracks would be many
  EXPECT_LT(worst_near, 0.005);
  EXPECT_GT(st_tiles.terrain_tiles, 0);
  EXPECT_LT(st_tiles.terrain_cells, 200L * 200L);
  RecordProperty("tile_cells", std::to_string(st_tiles.terrain_cells));
  RecordProperty("worst_near_rel", std::to_string(worst_near));
}

}  // namespace
}  // namespace mechsim::physics
