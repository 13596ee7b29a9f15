// mechsim's wheel-height field contact (physics/wheel_terrain_contact.hpp): a cylinder rolling
// down a 10 degree height field rolls as theory has it (a = 2/3 g sin(theta)), with contact
// normals on the surface's; two contacts on a plane, a third where a bump rises between the rims;
// a cylinder standing on its end and other shapes keep MuJoCo's routine and touch where they
// should; a box above the terrain costs nothing and gets no contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "physics/heightmap.hpp"
#include "physics/physics.hpp"
#include "physics/test/physics_test_util.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {
namespace {

constexpr double kSlope = 10.0 * M_PI / 180.0;
constexpr double kRadius = 0.09;  // m, the CC8's wheels
constexpr double kWidth = 0.12;   // m

// A free solid cylinder of 2 kg (I = m r^2 / 2 about its axis), axis along the link's y, or along
// its z when `upright`.
std::string cylinder_urdf(bool upright = false) {
  const double m = 2.0, ia = 0.5 * m * kRadius * kRadius, it = m * (3 * kRadius * kRadius + kWidth * kWidth) / 12.0;
  const std::string rpy = upright ? "0 0 0" : "1.5707963267948966 0 0";
  char inertia[256];
  std::snprintf(inertia, sizeof inertia, R"(<inertia ixx="%.9g" iyy="%.9g" izz="%.9g" ixy="0" ixz="0" iyz="0"/>)", it,
                upright ? it : ia, upright ? ia : it);
  return std::string(R"(<robot name="wheel"><link name="wheel"><inertial><mass value="2"/>)") + inertia +
         R"(</inertial><collision><origin rpy=")" + rpy + R"("/><geometry><cylinder radius="0.09" length="0.12"/></geometry>
    </collision></link></robot>)";
}

std::string box_urdf_sized(double x, double y, double z) {
  char text[512];
  std::snprintf(text, sizeof text, R"(<robot name="block"><link name="block"><inertial><mass value="5"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="%g %g %g"/></geometry></collision></link></robot>)", x, y, z);
  return text;
}

// A height field 8 m x 4 m of `cell` spacing with heights f(x, y).
template <typename F>
Heightmap field(double cell, F f) {
  Heightmap map;
  map.size_x = 8.0;
  map.size_y = 4.0;
  map.cols = static_cast<std::size_t>(std::lround(map.size_x / cell)) + 1;
  map.rows = static_cast<std::size_t>(std::lround(map.size_y / cell)) + 1;
  map.heights.resize(map.rows * map.cols);
  for (std::size_t r = 0; r < map.rows; ++r)
    for (std::size_t c = 0; c < map.cols; ++c)
      map.heights[r * map.cols + c] = static_cast<float>(
          f(-map.size_x / 2 + static_cast<double>(c) * map.cell_x(), -map.size_y / 2 + static_cast<double>(r) * map.cell_y()));
  map.source = "test field";
  return map;
}

BuildOptions on(Heightmap map) {
  BuildOptions options;
  options.world.kind = WorldSpec::Kind::Heightmap;
  options.world.ground_plane = false;
  options.world.terrain = std::move(map);
  return options;
}

// The plane z = -tan(kSlope) x: downhill towards +x.
double slope(double x, double /*y*/) { return -std::tan(kSlope) * x; }

TEST(WheelTerrainContact, ACylinderRollsDownAHeightFieldAsTheoryHas) {
  for (const double cell : {0.05, 0.1}) {
    SCOPED_TRACE("cell " + std::to_string(cell) + " m");
    BuildOptions options = on(field(cell, slope));
    const double x0 = -2.0;
    options.spawn = {x0 + kRadius * std::sin(kSlope), 0.0, slope(x0, 0) + kRadius * std::cos(kSlope), 0, 0, 0};
    const auto model = test::build(cylinder_urdf(), options);
    Physics physics(model);
    const description::Vec3 start = physics.base_pose().position;
    const description::Vec3 n{std::sin(kSlope), 0.0, std::cos(kSlope)};
    std::vector<Contact> contacts;
    double worst_normal_deg = 0.0;
    std::size_t most = 0;
    const double duration = 2.0;
    for (int k = 0; k < static_cast<int>(duration / model->timestep()); ++k) {
      ASSERT_TRUE(physics.step().ok());
      physics.contacts(contacts);
      most = std::max(most, contacts.size());
      for (const Contact& c : contacts) {
        const double cosine = std::abs(c.normal.x * n.x + c.normal.y * n.y + c.normal.z * n.z);
        worst_normal_deg = std::max(worst_normal_deg, std::acos(std::min(1.0, cosine)) * 180.0 / M_PI);
      }
    }
    const description::Vec3 end = physics.base_pose().position;
    const double theory = 0.5 * 2.0 / 3.0 * 9.81 * std::sin(kSlope) * duration * duration * std::cos(kSlope);
    std::printf("cell %.2f m: %.4f m of %.4f m (%.3f %% off), %.2g m sideways, normals off by %.3g deg, %zu contacts\n",
                cell, end.x - start.x, theory, 100 * ((end.x - start.x) / theory - 1), end.y - start.y, worst_normal_deg, most);
    EXPECT_NEAR((end.x - start.x) / theory, 1.0, 0.005);
    EXPECT_LT(std::abs(end.y - start.y), 1e-3);
    EXPECT_LT(worst_normal_deg, 1e-3);
    EXPECT_EQ(most, 2u) << "a cylinder on a plane rests on its two rims";
  }
}

