// The objects of a Gazebo SDF world in mechsim's physics: pr2_gazebo's own scan.world (a sphere,
// a box, a cylinder and a cup mesh on a box for ground) becomes a world whose sphere, box and
// cylinder stand where the file puts them, at their sizes (found by ray casts from above); the
// cup's mesh is listed as not simulated.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "physics/physics.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCube = R"(<robot name="cube"><link name="base"><inertial><mass value="1"/>
  <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link></robot>)";

TEST(SdfWorldObjects, Pr2ScanWorldsSphereBoxAndCylinderStandWhereTheFileSays) {
  const fs::path file = fs::path(MECHSIM_SHARED_DIR) / "robots/pr2_simulator/pr2_gazebo/test/sensors/scan.world";
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found at " << file;
  WorldConfig config;
  config.name = file.string();
  const World world = make_world(config);
  for (const char* m : {"gplane", "sphere1_model", "box1_model", "cylinder1_model"}) {
    EXPECT_NE(std::find(world.sdf_models.begin(), world.sdf_models.end(), m), world.sdf_models.end()) << m;
  }
  EXPECT_TRUE(std::any_of(world.not_simulated.begin(), world.not_simulated.end(),
                          [](const std::string& n) { return n.find("model 'cup1_model'") != std::string::npos; }));
  ASSERT_EQ(world.spec.boxes.size(), 4u);  // the ground is gplane, a 51.3 m box whose top is z = 0

  physics::BuildOptions options;
  options.world = world.spec;
  options.spawn.x = -2.0;  // out of the way
  const auto model = physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
  physics::Physics p(model);
  // The sphere: centre (2.5, -0.5, 0.5064), radius 0.5; the cylinder: centre (2, 0.8, 1), radius
  // 0.3, length 2, upright.
  EXPECT_NEAR(p.ground_height(2.5, -0.5), 1.0064, 1e-6);
  EXPECT_NEAR(p.ground_height(2.5 + 0.3, -0.5), 0.5064 + std::sqrt(0.25 - 0.09), 1e-6);
  EXPECT_NEAR(p.ground_height(2.0, 0.8), 2.0, 1e-6);
  EXPECT_NEAR(p.ground_height(2.0 + 0.29, 0.8), 2.0, 1e-6);
  EXPECT_NEAR(p.ground_height(2.0 + 0.31, 0.8), 0.0, 1e-6);
}

// Free cylinders and spheres fall and rest on the ground at their own size.
TEST(SdfWorldObjects, FreeCylindersAndSpheresRestAtTheirSize) {
  physics::BuildOptions options;
  physics::WorldBox ball, drum;
  ball.name = "ball";
  ball.shape = physics::WorldBox::Shape::Sphere;
  ball.size = {0.2, 0.2, 0.2};
  ball.pose.position = {1.0, 0.0, 0.5};
  ball.fixed = false;
  drum.name = "drum";
  drum.shape = physics::WorldBox::Shape::Cylinder;
  drum.size = {0.3, 0.3, 0.4};
  drum.pose.position = {-1.0, 0.0, 0.6};
  drum.fixed = false;
  drum.mass = 5.0;
  options.world.boxes = {ball, drum};
  const auto model = physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
  physics::Physics p(model);
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.ground_height(1.0, 0.0), 0.2, 3e-3);    // the ball's top
  EXPECT_NEAR(p.ground_height(-1.0, 0.0), 0.4, 3e-3);   // the drum's top, still upright
  EXPECT_NEAR(p.ground_height(-1.0, 0.14), 0.4, 3e-3);  // flat across its face
}

TEST(SdfWorldObjects, ARoundObjectOfUnequalWidthsIsABuildErrorNamingIt) {
  physics::BuildOptions options;
  physics::WorldBox egg;
  egg.name = "egg";
  egg.shape = physics::WorldBox::Shape::Sphere;
  egg.size = {0.2, 0.3, 0.2};
  options.world.boxes = {egg};
  try {
    physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
    FAIL() << "built";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("world box 'egg': a cylinder's or sphere's size must be equal"));
  }
}

}  // namespace
}  // namespace mechsim::sim
