// `mechsim check` on ros2_control robots: the <ros2_control> hardware and the plugin's settings in
// the summary, the controllers of the plugin's parameter files (or --controllers FILE) loaded with
// what they claim, the CC8's and the PR2's ROS 2 variants among them; a bad controller file fails.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "run_process.hpp"

namespace {

using mechsim::apps::test::ProcessResult;
using mechsim::apps::test::run_process;

namespace fs = std::filesystem;

const fs::path kSource = MECHSIM_SOURCE_DIR;
const fs::path kBots = kSource / "robots/ros2bots";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CheckRos2ControlCli, ListsTheHardwareThePluginAndTheControllers) {
  const auto r = run_process({MECHSIM_EXE, "check", (kBots / "urdf/rrbot.urdf.xacro").string(), "--package",
                              "mechsim_ros2bots=" + kBots.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "ros2_control:    1 hardware component")) << r.out;
  EXPECT_TRUE(has(r.out, "RRBotSystem (system, gazebo_ros2_control/GazeboSystem)")) << r.out;
  EXPECT_TRUE(has(r.out, "joint joint1: command position [-1, 1]; state position, velocity, effort")) << r.out;
  EXPECT_TRUE(has(r.out, "joint joint2: command position; state position (initial 0.3), velocity")) << r.out;
  EXPECT_TRUE(has(r.out, "mimics left_finger_joint (x 1, <param name=\"mimic\">)")) << r.out;
  EXPECT_TRUE(has(r.out, "plugin libgazebo_ros2_control.so: controller manager /controller_manager, hold_joints true")) << r.out;
  EXPECT_TRUE(has(r.out, "ros2_control controller manager /controller_manager")) << r.out;
  EXPECT_TRUE(has(r.out, "update_rate 100 Hz, 4 controllers declared")) << r.out;
  EXPECT_TRUE(has(r.out, "/joint_trajectory_controller (joint_trajectory_controller/JointTrajectoryController): position [joint1, joint2]"))
      << r.out;
  EXPECT_TRUE(has(r.out, "4 of 4 controllers load")) << r.out;
  EXPECT_TRUE(has(r.out, "(libgazebo_ros2_control.so), line")) << r.out;
}

TEST(CheckRos2ControlCli, TheCc8AndThePr2OnRos2LoadTheirControllers) {
  const auto cc8 = run_process({MECHSIM_EXE, "check", (kSource / "robots/cc8/urdf/cc8.urdf.xacro").string(), "--package",
                                "mechsim_cc8=" + (kSource / "robots/cc8").string(), "ros2_control:=true"});
  EXPECT_EQ(cc8.exit_code, 0) << cc8.err;
  EXPECT_TRUE(has(cc8.out, "ros2_control controller manager /cc8/controller_manager")) << cc8.out;
  EXPECT_TRUE(has(cc8.out, "13 of 13 controllers load")) << cc8.out;
  EXPECT_TRUE(has(cc8.out, "/rover_drive_controller (mechsim/RoverDriveController): effort [steering_FL")) << cc8.out;
  const auto pr2 = run_process({MECHSIM_EXE, "check", (kSource / "robots/pr2/urdf/pr2.urdf.xacro").string(), "--package",
                                "mechsim_pr2=" + (kSource / "robots/pr2").string(), "ros2_control:=true"});
  EXPECT_EQ(pr2.exit_code, 0) << pr2.err;
  EXPECT_TRUE(has(pr2.out, "/r_arm_controller (joint_trajectory_controller/JointTrajectoryController): effort [r_shoulder_pan_joint"))
      << pr2.out;
  EXPECT_TRUE(has(pr2.out, "28 of 28 controllers load")) << pr2.out;
}

TEST(CheckRos2ControlCli, ABadRos2ControllerFileFailsNamingTheParameter) {
  const fs::path dir = fs::temp_directory_path() / ("mechsim_check_ros2_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "bad.yaml").string();
  std::ofstream(file) << "controller_manager:\n  ros__parameters:\n    fwd: {type: forward_command_controller/ForwardCommandController}\n"
                         "fwd:\n  ros__parameters:\n    joints: [joint1]\n    interface_name: torque\n";
  const auto r = run_process({MECHSIM_EXE, "check", (kBots / "urdf/rrbot.urdf.xacro").string(), "--package",
                              "mechsim_ros2bots=" + kBots.string(), "--controllers", file});
  fs::remove_all(dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.out, "/fwd (forward_command_controller/ForwardCommandController): ERROR")) << r.out;
  EXPECT_TRUE(has(r.out, "parameter /fwd/interface_name: interface 'torque' is none of position, velocity, effort")) << r.out;
  EXPECT_TRUE(has(r.out, "0 of 1 controllers load")) << r.out;
}

}  // namespace
