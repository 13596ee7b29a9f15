// mechsim's test robots (robots/testbots) through their shipped scenarios: a differential drive
// and a four-wheel skid steer driven by diff_drive_controller and by Gazebo's drive plugins, a
// planar-move base, and a gripper whose second finger follows the first through the mimic joint
// plugin (the acceptance figures of issues 15 and 25: 1 m within 1 %, 90 deg within 1 deg,
// odometry within 1 %, mimic tracking within 1e-3 rad), and a turntable whose one joint has three
// transmissions, stepped through gazebo_ros_control's pid_gains and through the servo. Every check of every scenario passes, and
// the figures are printed.

#include <gtest/gtest.h>

#include <algorithm>
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

// A second planar-move robot in the same world (others:) moves by its own plugin's twists: half
// the first one's speed forward, twice its speed sideways, 2 m to its left; each ends where its
// own commands take it and its odometry (the base's world pose) follows it.
TEST(Testbots, ASecondPlanarMoveRobotDrivesByItsOwnPlugin) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/testbots/scenarios/planarbot_straight_1m.yaml";
  Scenario s = load_scenario(file.string());
  OtherRobotConfig second;
  second.name = "p2";
  second.description = s.description;
  second.packages = s.packages;
  second.spawn = s.spawn;
  second.spawn.y = 2.0;
  s.others.push_back(second);
  const std::vector<TimelineEvent> first = s.timeline;
  for (TimelineEvent e : first) {
    e.robot = "p2";
    e.twist.linear.x *= 0.5;
    e.twist.linear.y *= 2.0;
    s.timeline.push_back(e);
  }
  std::stable_sort(s.timeline.begin(), s.timeline.end(), [](const TimelineEvent& a, const TimelineEvent& b) { return a.at < b.at; });
  const ScenarioResult r = run_scenario(s, RunOptions{});
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_EQ(r.others.size(), 1u);
  const RobotMotion& p2 = r.others[0];
  std::cout << "[ figures  ] first (" << r.final_x << ", " << r.final_y << "), second (" << p2.final_x << ", "
            << p2.final_y << "), odometry error " << p2.odometry_error << " m\n";
  EXPECT_NEAR(r.final_x, 1.0, 0.011);
  EXPECT_NEAR(r.final_y, 0.5, 0.011);
  EXPECT_NEAR(p2.final_x, 0.5, 0.011);
  EXPECT_NEAR(p2.final_y, 3.0, 0.011);
  ASSERT_TRUE(p2.has_odometry);
  EXPECT_LT(p2.odometry_error, 0.01 * p2.distance);
}

}  // namespace
}  // namespace mechsim::sim
