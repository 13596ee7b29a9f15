// Sensing queries: the exact ray/height-field intersection against an independent evaluation of
// MuJoCo's triangulated surface (and MuJoCo 2.2.2's own mj_rayHfield, which misses on grid
// lines), Physics::cast_rays on shapes, accelerations at rest and in free fall, joint wrenches and
// contact forces.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include "physics/mujoco_internal.hpp"
#include "physics/ray_cast.hpp"
#include "physics/sensing_internal.hpp"
#include "physics/transform.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A rough random grid in [0, 1] (MuJoCo's normalised data).
struct Grid {
  int rows = 13, cols = 17;
  std::vector<float> data;
  HfieldGrid view() const { return {rows, cols, 4.0, 3.0, 0.8, 0.5, data.data()}; }
};

Grid random_grid(std::uint64_t seed) {
  Grid g;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < g.rows * g.cols; ++i) g.data.push_back(static_cast<float>(u(rng)));
  return g;
}

// The surface height at (x, y) computed independently of ray_cast.cpp: find the cell, pick the
// triangle by which side of the (c, r)-(c+1, r+1) diagonal the point is on, and intersect the
// vertical line with the plane through the triangle's three corners (normal by cross product).
double surface(const HfieldGrid& g, double x, double y) {
  const double dx = 2 * g.half_x / (g.cols - 1), dy = 2 * g.half_y / (g.rows - 1);
  const int c = std::clamp(static_cast<int>((x + g.half_x) / dx), 0, g.cols - 2);
  const int r = std::clamp(static_cast<int>((y + g.half_y) / dy), 0, g.rows - 2);
  const auto corner = [&](int cc, int rr) {
    return Vec3{-g.half_x + cc * dx, -g.half_y + rr * dy, g.data[rr * g.cols + cc] * g.top};
  };
  const Vec3 a = corner(c, r), b = corner(c + 1, r + 1);
  const bool lower = (x - a.x) / dx >= (y - a.y) / dy;  // below the diagonal: the (c+1, r) triangle
  const Vec3 k = lower ? corner(c + 1, r) : corner(c, r + 1);
  const Vec3 e1{b.x - a.x, b.y - a.y, b.z - a.z}, e2{k.x - a.x, k.y - a.y, k.z - a.z};
  const Vec3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
  return a.z - (n.x * (x - a.x) + n.y * (y - a.y)) / n.z;
}

