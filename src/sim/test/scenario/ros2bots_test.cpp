// mechsim's ros2_control test robots (robots/ros2bots) through their shipped scenarios: an arm on
// position interfaces moved by forward_command_controller (its command clamped at the interface's
// max) and by joint_trajectory_controller, its gripper's mimic finger following, a differential
// drive through diff_drive_controller with ROS 2 parameters (and two of them in one world, each
// with its own controller manager and namespace), and a tricycle through tricycle_controller. Every check of every scenario passes; the figures are printed.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

class Ros2Bots : public testing::TestWithParam<const char*> {};

TEST_P(Ros2Bots, MeetsItsChecks) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/ros2bots/scenarios" / (std::string(GetParam()) + ".yaml");
  const ScenarioResult r = run_scenario(load_scenario(file.string()), RunOptions{});
  std::cout << "[ figures  ] " << GetParam() << ": final (" << r.final_x << ", " << r.final_y << ") yaw "
            << r.final_yaw * 180.0 / M_PI << " deg, odometry error " << r.odometry_error << " m\n";
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  EXPECT_TRUE(r.passed);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, Ros2Bots,
                         testing::Values("rrbot_forward_position", "rrbot_trajectory", "rrbot_gripper", "diffbot_drive",
                                         "tricycle_drive", "two_diffbots"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

// The CC8 and the PR2 on ROS 2 (their ros2_control:=true descriptions and ros2_controllers.yaml):
// the rover drive and the arm's trajectory meet the checks their ROS 1 scenarios meet.
class Ros2Robots : public testing::TestWithParam<const char*> {};

TEST_P(Ros2Robots, MeetsItsChecks) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots" / (std::string(GetParam()) + ".yaml");
  const ScenarioResult r = run_scenario(load_scenario(file.string()), RunOptions{});
  std::cout << "[ figures  ] " << GetParam() << ": final (" << r.final_x << ", " << r.final_y << "), odometry error "
            << r.odometry_error << " m\n";
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  ASSERT_TRUE(r.completed) << r.error;
  EXPECT_TRUE(r.passed);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, Ros2Robots, testing::Values("cc8/scenarios/ros2_straight_5m", "pr2/scenarios/ros2_arm_trajectory"),
                         [](const testing::TestParamInfo<const char*>& param) {
                           std::string name = param.param;
                           for (char& c : name) c = (c == '/') ? '_' : c;
                           return name;
                         });

}  // namespace
}  // namespace mechsim::sim
