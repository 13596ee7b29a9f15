// The CC8 rover driving on flat ground through its rover drive controller, from the scenario
// files shipped in robots/cc8/scenarios (the acceptance figures): 5 m straight, a
// 90-degree Ackermann turn, a 180-degree point turn, crab at 45 degrees.

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

ScenarioResult run_shipped(const std::string& name) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8/scenarios" / (name + ".yaml");
  const Scenario scenario = load_scenario(file.string());
  const ScenarioResult r = run_scenario(scenario, RunOptions{});
  std::cout << "[ figures  ] " << name << ": distance " << r.distance << " m, final (" << r.final_x << ", " << r.final_y
            << ") yaw " << r.final_yaw * 57.29577951308232 << " deg, odometry error " << r.odometry_error << " m\n";
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  return r;
}

class Cc8Drive : public testing::TestWithParam<const char*> {};

TEST_P(Cc8Drive, MeetsItsChecks) {
  const ScenarioResult r = run_shipped(GetParam());
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  EXPECT_TRUE(r.passed);
}

INSTANTIATE_TEST_SUITE_P(FlatGround, Cc8Drive,
                         testing::Values("straight_5m", "ackermann_90", "point_turn_180", "crab_45"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

}  // namespace
}  // namespace mechsim::sim
