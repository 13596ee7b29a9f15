// What Gazebo loads, mechsim's node loads (the node reads descriptions leniently in gzserver mode,
// and builds a Simulation of them): three public-style descriptions of our own
// (robots/testbots/urdf/lenient/, `mechsim check --lenient`'s test) load into a Simulation with
// warnings naming what is left out: the gripper's mimic joint plugins take their PID gains from
// the run's parameters (the launch file's YAML) and drive the followers after the actuated knuckle;
// the base runs without the camera of a link it lacks; the arm runs its simple transmissions
// without the vendor's state and model ones.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "description/robot_loader.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

description::LoadedRobot load(const std::string& name) {
  description::LoadOptions options;
  options.lenient = true;
  return description::load_robot((fs::path(MECHSIM_SOURCE_DIR) / "robots/testbots/urdf/lenient" / name).string(), options);
}

bool mentions(const std::vector<std::string>& lines, const std::string& what) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(what) != std::string::npos; });
}

TEST(LenientLoad, TheGrippersMimicPidsTakeTheRunsGainsAndFollowTheKnuckle) {
  const description::LoadedRobot robot = load("adaptive_gripper.urdf");
  const control::Params params = control::Params::from_yaml_string(R"(
gazebo_ros_control:
  pid_gains:
    right_outer_knuckle_joint: {p: 2.0, i: 0.0, d: 0.01}
    left_inner_knuckle_joint: {p: 2.0, i: 0.0, d: 0.01}
    right_inner_knuckle_joint: {p: 2.0, i: 0.0, d: 0.01}
finger: {type: position_controllers/JointPositionController, joint: finger_joint}
)",
                                                                   "gripper");
  Simulation sim(robot.model, make_world({}), params);
  ASSERT_TRUE(sim.controllers().load_controller("finger").ok);
  ASSERT_TRUE(sim.controllers().switch_controllers({"finger"}, {}, control::SwitchStrictness::Strict).ok);
  ASSERT_TRUE(sim.step());  // the switch applies at the tick, whose starting() holds the joint where it is
  auto* cmd = sim.controllers().controller("finger")->port_as<control::ScalarCommandPort>("command");
  ASSERT_NE(cmd, nullptr);
  ASSERT_TRUE(cmd->write(0.5));
  ASSERT_TRUE(sim.run_for(2.0));
  const auto position = [&](const char* joint) {
    return sim.mechanism_state().joints[static_cast<std::size_t>(sim.mechanism().joint_index(joint))].position;
  };
  EXPECT_NEAR(position("finger_joint"), 0.5, 0.02);
  for (const char* follower : {"right_outer_knuckle_joint", "left_inner_knuckle_joint", "right_inner_knuckle_joint"})
    EXPECT_NEAR(position(follower), 0.5, 0.05) << follower;
}

TEST(LenientLoad, TheBaseLoadsWithoutTheCameraOfALinkItLacks) {
  const description::LoadedRobot robot = load("camera_base.urdf");
  EXPECT_TRUE(mentions(robot.warnings, "sensor 'front_camera' left out"));
  EXPECT_TRUE(robot.model.sensors.empty());
  Simulation sim(robot.model, make_world({}), control::Params());
  EXPECT_NE(sim.controllers().controller("diff_drive"), nullptr);
  EXPECT_TRUE(sim.run_for(0.1));
}

TEST(LenientLoad, TheArmRunsItsSimpleTransmissionsWithoutTheVendors) {
  const description::LoadedRobot robot = load("vendor_arm.urdf");
  EXPECT_TRUE(mentions(robot.warnings, "transmission 'arm_franka_state' of type 'franka_hw/FrankaStateInterface' left out"));
  EXPECT_TRUE(mentions(robot.warnings, "transmission 'arm_franka_model' of type 'franka_hw/FrankaModelInterface' left out"));
  ASSERT_EQ(robot.model.transmissions.size(), 3u);
  Simulation sim(robot.model, make_world({}), control::Params());
  EXPECT_EQ(sim.mechanism().transmissions.size(), 3u);
  EXPECT_TRUE(sim.run_for(0.1));
  // Not lenient, the vendor's type is an error naming it.
  description::LoadOptions strict;
  const description::LoadedRobot as_is = description::load_robot(
      (fs::path(MECHSIM_SOURCE_DIR) / "robots/testbots/urdf/lenient/vendor_arm.urdf").string(), strict);
  try {
    Simulation bad(as_is.model, make_world({}), control::Params());
    ADD_FAILURE() << "a vendor transmission type built without lenient";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown transmission type 'franka_hw/FrankaStateInterface'"));
  }
}

}  // namespace
}  // namespace mechsim::sim
