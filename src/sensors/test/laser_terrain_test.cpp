// A laser over the Mars Yard (mars_yard_2024, 811 x 541 samples at 5 cm): every ray's range
// within 1 cm of the analytic value, noise off. The analytic reference is the height field's
// surface as MuJoCo defines it — each grid cell split into two flat triangles along the diagonal
// from sample (c, r) to (c + 1, r + 1) (piecewise-linear, not bilinear) — evaluated here from the
// heightmap's own heights, independently of physics/ray_cast.cpp: march along the ray in 2 mm
// steps to the first point at or below the surface, then bisect. The laser hangs from a mast
// fixed to the world, pitched down so that its rays sweep the ground, at several places and
// headings, including scans whose middle ray lies exactly on a grid row and along a cell
// diagonal (where MuJoCo 2.2.2's own mj_ray can miss the surface).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "description/urdf/urdf_parser.hpp"
#include "physics/heightmap_sample.hpp"
#include "physics/mars_yard.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sensors {
namespace {

// The triangulated surface's height at (x, y), from the grid's absolute heights.
double surface(const physics::Heightmap& h, double x, double y) {
  const double dx = h.cell_x(), dy = h.cell_y();
  const double fx = (x + h.size_x / 2) / dx, fy = (y + h.size_y / 2) / dy;
  const std::size_t c = std::min<std::size_t>(static_cast<std::size_t>(std::max(0.0, std::floor(fx))), h.cols - 2);
  const std::size_t r = std::min<std::size_t>(static_cast<std::size_t>(std::max(0.0, std::floor(fy))), h.rows - 2);
  const double u = fx - static_cast<double>(c), w = fy - static_cast<double>(r);
  const double z00 = h.at(r, c), z10 = h.at(r, c + 1), z01 = h.at(r + 1, c), z11 = h.at(r + 1, c + 1);
  // Barycentric weights on the triangle holding (u, w).
  return u >= w ? (1 - u) * z00 + (u - w) * z10 + w * z11 : (1 - w) * z00 + (w - u) * z01 + u * z11;
}

// Distance along the unit ray from `o` to the surface, searched in [near, far]; +inf for none.
double analytic(const physics::Heightmap& h, const description::Vec3& o, const description::Vec3& d, double near,
                double far) {
  const auto below = [&](double t) {
    const double x = o.x + t * d.x, y = o.y + t * d.y;
    if (std::abs(x) > h.size_x / 2 || std::abs(y) > h.size_y / 2) return false;
    return o.z + t * d.z <= surface(h, x, y);
  };
  // Steps by index (summed steps drift) and ends exactly at `far`: a hit just short of the
  // maximum range is one.
  const int steps = static_cast<int>(std::ceil((far - near) / 0.002));
  double prev = near;
  for (int k = 0; k <= steps; ++k) {
    const double t = std::min(far, near + 0.002 * k);
    if (below(t)) {
      double lo = prev, hi = t;
      for (int i = 0; i < 50; ++i) (below(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
      return hi;
    }
    prev = t;
  }
  return std::numeric_limits<double>::infinity();
}

constexpr const char* kMast = R"(<robot name="mast">
  <link name="world"/>
  <joint name="mount" type="fixed"><parent link="world"/><child link="mast"/></joint>
  <link name="mast"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <gazebo reference="mast"><sensor type="ray" name="laser"><update_rate>10</update_rate><pose>0 0 0 0 0.35 0</pose>
    <ray><scan><horizontal><samples>640</samples><min_angle>-2.2689</min_angle><max_angle>2.2689</max_angle></horizontal></scan>
      <range><min>0.08</min><max>10.0</max></range></ray></sensor></gazebo>
</robot>)";

TEST(LaserOverMarsYard, EveryRayWithinOneCentimetreOfTheAnalyticSurface) {
  const physics::MarsYard yard = physics::generate_mars_yard(physics::kMarsYardDefaultSeed);
  const physics::Heightmap& h = yard.heightmap;
  const description::RobotModel robot = description::parse_urdf_string(kMast, "mast.urdf", {});
  const double dx = h.cell_x(), dy = h.cell_y();
  // Mast positions: (x, y, heading); two on grid points with the middle ray along a grid row and
  // along a cell diagonal.
  const double gx = -h.size_x / 2 + 300 * dx, gy = -h.size_y / 2 + 200 * dy;
  struct Place {
    double x, y, yaw;
  };
  const std::vector<Place> places = {{yard.start.x, yard.start.y, yard.start.yaw},
                                     {gx, gy, 0.0},
                                     {gx, gy, std::atan2(dy, dx)},
                                     {3.1, -4.7, 2.2},
                                     {-8.35, 6.2, -1.0},
                                     {12.0, 2.0, M_PI}};
  double worst = 0.0;
  int rays = 0, hits = 0, misses = 0;
  for (const Place& p : places) {
    physics::BuildOptions o;
    o.world.kind = physics::WorldSpec::Kind::Heightmap;
    o.world.terrain = h;
    o.spawn = {p.x, p.y, physics::height_at(h, p.x, p.y) + 1.2, 0.0, 0.0, p.yaw};
    const auto model = physics::PhysicsModel::build(robot, o);
    physics::Physics physics(model);
    SensorSet set(robot.sensors, model, 1);
    set.sample_all(physics, 0.0);
    const LaserScan& scan = std::get<LaserScan>(set.reading(0).value);
    // The sensor frame: at the spawn point, yawed, pitched down 0.35 rad.
    const double cy = std::cos(p.yaw), sy = std::sin(p.yaw), cp = std::cos(0.35), sp = std::sin(0.35);
    const description::Vec3 origin{p.x, p.y, o.spawn.z};
    for (int i = 0; i < scan.horizontal_count; ++i) {
      const double a = scan.angle_min + i * scan.angle_increment;
      // R = Rz(yaw) Ry(0.35) applied to (cos a, sin a, 0).
      const double lx = cp * std::cos(a), ly = std::sin(a), lz = -sp * std::cos(a);
      const description::Vec3 d{cy * lx - sy * ly, sy * lx + cy * ly, lz};
      const double want = analytic(h, origin, d, 0.08, 10.0);
      const double got = scan.ranges[static_cast<std::size_t>(i)];
      ++rays;
      if (std::isinf(want)) {
        EXPECT_EQ(got, std::numeric_limits<float>::infinity()) << "place (" << p.x << ", " << p.y << ") ray " << i;
        ++misses;
        continue;
      }
      ++hits;
      worst = std::max(worst, std::abs(got - want));
      EXPECT_NEAR(got, want, 0.01) << "place (" << p.x << ", " << p.y << ") ray " << i;
    }
  }
  EXPECT_GT(hits, 1000);
  std::printf("laser over the Mars Yard: %d rays at %zu places, %d hit the terrain (worst |range - analytic| %.2e m), "
              "%d out of range (+inf)\n",
              rays, places.size(), hits, worst, misses);
}

}  // namespace
}  // namespace mechsim::sensors