// A cylinder lying across y at (0, 0) on `map`, `clearance` above where it would rest on z = 0.
std::size_t contacts_at_rest(const Heightmap& map, double z, std::vector<Contact>& contacts) {
  BuildOptions options = on(map);
  options.spawn = {0.0, 0.0, z, 0, 0, 0};
  const auto model = test::build(cylinder_urdf(), options);
  Physics physics(model);
  EXPECT_TRUE(physics.step().ok());
  return physics.contacts(contacts);
}

TEST(WheelTerrainContact, ABumpBetweenTheRimsGetsItsOwnContact) {
  std::vector<Contact> contacts;
  // Level ground: the two rims.
  EXPECT_EQ(contacts_at_rest(field(0.05, [](double, double) { return 0.0; }), kRadius - 0.001, contacts), 2u);
  // A ridge 5 cm high along x under the tread's middle, narrower than the tread (0 at |y| >= 5 cm):
  // the rims do not reach it; the middle circle does, with the surface's normal there.
  const auto ridge = [](double, double y) { return std::max(0.0, 0.05 - std::abs(y)); };
  ASSERT_EQ(contacts_at_rest(field(0.05, ridge), kRadius + 0.049, contacts), 1u);
  EXPECT_NEAR(contacts[0].position.y, 0.0, 1e-6);
  EXPECT_NEAR(contacts[0].depth, 0.001, 1e-6);
  EXPECT_NEAR(contacts[0].normal.z, 1.0, 1e-9);
}

TEST(WheelTerrainContact, AWheelAgainstAStepTouchesItsEdgeAndTheGround) {
  // A 4 cm step at x = 0.05 m (rising over one 1 cm cell): the wheel at x = 0 rests on the ground
  // and leans on the step's edge, two contacts per rim, the edge's along the wheel's radius.
  const auto step = [](double x, double) { return std::clamp((x - 0.05) / 0.01, 0.0, 1.0) * 0.04; };
  std::vector<Contact> contacts;
  const std::size_t n = contacts_at_rest(field(0.01, step), kRadius - 0.0005, contacts);
  EXPECT_EQ(n, 4u);
  int on_step = 0;
  for (const Contact& c : contacts) on_step += c.normal.x < -0.5 ? 1 : 0;  // from the edge to the axle
  EXPECT_EQ(on_step, 2);
}

TEST(WheelTerrainContact, ACylinderOnItsEndAndABoxKeepMuJoCosContacts) {
  // A cylinder standing on its end on level ground settles on its face at the right height.
  {
    BuildOptions options = on(field(0.05, [](double, double) { return 0.0; }));
    options.spawn = {0.013, -0.021, 0.5 * kWidth + 0.002, 0, 0, 0};
    Physics physics(test::build(cylinder_urdf(true), options));
    for (int k = 0; k < 500; ++k) ASSERT_TRUE(physics.step().ok());
    EXPECT_NEAR(physics.base_pose().position.z, 0.5 * kWidth, 2e-3);
    EXPECT_LT(std::abs(physics.base_twist().angular.x) + std::abs(physics.base_twist().angular.y), 1e-2);
  }
  // A box resting on the slope stays put at the right height (the shortcut skips only boxes that
  // cannot touch).
  {
    BuildOptions options = on(field(0.05, [](double x, double) { return 0.1 * x; }));
    options.spawn = {0.0, 0.0, 0.05 / std::cos(std::atan(0.1)) + 0.001, 0, -std::atan(0.1), 0};
    Physics physics(test::build(box_urdf_sized(0.3, 0.2, 0.1), options));
    for (int k = 0; k < 500; ++k) ASSERT_TRUE(physics.step().ok());
    EXPECT_NEAR(physics.base_pose().position.z, 0.05 / std::cos(std::atan(0.1)), 2e-3);
    EXPECT_LT(std::abs(physics.base_pose().position.x), 2e-3);
  }
  // A box above every sample under it gets no contact; lowered onto the ground, it does.
  {
    BuildOptions options = on(field(0.05, [](double x, double y) { return 0.02 * std::sin(7 * x) * std::cos(5 * y); }));
    options.spawn = {0.0, 0.0, 0.05 + 0.02 + 0.001, 0, 0, 0};
    Physics physics(test::build(box_urdf_sized(0.3, 0.2, 0.1), options));
    ASSERT_TRUE(physics.step().ok());
    std::vector<Contact> contacts;
    EXPECT_EQ(physics.contacts(contacts), 0u);
    for (int k = 0; k < 300; ++k) ASSERT_TRUE(physics.step().ok());
    EXPECT_GT(physics.contacts(contacts), 0u);
    EXPECT_GT(physics.base_pose().position.z, 0.04);
  }
}

}  // namespace
}  // namespace mechsim::physics
