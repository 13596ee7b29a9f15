// Boxes in the world (WorldSpec::boxes): fixed boxes are world geoms the robot rests on, free
// boxes fall and rest under gravity, contacts name them, bad boxes are build errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "physics/physics_error.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

WorldBox box(const std::string& name, double x, double y, double z, double size, bool fixed, double mass = 1.0) {
  WorldBox b;
  b.name = name;
  b.pose.position = {x, y, z};
  b.size = {size, size, size};
  b.fixed = fixed;
  b.mass = mass;
  return b;
}

// The test robot (a free 0.1 m cube) lands on a fixed 0.4 m pedestal; a free 0.2 m box dropped
// beside it comes to rest on the ground. Heights within 3 mm (contact softness).
TEST(PhysicsWorldBox, RobotRestsOnAFixedBoxAndAFreeBoxOnTheGround) {
  BuildOptions o;
  o.world.boxes = {box("pedestal", 0.0, 0.0, 0.2, 0.4, true), box("crate", 1.0, 0.0, 0.5, 0.2, false, 2.0)};
  o.spawn.z = 0.8;
  auto model = test::build(test::box_urdf(), o);
  Physics p(model);
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.base_pose().position.z, 0.4 + 0.05, 3e-3);  // the robot's root, not the crate
  EXPECT_NEAR(p.base_pose().position.x, 0.0, 1e-3);
  std::vector<Contact> contacts;
  p.contacts(contacts);
  bool robot_on_pedestal = false, crate_on_ground = false;
  double crate_force = 0.0;
  for (const Contact& c : contacts) {
    const std::string a(c.link_a), b(c.link_b);
    if ((a == "box:pedestal") != (b == "box:pedestal") && (a != "ground" && b != "ground")) robot_on_pedestal = true;
    if ((a == "box:crate" && b == "ground") || (a == "ground" && b == "box:crate")) {
      crate_on_ground = true;
      crate_force += c.normal_force;
    }
  }
  EXPECT_TRUE(robot_on_pedestal);
  EXPECT_TRUE(crate_on_ground);
  EXPECT_NEAR(crate_force, 2.0 * 9.81, 0.05 * 2.0 * 9.81);  // the crate's weight
  // The crate's height from a ray cast from above (world geoms are in group 2).
  EXPECT_NEAR(p.ground_height(1.0, 0.0), 0.2, 3e-3);
  EXPECT_NEAR(p.ground_height(0.15, 0.15), 0.4, 1e-6);  // the pedestal's top, beside the robot
}

TEST(PhysicsWorldBox, BadBoxesAreBuildErrorsNamingTheBox) {
  const auto expect_error = [](const std::vector<WorldBox>& boxes, const std::string& needle) {
    BuildOptions o;
    o.world.boxes = boxes;
    try {
      test::build(test::box_urdf(), o);
      ADD_FAILURE() << "built with " << needle;
    } catch (const PhysicsError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_error({box("flat", 0, 0, 0, 0.0, true)}, "world box 'flat': size");
  expect_error({box("twin", 0, 0, 0, 0.1, true), box("twin", 1, 0, 0, 0.1, false)}, "world box 'twin': the name");
  expect_error({box("ghost", 0, 0, 1, 0.1, false, 0.0)}, "world box 'ghost': mass");
  expect_error({box("", 0, 0, 1, 0.1, true)}, "a box has no name");
}

}  // namespace
}  // namespace mechsim::physics
