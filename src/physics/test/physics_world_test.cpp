// Worlds: the empty world's ground plane and gravity, and heightmap terrain as a MuJoCo hfield
// whose absolute heights match the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/physics_error.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

Heightmap ramp() {
  Heightmap h;
  h.rows = 5;  // y
  h.cols = 9;  // x
  h.size_x = 8.0;
  h.size_y = 4.0;
  h.source = "test ramp";
  for (std::size_t r = 0; r < h.rows; ++r)
    for (std::size_t c = 0; c < h.cols; ++c)  // rises 0.1 m per column, 0.05 m per row, offset 1.5 m
      h.heights.push_back(static_cast<float>(1.5 + 0.1 * static_cast<double>(c) + 0.05 * static_cast<double>(r)));
  return h;
}

TEST(PhysicsWorld, EmptyWorldGroundIsAtZero) {
  Physics p(test::build(test::box_urdf()));
  EXPECT_NEAR(p.ground_height(3.0, -2.0), 0.0, 1e-9);
}

TEST(PhysicsWorld, HeightfieldReproducesTheGridHeightsAtItsSamples) {
  BuildOptions o;
  o.world.kind = WorldSpec::Kind::Heightmap;
  o.world.terrain = ramp();
  o.spawn.z = 5.0;
  Physics p(test::build(test::box_urdf(), o));
  const Heightmap& h = *o.world.terrain;
  for (std::size_t r = 0; r < h.rows; ++r)
    for (std::size_t c = 0; c < h.cols; ++c) {
      // Sample (r, c) sits at x = -size_x/2 + c dx, y = -size_y/2 + r dy; probe just inside
      // the grid so the ray hits the surface rather than its edge.
      const double x = std::clamp(-h.size_x / 2 + static_cast<double>(c) * h.cell_x(), -3.999, 3.999);
      const double y = std::clamp(-h.size_y / 2 + static_cast<double>(r) * h.cell_y(), -1.999, 1.999);
      EXPECT_NEAR(p.ground_height(x, y), h.at(r, c), 2e-3) << "row " << r << " col " << c;
    }
}

TEST(PhysicsWorld, BoxComesToRestOnTheTerrainSurface) {
  BuildOptions o;
  o.world.kind = WorldSpec::Kind::Heightmap;
  Heightmap flat = ramp();
  for (float& z : flat.heights) z = 0.75f;
  flat.heights[0] = 0.0f;  // one low corner so the field has a range
  o.world.terrain = flat;
  o.spawn.z = 1.0;
  Physics p(test::build(test::box_urdf(), o));
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.base_pose().position.z, 0.75 + 0.05, 3e-3);
}

TEST(PhysicsWorld, BadHeightmapsAreBuildErrors) {
  BuildOptions o;
  o.world.kind = WorldSpec::Kind::Heightmap;
  EXPECT_THROW(test::build(test::box_urdf(), o), PhysicsError);  // none given
  Heightmap h = ramp();
  h.heights.pop_back();
  o.world.terrain = h;
  try {
    test::build(test::box_urdf(), o);
    FAIL();
  } catch (const PhysicsError& e) {
    EXPECT_NE(std::string(e.what()).find("test ramp"), std::string::npos) << e.what();
  }
}

TEST(PhysicsWorld, GravityIsConfigurable) {
  BuildOptions o;
  o.world.gravity = 1.62;  // the Moon
  o.spawn.z = 10.0;
  Physics p(test::build(test::box_urdf(), o));
  while (p.time() < 1.0 - 1e-9) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(10.0 - p.base_pose().position.z, 0.5 * 1.62, 0.01 * 0.81);
}

TEST(PhysicsWorld, GazeboGravityOffLinksFloat) {
  const std::string urdf = test::box_urdf().substr(0, test::box_urdf().rfind("</robot>")) +
                           "<gazebo reference=\"box\"><turnGravityOff>true</turnGravityOff></gazebo></robot>";
  BuildOptions o;
  o.spawn.z = 1.0;
  auto model = test::build(urdf, o);
  ASSERT_EQ(model->gravity_off_links().size(), 1u);
  Physics p(model);
  while (p.time() < 1.0) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.base_pose().position.z, 1.0, 1e-9);
  p.reset();  // still compensated after a reset
  while (p.time() < 0.5) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.base_pose().position.z, 1.0, 1e-9);
}

}  // namespace
}  // namespace mechsim::physics
