// mechsim's test robots (robots/testbots) through their shipped scenarios: a differential drive
// and a four-wheel skid steer driven by diff_drive_controller and by Gazebo's drive plugins, a
// planar-move base, and a gripper whose second finger follows the first through the mimic joint
// plugin (the acceptance figures of issues 15 and 25: 1 m within 1 %, 90 deg within 1 deg,
// odometry within 1 %, mimic tracking within 1e-3 rad), and a turntable whose one joint has three
// transmissions, stepped through gazebo_ros_control's pid_gains and through the servo. Every check of every scenario passes, and
// the figures are printed.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

class Testbots : public testing::TestWithParam<const char*> {};

TEST_P(Testbots, MeetsItsChecks) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/testbots/scenarios" / (std::string(GetParam()) + ".yaml");
  const ScenarioResult r = run_scenario(load_scenario(file.string()), RunOptions{});
  std::cout << "[ figures  ] " << GetParam() << ": final (" << r.final_x << ", " << r.final_y << ") yaw "
            << r.final_yaw * 180.0 / M_PI << " deg, odometry error " << r.odometry_error << " m, yaw "
            << r.odometry_yaw_error * 180.0 / M_PI << " deg\n";
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  EXPECT_TRUE(r.passed);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, Testbots,
                         testing::Values("diffbot_straight_1m", "diffbot_turn_90", "diffbot_plugin_straight_1m",
                                         "diffbot_plugin_turn_90", "skidbot_straight_1m", "skidbot_turn_90",
                                         "skidbot_plugin_straight_1m", "skidbot_plugin_turn_90", "planarbot_straight_1m",
                                         "planarbot_turn_90", "gripper_mimic_close", "gripper_mimic_pid_close",
                                         "gripper_action_close", "gripper_position_action_close", "diffbot_plugin_square",
                                         "turntable_pid_step", "turntable_servo_step"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

}  // namespace
}  // namespace mechsim::sim