// Reference distance: march in steps of 0.5 mm until the ray is at or below the surface inside
// the footprint, then bisect. Rays here start above the field and inside its footprint.
double reference(const HfieldGrid& g, const double p[3], const double v[3], double max_t) {
  const auto below = [&](double t) {
    const double x = p[0] + t * v[0], y = p[1] + t * v[1], z = p[2] + t * v[2];
    if (std::abs(x) > g.half_x || std::abs(y) > g.half_y) return false;
    return z <= surface(g, x, y);
  };
  double prev = 0.0;
  for (double t = 0.0005; t <= max_t; t += 0.0005) {
    const double x = p[0] + t * v[0], y = p[1] + t * v[1];
    if (std::abs(x) > g.half_x || std::abs(y) > g.half_y) return -1.0;
    if (below(t)) {
      double lo = prev, hi = t;
      for (int i = 0; i < 60; ++i) (below(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
      return hi;
    }
    prev = t;
  }
  return -1.0;
}

TEST(RayHfield, MatchesAnIndependentSurfaceOnRandomRays) {
  const Grid grid = random_grid(7);
  const HfieldGrid g = grid.view();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(-3.9, 3.9), uy(-2.9, 2.9), angle(-M_PI, M_PI), down(-0.6, -0.02);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const double p[3] = {ux(rng), uy(rng), 0.85};
    const double a = angle(rng), e = down(rng);
    const double v[3] = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
    const double want = reference(g, p, v, 12.0);
    const double got = ray_hfield(g, p, v);
    if (want < 0.0) {
      // The reference stops at the footprint's edge; ours may hit the field's side wall there.
      if (got >= 0.0) {
        const double x = p[0] + got * v[0], y = p[1] + got * v[1];
        EXPECT_NEAR(std::max(std::abs(x) - g.half_x, std::abs(y) - g.half_y), 0.0, 1e-9) << "ray " << i;
      }
      continue;
    }
    ++hits;
    EXPECT_NEAR(got, want, 1e-6) << "ray " << i;
  }
  EXPECT_GT(hits, 250);
}

// Rays lying exactly on grid lines and cell diagonals: where MuJoCo 2.2.2's mj_rayHfield can
// pass between two triangles.
TEST(RayHfield, RaysOnGridLinesAndDiagonalsHitTheSurface) {
  const Grid grid = random_grid(3);
  const HfieldGrid g = grid.view();
  const double dx = 2 * g.half_x / (g.cols - 1), dy = 2 * g.half_y / (g.rows - 1);
  int checked = 0;
  for (int c = 1; c < g.cols - 1; ++c) {
    for (int r = 1; r < g.rows - 1; ++r) {
      const double x = -g.half_x + c * dx, y = -g.half_y + r * dy;
      for (const auto& dir : {std::array<double, 2>{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {dx, dy}, {-dx, -dy}}) {
        const double n = std::hypot(dir[0], dir[1]);
        for (const double e : {-0.05, -0.2, -0.5}) {
          const double v[3] = {std::cos(e) * dir[0] / n, std::cos(e) * dir[1] / n, std::sin(e)};
          const double p[3] = {x, y, 0.85};
          const double want = reference(g, p, v, 12.0);
          if (want < 0.0) continue;
          EXPECT_NEAR(ray_hfield(g, p, v), want, 1e-6) << "from (" << c << ", " << r << ")";
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(RayHfield, SideWallsBottomAndInside) {
  const Grid grid = random_grid(5);
  const HfieldGrid g = grid.view();
  // From outside, level and low: hits the side wall at x = -half_x.
  const double p[3] = {-6.0, 0.3, -0.2}, v[3] = {1, 0, 0};
  EXPECT_NEAR(ray_hfield(g, p, v), 2.0, 1e-12);
  // From below: the bottom of the block.
  const double q[3] = {0.5, 0.5, -2.0}, up[3] = {0, 0, 1};
  EXPECT_NEAR(ray_hfield(g, q, up), 1.5, 1e-12);
  // Starting inside the solid.
  const double s[3] = {0.5, 0.5, -0.1};
  EXPECT_EQ(ray_hfield(g, s, up), 0.0);
  // Above and pointing away: nothing.
  const double a[3] = {0.5, 0.5, 2.0};
  EXPECT_LT(ray_hfield(g, a, up), 0.0);
  // Straight down onto a sample point: its height.
  const double dx = 2 * g.half_x / (g.cols - 1), dy = 2 * g.half_y / (g.rows - 1);
  const double d[3] = {-g.half_x + 5 * dx, -g.half_y + 4 * dy, 2.0}, down[3] = {0, 0, -1};
  EXPECT_NEAR(ray_hfield(g, d, down), 2.0 - g.data[4 * g.cols + 5] * g.top, 1e-12);
}

// MuJoCo 2.2.2's own height-field ray on the same grid-line rays: the defect this file works
// around. If a MuJoCo upgrade fixes it, this test fails and physics/README.md should say so.
TEST(RayHfield, MujocoRayHfieldMissesOnGridLines) {
  Heightmap h;
  h.rows = 13;
  h.cols = 17;
  h.size_x = 8.0;
  h.size_y = 6.0;
  const Grid grid = random_grid(3);
  for (const float z : grid.data) h.heights.push_back(z * 0.8f);
  BuildOptions o;
  o.world.kind = WorldSpec::Kind::Heightmap;
  o.world.terrain = h;
  o.spawn.z = 5.0;
  const auto model = test::build(test::box_urdf(), o);
  const mjModel* m = model->impl().model;
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  int geom = -1;
  for (int i = 0; i < m->ngeom; ++i)
    if (m->geom_type[i] == mjGEOM_HFIELD) geom = i;
  ASSERT_GE(geom, 0);
  const double z0 = d->geom_xpos[3 * geom + 2];
  const HfieldGrid g = detail::hfield_grid(m, geom);
  const double dx = h.cell_x(), dy = h.cell_y();
  int rays = 0, wrong_mujoco = 0, wrong_ours = 0;
  for (int c = 1; c < g.cols - 1; ++c)
    for (int r = 1; r < g.rows - 1; ++r)
      for (const double e : {-0.05, -0.2}) {
        // Along the row's grid line (+x), from the sample point.
        const mjtNum p[3] = {-4.0 + c * dx, -3.0 + r * dy, z0 + 0.85}, v[3] = {std::cos(e), 0.0, std::sin(e)};
        const double local[3] = {p[0], p[1], p[2] - z0};
        const double want = reference(g, local, v, 12.0);
        if (want < 0.0) continue;
        ++rays;
        if (std::abs(mj_rayHfield(m, d, geom, p, v) - want) > 0.01) ++wrong_mujoco;
        if (std::abs(detail::ray_hfield_geom(m, d, geom, p, v) - want) > 1e-6) ++wrong_ours;
      }
  mj_deleteData(d);
  EXPECT_GT(rays, 100);
  EXPECT_EQ(wrong_ours, 0);
  EXPECT_GT(wrong_mujoco, 0) << "MuJoCo's mj_rayHfield hit every grid-line ray: update physics/README.md";
  std::printf("grid-line rays: %d, MuJoCo 2.2.2 mj_rayHfield off by > 1 cm: %d, mechsim's: %d\n", rays, wrong_mujoco,
              wrong_ours);
}

// A robot of two boxes on the ground: `base` (0.4 m cube, 10 kg) and, on a fixed joint 0.5 m
// above its centre, `head` (0.1 m cube, 1 kg, its own body).
std::string two_box_urdf() {
  return R"(<robot name="boxes">
  <link name="base"><inertial><mass value="10"/><inertia ixx="0.27" ixy="0" ixz="0" iyy="0.27" iyz="0" izz="0.27"/></inertial>
    <collision><geometry><box size="0.4 0.4 0.4"/></geometry></collision></link>
  <joint name="neck" type="fixed"><parent link="base"/><child link="head"/><origin xyz="0 0 0.5"/></joint>
  <link name="head"><inertial><origin xyz="0.05 0 0"/><mass value="1"/><inertia ixx="0.002" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
</robot>)";
}

std::shared_ptr<const PhysicsModel> boxes_with_wall(double wall_x) {
  BuildOptions o;
  o.spawn.z = 0.2;
  WorldBox wall;
  wall.name = "wall";
  wall.pose.position = {wall_x, 0.0, 0.5};
  wall.size = {0.2, 4.0, 1.0};
  o.world.boxes.push_back(wall);
  return test::build(two_box_urdf(), o);
}

TEST(PhysicsSensing, CastRaysHitsTheWallTheGroundAndNotTheExcludedBody) {
  const auto model = boxes_with_wall(3.0);
  Physics p(model);
  const int base_body = model->links()[*model->link_index("base")].body;
  const RayFilter own_excluded = make_ray_filter(*model, base_body, RayTargets::Collision);
  const RayFilter all = make_ray_filter(*model, -1, RayTargets::Collision);
  const Vec3 origin{0.0, 0.0, 0.1};  // inside the base box
  const Vec3 dirs[5] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, -1}, {std::cos(0.3), std::sin(0.3), 0}, {0, 0, 1}};
  double r[5];
  p.cast_rays(own_excluded, origin, dirs, 5, 0.0, 10.0, r);
  EXPECT_NEAR(r[0], 2.9, 1e-9);                 // the wall's near face
  EXPECT_EQ(r[1], kInf);                        // nothing behind
  EXPECT_NEAR(r[2], 0.1, 1e-9);                 // the ground, through the excluded base
  EXPECT_NEAR(r[3], 2.9 / std::cos(0.3), 1e-9);  // the face, obliquely
  EXPECT_EQ(r[4], kInf);  // the head, on a fixed joint to the base, is the sensor's own too (Gazebo lumps it)
  p.cast_rays(all, origin, dirs, 5, 0.0, 10.0, r);
  EXPECT_NEAR(r[1], 0.2, 1e-9);  // the base box's own face, from inside
  EXPECT_NEAR(r[4], 0.3, 1e-9);  // its top face
  // Nearer than `near` is not seen; beyond `far` is nothing.
  p.cast_rays(own_excluded, origin, dirs, 1, 0.0, 2.5, r);
  EXPECT_EQ(r[0], kInf);
}

// Rays against a real mesh (the PR2's torso collision mesh, 1 m ahead): cast_rays (the mesh's BVH,
// mju_rayGeom for the rest) agrees with MuJoCo's own mj_ray (mj_rayMesh: every triangle).
TEST(PhysicsSensing, CastRaysOnAMeshAgreesWithMujocoRayMesh) {
  const std::string mesh = std::string(MECHSIM_SHARED_DIR) + "/robots/pr2_description/meshes/torso_v0/torso_lift_L.stl";
  if (!std::ifstream(mesh)) GTEST_SKIP() << "shared data absent: no " << mesh;
  const std::string urdf = R"(<robot name="m">
  <link name="base"><inertial><mass value="10"/><inertia ixx="0.27" ixy="0" ixz="0" iyy="0.27" iyz="0" izz="0.27"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <joint name="j" type="fixed"><parent link="base"/><child link="torso"/><origin xyz="1.0 0.1 0.3" rpy="0.3 -0.2 0.7"/></joint>
  <link name="torso"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><mesh filename=")" + mesh + R"("/></geometry></collision></link>
</robot>)";
  BuildOptions o;
  o.spawn.z = 0.2;
  const auto model = test::build(urdf, o);
  const mjModel* m = model->impl().model;
  Physics p(model);
  // Nothing excluded: the torso is welded to the base, so excluding the base would drop it.
  const RayFilter filter = make_ray_filter(*model, -1, RayTargets::Collision);
  ASSERT_EQ(filter.meshes.size(), 1u);
  const int g = filter.meshes[0];
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  const Vec3 origin{0.0, 1.0, 0.5};  // beside the base: no ray towards the mesh passes over it
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  int hits = 0, disagree = 0;
  double worst = 0.0;
  for (int i = 0; i < 4000; ++i) {
    // Towards the mesh, spread over its bounding sphere and beyond.
    const mjtNum* c = d->geom_xpos + 3 * g;
    Vec3 u{c[0] - origin.x + 0.3 * n(rng), c[1] - origin.y + 0.3 * n(rng), c[2] - origin.z + 0.3 * n(rng)};
    const double len = std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    u = {u.x / len, u.y / len, u.z / len};
    double r = 0.0;
    p.cast_rays(filter, origin, &u, 1, 0.0, 10.0, &r);
    const mjtNum pnt[3] = {origin.x, origin.y, origin.z}, vec[3] = {u.x, u.y, u.z};
    // MuJoCo's own ray over the same shapes (collision group 0, world group 2): mj_rayMesh for
    // the mesh, its box and plane routines for the base and the ground.
    const mjtByte groups[mjNGROUP] = {1, 0, 1, 0, 0, 0};
    int hit_geom = -1;
    double want = mj_ray(m, d, pnt, vec, groups, 1, -1, &hit_geom);
    if (want > 10.0) want = -1.0;  // beyond the cast's range
    if (hit_geom == g) ++hits;
    if ((want < 0.0) != (r == kInf)) {
      ++disagree;
      continue;
    }
    if (want >= 0.0) worst = std::max(worst, std::abs(r - want));
  }
  mj_deleteData(d);
  EXPECT_GT(hits, 1000);
  EXPECT_EQ(disagree, 0);
  EXPECT_LT(worst, 1e-6);
}

TEST(PhysicsSensing, AccelerationAtRestIsGravityUpAndZeroInFreeFall) {
  Physics p(boxes_with_wall(3.0));
  for (int i = 0; i < 1500; ++i) ASSERT_TRUE(p.step().ok());  // settle on the ground
  const std::size_t head = *p.model().link_index("head");
  const Acceleration a = p.link_acceleration(head, {0.05, 0.0, 0.0});
  EXPECT_NEAR(a.specific_force.x, 0.0, 1e-3);
  EXPECT_NEAR(a.specific_force.y, 0.0, 1e-3);
  EXPECT_NEAR(a.specific_force.z, 9.81, 1e-3);
  // Free fall: an accelerometer reads nothing.
  BuildOptions o;
  o.spawn.z = 50.0;
  Physics falling(test::build(test::box_urdf(), o));
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(falling.step().ok());
  const Acceleration f = falling.link_acceleration(0, {0.02, 0.03, 0.0});
  EXPECT_NEAR(f.specific_force.z, 0.0, 1e-9);
}

TEST(PhysicsSensing, JointWrenchCarriesTheChildsWeightAndMoment) {
  Physics p(boxes_with_wall(3.0));
  for (int i = 0; i < 1500; ++i) ASSERT_TRUE(p.step().ok());
  const std::size_t head = *p.model().link_index("head");
  ASSERT_NE(p.model().links()[head].body, p.model().links()[*p.model().link_index("base")].body);
  const Wrench w = p.joint_wrench(head, {0.0, 0.0, 0.0});
  // The base holds the 1 kg head up, and against the moment of its centre 5 cm off the joint.
  EXPECT_NEAR(w.force.x, 0.0, 1e-3);
  EXPECT_NEAR(w.force.z, 9.81, 1e-3);
  EXPECT_NEAR(w.torque.y, -0.05 * 9.81, 1e-3);
}

TEST(PhysicsSensing, ContactForcesOnARestingRobotSumToItsWeight) {
  Physics p(boxes_with_wall(3.0));
  for (int i = 0; i < 1500; ++i) ASSERT_TRUE(p.step().ok());
  std::vector<Contact> contacts;
  ASSERT_GT(p.contacts(contacts), 0u);
  double up = 0.0;
  for (const Contact& c : contacts) {
    // The force on the robot, whichever side of the pair it is.
    const bool robot_is_b = p.model().geom_name(c.geom_b).find("/collision/") != std::string_view::npos;
    up += robot_is_b ? c.force.z : -c.force.z;
  }
  EXPECT_NEAR(up, 11.0 * 9.81, 0.02 * 11.0 * 9.81);
}

}  // namespace
}  // namespace mechsim::physics
