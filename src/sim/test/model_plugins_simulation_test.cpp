// Gazebo model plugins inside the Simulation (the differential-drive test robot with its diff drive
// plugin, robots/testbots): the plugin runs from construction in the manager's tick, its joints
// join the mechanism as direct joints, a ros_control controller on one of them is an error naming
// both, reset() restarts it (Gazebo's plugin Reset), an unknown plugin is named once among the
// warnings and never stops the run, and bad elements stop the construction naming file, line and
// plugin.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "description/robot_loader.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kTestbots = fs::path(MECHSIM_SOURCE_DIR) / "robots" / "testbots";

description::RobotModel diffbot(std::map<std::string, std::string> args = {}) {
  description::LoadOptions options;
  options.packages = {{"mechsim_testbots", kTestbots.string()}};
  args["drive"] = "plugin";
  options.xacro_args = args;
  return description::load_robot((kTestbots / "urdf" / "diffbot.urdf.xacro").string(), options).model;
}

constexpr const char* kControllers = R"(
wheel: {type: velocity_controllers/JointVelocityController, joint: left_wheel_joint}
)";

TEST(ModelPluginsInSimulation, DriveFromConstructionAndRestartOnReset) {
  Simulation sim(diffbot(), make_world({}), control::Params::from_yaml_string(kControllers, "controllers"));
  control::Controller* plugin = sim.controllers().controller("differential_drive_controller");
  ASSERT_NE(plugin, nullptr);
  EXPECT_GE(sim.mechanism().joint_index("left_wheel_joint"), 0);  // a direct joint of the plugin
  auto* cmd = plugin->port_as<control::TwistCommandPort>("cmd_vel");
  auto* odom = plugin->port_as<control::StatePort<control::OdometrySnapshot>>("odom");
  ASSERT_TRUE(cmd && odom);
  control::Twist t;
  t.linear.x = 0.3;
  ASSERT_TRUE(cmd->write(t));
  ASSERT_TRUE(sim.run_for(1.0));
  const double x = sim.physics().base_pose().position.x;
  EXPECT_GT(x, 0.2);
  EXPECT_NEAR(odom->read().x, x, 0.01);
  sim.reset();
  ASSERT_TRUE(sim.step());
  EXPECT_NEAR(sim.physics().base_pose().position.x, 0.0, 1e-3);
  ASSERT_TRUE(sim.run_for(0.05));
  EXPECT_NEAR(odom->read().x, 0.0, 1e-3);  // odometry back at the origin, command zeroed
}

TEST(ModelPluginsInSimulation, AControllerOnAPluginsJointIsAnErrorNamingBoth) {
  Simulation sim(diffbot(), make_world({}), control::Params::from_yaml_string(kControllers, "controllers"));
  const control::ControlResult r = sim.load_controller("wheel");
  ASSERT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("'left_wheel_joint' (parameter /wheel/joint) has no transmission"));
  EXPECT_THAT(r.error, HasSubstr("Gazebo model plugin 'differential_drive_controller' (libgazebo_ros_diff_drive.so"));
  EXPECT_THAT(r.error, HasSubstr("controller 'wheel'"));
}

TEST(ModelPluginsInSimulation, BadElementsStopTheConstructionNamingFileLineAndPlugin) {
  try {
    Simulation sim(diffbot({{"odometry_source", "compass"}}), make_world({}), control::Params());
    FAIL() << "built";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("Gazebo model plugin 'differential_drive_controller' (libgazebo_ros_diff_drive.so, "));
    EXPECT_THAT(e.what(), HasSubstr("diffbot.urdf.xacro"));
    EXPECT_THAT(e.what(), HasSubstr("<odometrySource> must be world or encoder (got \"compass\")"));
  }
}

TEST(ModelPluginsInSimulation, AnUnknownPluginIsNamedOnceAndNeverFatal) {
  description::RobotModel robot = diffbot();
  description::GazeboPlugin unknown;
  unknown.name = "smoke";
  unknown.filename = "libsmoke_machine.so";
  unknown.xml.name = "plugin";
  unknown.xml.line = 7;
  robot.plugins.push_back(unknown);
  Simulation sim(std::move(robot), make_world({}), control::Params());
  ASSERT_TRUE(sim.run_for(0.1));
  const std::vector<std::string> w = sim.physics_warnings();
  EXPECT_EQ(std::count_if(w.begin(), w.end(), [](const std::string& s) { return s.find("libsmoke_machine.so") != std::string::npos; }),
            1);
  EXPECT_TRUE(std::any_of(w.begin(), w.end(), [](const std::string& s) { return s.find("NOT SIMULATED") != std::string::npos; }));
}

}  // namespace
}  // namespace mechsim::sim
