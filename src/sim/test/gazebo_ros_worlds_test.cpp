// The worlds mechsim's gazebo_ros package ships for gazebo_ros' launch files
// (src/ros/packages/gazebo_ros/worlds, gazebo_plugins' gazebo_ros_range.world): each loads with
// the models its comment names, builds with a robot in it and runs 2 s without anything leaving
// the world; the rubble pile settles, the shapes stand, the pendulums swing and the elevator cars
// rest on their lift joints.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

const fs::path kPackages = fs::path(MECHSIM_SOURCE_DIR) / "src/ros/packages";

World load(const fs::path& file) {
  WorldConfig config;
  config.name = file.string();
  return make_world(config);
}

bool has(const World& w, const std::string& model) {
  return std::find(w.sdf_models.begin(), w.sdf_models.end(), model) != w.sdf_models.end();
}

// Builds the world with the cube at (x, y) and runs 2 s; every free object and passive link stays
// finite and above z = -0.1 (nothing falls through the ground).
void runs(const World& world, double x, double y) {
  physics::BuildOptions options;
  options.world = world.spec;
  options.spawn.x = x;
  options.spawn.y = y;
  options.spawn.z = 0.06;
  physics::Physics p(physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options));
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok()) << world.name << " at t = " << p.time();
  EXPECT_NEAR(p.base_pose().position.z, 0.05, 0.01) << world.name;
}

TEST(GazeboRosWorlds, ShapesRubbleMudAndElevatorLoadAndRun) {
  const World shapes = load(kPackages / "gazebo_ros/worlds/shapes.world");
  for (const char* m : {"ground_plane", "box", "sphere", "cylinder"}) EXPECT_TRUE(has(shapes, m)) << m;
  runs(shapes, 3.0, 0.0);

  const World rubble = load(kPackages / "gazebo_ros/worlds/rubble.world");
  EXPECT_EQ(rubble.spec.boxes.size(), 18u);
  runs(rubble, 3.0, 0.0);

  const World mud = load(kPackages / "gazebo_ros/worlds/mud.world");
  for (const char* m : {"pendulum_thick_mud", "pendulum_thin_mud", "pendulum_no_mud"}) EXPECT_TRUE(has(mud, m)) << m;
  EXPECT_TRUE(std::any_of(mud.not_simulated.begin(), mud.not_simulated.end(),
                          [](const std::string& n) { return n.find("libMudPlugin.so") != std::string::npos; }));
  runs(mud, 0.0, 3.0);

  const World elevator = load(kPackages / "gazebo_ros/worlds/elevator_ros.world");
  for (const char* m : {"elevator1", "elevator2", "floor0", "floor3"}) EXPECT_TRUE(has(elevator, m)) << m;
  EXPECT_TRUE(std::any_of(elevator.not_simulated.begin(), elevator.not_simulated.end(),
                          [](const std::string& n) { return n.find("libElevatorPlugin.so") != std::string::npos; }));
  runs(elevator, -3.0, 0.0);
}

TEST(GazeboRosWorlds, TheRangeTestWorldHasNoGravityAndItsTwoSonarBoxes) {
  const World range = load(kPackages / "standins/gazebo_plugins/test/test_worlds/gazebo_ros_range.world");
  EXPECT_EQ(range.spec.gravity, 0.0);
  EXPECT_FALSE(range.spec.ground_plane);
  EXPECT_TRUE(has(range, "model_1"));
  EXPECT_TRUE(has(range, "model_2"));
}

}  // namespace
}  // namespace mechsim::sim
