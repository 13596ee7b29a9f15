// The CC8 rover driving on flat ground through its rover drive controller, from the scenario
// files shipped in robots/cc8/scenarios (the acceptance figures): 5 m straight, a
// 90-degree Ackermann turn, a 180-degree point turn, crab at 45 degrees (to the left as
// shipped, and mirrored to the right).

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Scenario load_shipped(const std::string& name) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8/scenarios" / (name + ".yaml");
  return load_scenario(file.string());
}

ScenarioResult run_shipped(const std::string& name, const Scenario& scenario) {
  const ScenarioResult r = run_scenario(scenario, RunOptions{});
  std::cout << "[ figures  ] " << name << ": distance " << r.distance << " m, final (" << r.final_x << ", " << r.final_y
            << ") yaw " << r.final_yaw * 57.29577951308232 << " deg, odometry error " << r.odometry_error << " m\n";
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  return r;
}

ScenarioResult run_shipped(const std::string& name) { return run_shipped(name, load_shipped(name)); }

class Cc8Drive : public testing::TestWithParam<const char*> {};

TEST_P(Cc8Drive, MeetsItsChecks) {
  const ScenarioResult r = run_shipped(GetParam());
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  EXPECT_TRUE(r.passed);
  for (const RobotMotion& o : r.others)
    std::cout << "[ figures  ]   " << o.name << ": distance " << o.distance << " m, final (" << o.final_x << ", " << o.final_y
              << ") yaw " << o.final_yaw * 57.29577951308232 << " deg, odometry error " << o.odometry_error << " m\n";
}

// The two rovers' report: others.csv holds the second robot's base (its last row where the run
// says it ended), summary.json its motion.
TEST(Cc8TwoRovers, TheReportHasTheSecondRobotsPath) {
  const fs::path out = fs::path(::testing::TempDir()) / ("mechsim_two_rovers_" + std::to_string(::getpid()));
  RunOptions options;
  options.output_dir = out.string();
  options.plots = false;
  const ScenarioResult r = run_scenario(load_shipped("two_rovers"), options);
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_EQ(r.others.size(), 1u);
  std::ifstream csv(out / "others.csv");
  std::string header, line, last;
  std::getline(csv, header);
  EXPECT_EQ(header, "time,cc8_2/x,cc8_2/y,cc8_2/z,cc8_2/yaw");
  int rows = 0;
  while (std::getline(csv, line)) {
    last = line;
    ++rows;
  }
  EXPECT_GE(rows, 600);  // 12 s at 50 Hz
  double t = 0, x = 0, y = 0;
  ASSERT_EQ(std::sscanf(last.c_str(), "%lf,%lf,%lf", &t, &x, &y), 3);
  EXPECT_NEAR(x, r.others[0].final_x, 0.01);
  EXPECT_NEAR(y, r.others[0].final_y, 0.01);
  std::ifstream summary(out / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"others\""), std::string::npos);
  EXPECT_NE(text.find("\"cc8_2\""), std::string::npos);
  std::error_code ec;
  fs::remove_all(out, ec);
}

// The two rovers' scenario: the second robot's checks judge its own motion (a check of its final
// pose at the first one's end point fails), and summary figures come per robot.
TEST(Cc8TwoRovers, ChecksJudgeTheRobotTheyName) {
  Scenario s = load_shipped("two_rovers");
  for (Check& c : s.checks)
    if (c.robot == "cc8_2" && c.kind == Check::Kind::FinalPose) {
      c.x = 3.0;
      c.y = 0.0;
    }
  const ScenarioResult r = run_shipped("two_rovers (second judged at the first's end)", s);
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_EQ(r.others.size(), 1u);
  EXPECT_GT(r.others[0].distance, 2.0);
  EXPECT_FALSE(r.passed);
  int failed = 0;
  for (const CheckOutcome& c : r.checks) failed += !c.passed;
  EXPECT_EQ(failed, 1);
}

INSTANTIATE_TEST_SUITE_P(FlatGround, Cc8Drive,
                         testing::Values("straight_5m", "ackermann_90", "point_turn_180", "crab_45", "two_rovers"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

// The crab acceptance, asserted figure by figure: the direction of travel within 5 deg of
// the command, odometry error under 3 % of the distance, and the heading kept within 3 deg. The
// fixed middle wheels are dragged sideways in crab; without the rover drive's sensing wheels and
// heading hold the odometry error is 7.7 % and the heading drifts 9 deg. Mirrored to the right,
// where the other side trails, the same must hold.
// crab_45_imu: the same with the heading hold on the ZED2 IMU's yaw (crab_heading_source: imu)
// instead of the odometry's; robots/cc8/README.md compares the two.
class Cc8Crab : public testing::TestWithParam<const char*> {};

TEST_P(Cc8Crab, KeepsDirectionOdometryAndHeadingBothWays) {
  for (const double side : {1.0, -1.0}) {
    Scenario s = load_shipped(GetParam());
    for (TimelineEvent& e : s.timeline) e.twist.linear.y *= side;
    for (Check& c : s.checks) {
      if (c.kind == Check::Kind::Direction) c.yaw *= side;
    }
    const ScenarioResult r = run_shipped(std::string(GetParam()) + (side > 0 ? " (left)" : " (mirrored, right)"), s);
    ASSERT_TRUE(r.completed) << r.error;
    ASSERT_TRUE(r.has_odometry);
    const double direction = std::atan2(r.final_y - s.spawn.y, r.final_x - s.spawn.x);
    const double fraction = r.odometry_error / r.distance;
    std::cout << "[ figures  ]   direction " << direction / kDeg << " deg (commanded " << side * 45 << "), odometry error "
              << 100 * fraction << " % of " << r.distance << " m, heading drift " << r.final_yaw / kDeg << " deg\n";
    EXPECT_NEAR(direction, side * 45 * kDeg, 5 * kDeg);
    EXPECT_LT(fraction, 0.03);
    EXPECT_LT(std::abs(r.final_yaw), 3 * kDeg);
    // Two corners unpowered must not stall the crab: 10 s at 0.5 m/s commanded.
    EXPECT_GT(r.distance, 4.0);
    EXPECT_TRUE(r.passed);
  }
}

INSTANTIATE_TEST_SUITE_P(HeadingSource, Cc8Crab, testing::Values("crab_45", "crab_45_imu"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

}  // namespace
}  // namespace mechsim::sim
