// `mechsim check --lenient` loads what Gazebo loads, each thing left out named with why: three
// public-style descriptions of our own (robots/testbots/urdf/lenient/): a Robotiq-style gripper
// whose mimic joint plugins ask for a PID with no gains on the parameter server at check time
// (they come with the launch file's YAML: checked with --controllers, not without), a base whose
// camera macro names a link it does not have (Gazebo ignores the sensor), and an arm with a
// vendor's state and model transmissions (left out when lenient; an error otherwise).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

std::string lenient_robot(const std::string& name) {
  return (fs::path(MECHSIM_SOURCE_DIR) / "robots/testbots/urdf/lenient" / name).string();
}

TEST(CheckLenientCli, AMimicPluginsPidGainsAreTheRunsNotTheChecks) {
  const std::string file = lenient_robot("adaptive_gripper.urdf");
  const ProcessResult r = run_process({MECHSIM_EXE, "check", "--lenient", file}, 60.0);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("<hasPID>: the PID gains at /gazebo_ros_control/pid_gains/right_outer_knuckle_joint are "
                               "read from the parameter server when the run starts (not checked here)"));
  // Given the run's YAML, the gains are checked: present, they load; absent, it is an error.
  const std::string dir = (fs::path(::testing::TempDir()) / ("mechsim_lenient_" + std::to_string(getpid()))).string();
  fs::create_directories(dir);
  write_file(dir + "/gains.yaml", "gripper:\n  gazebo_ros_control:\n    pid_gains:\n"
                                  "      right_outer_knuckle_joint: {p: 20.0, i: 0.0, d: 0.1}\n"
                                  "      left_inner_knuckle_joint: {p: 20.0, i: 0.0, d: 0.1}\n"
                                  "      right_inner_knuckle_joint: {p: 20.0, i: 0.0, d: 0.1}\n"
                                  "  joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 50}\n");
  const ProcessResult with = run_process({MECHSIM_EXE, "check", "--lenient", file, "--controllers", dir + "/gains.yaml"}, 60.0);
  EXPECT_EQ(with.exit_code, 0) << with.out << with.err;
  EXPECT_THAT(with.err, Not(HasSubstr("not checked here")));
  write_file(dir + "/no_gains.yaml",
             "gripper:\n  joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 50}\n");
  const ProcessResult without = run_process({MECHSIM_EXE, "check", "--lenient", file, "--controllers", dir + "/no_gains.yaml"}, 60.0);
  EXPECT_EQ(without.exit_code, 1) << without.out << without.err;
  EXPECT_THAT(without.err, HasSubstr("asks for a PID, but the parameter server has no gains at"));
  fs::remove_all(dir);
}

TEST(CheckLenientCli, ACameraOnALinkTheRobotLacksIsLeftOutAsGazeboIgnoresIt) {
  for (const bool lenient : {true, false}) {
    std::vector<std::string> argv = {MECHSIM_EXE, "check", lenient_robot("camera_base.urdf")};
    if (lenient) argv.push_back("--lenient");
    const ProcessResult r = run_process(argv, 60.0);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_THAT(r.err, HasSubstr("sensor 'front_camera' left out: <gazebo reference=\"camera_link\"> names no link or joint of "
                                 "the robot (Gazebo ignores it too)"));
    EXPECT_THAT(r.out, HasSubstr("diff_drive (libgazebo_ros_diff_drive.so)"));
  }
}

TEST(CheckLenientCli, AVendorTransmissionTypeIsLeftOutWhenLenient) {
  const std::string file = lenient_robot("vendor_arm.urdf");
  const ProcessResult r = run_process({MECHSIM_EXE, "check", "--lenient", file}, 60.0);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("transmission 'arm_franka_state' of type 'franka_hw/FrankaStateInterface' left out: mechsim "
                               "does not simulate that type"));
  EXPECT_THAT(r.err, HasSubstr("transmission 'arm_franka_model' of type 'franka_hw/FrankaModelInterface' left out"));
  EXPECT_THAT(r.out, HasSubstr("transmissions:   3"));
  const ProcessResult strict = run_process({MECHSIM_EXE, "check", file}, 60.0);
  EXPECT_EQ(strict.exit_code, 1) << strict.out << strict.err;
  EXPECT_THAT(strict.err, HasSubstr("unknown transmission type 'franka_hw/FrankaStateInterface'"));
}

}  // namespace
}  // namespace mechsim::apps::test
