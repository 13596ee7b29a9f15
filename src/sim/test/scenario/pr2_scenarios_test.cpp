// The PR2 scenario files shipped in robots/pr2/scenarios, run through the scenario runner as
// `mechsim run` runs them: each file's own checks decide (the acceptance figures of the arm
// trajectory, the gripper, the base turn and the 1 m forward run; the latter failed its 3 % check
// until the physics wheel-contact fix e6fe16f). The files run mechsim's own PR2
// (robots/pr2/urdf/pr2.urdf.xacro); each is run again on the real pr2_description (the reference
// expansion in ../shared, skipped when absent).
// Simulated time: 2 x (8.6 + 3.5 + 5.6 + 6.3) + 8.6 s.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/test/scenario/pr2_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

enum class Robot { Own, Reference };

ScenarioResult run_shipped(const std::string& name, const std::string& output_dir = "", Robot robot = Robot::Own) {
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2/scenarios" / (name + ".yaml");
  Scenario scenario = load_scenario(file.string());
  if (robot == Robot::Reference) {  // the real pr2_description, as make_pr2_simulation loads it
    const fs::path shared = MECHSIM_SHARED_DIR;
    scenario.description = (shared / "robots/reference/pr2.urdf").string();
    scenario.packages = {{"pr2_description", (shared / "robots/pr2_description").string()}};
    scenario.lenient = true;  // two sensor mounts break the inertia triangle inequality
  }
  scenario.integrator = pr2_test_integrator();  // MECHSIM_PR2_INTEGRATOR, as the other PR2 tests
  RunOptions options;
  options.output_dir = output_dir;
  options.plots = false;  // gnuplot is the report's business, not this test's
  const ScenarioResult r = run_scenario(scenario, options);
  std::cout << "[ figures  ] " << name << ": distance " << r.distance << " m, final (" << r.final_x << ", " << r.final_y
            << ") yaw " << r.final_yaw * 57.29577951308232 << " deg, real-time factor " << r.real_time_factor << "\n";
  for (const TrajectoryGoalOutcome& g : r.trajectory_goals) {
    std::cout << "[ figures  ]   " << g.controller << " goal " << g.index << ": " << g.status << ", "
              << control::result_code_name(g.result.error_code) << ", " << g.samples << " samples, RMS per joint (rad):";
    for (std::size_t j = 0; j < g.joints.size(); ++j) std::cout << " " << g.joints[j] << " " << g.rms[j];
    std::cout << "\n";
  }
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  return r;
}

class Pr2ShippedScenario : public testing::TestWithParam<const char*> {};

TEST_P(Pr2ShippedScenario, MeetsItsChecks) {
  const ScenarioResult r = run_shipped(GetParam());
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  for (const CheckOutcome& c : r.checks) EXPECT_TRUE(c.passed) << c.detail;
  EXPECT_TRUE(r.passed);
}

TEST_P(Pr2ShippedScenario, MeetsItsChecksOnTheRealPr2Description) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  const ScenarioResult r = run_shipped(GetParam(), "", Robot::Reference);
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  for (const CheckOutcome& c : r.checks) EXPECT_TRUE(c.passed) << c.detail;
  EXPECT_TRUE(r.passed);
}

INSTANTIATE_TEST_SUITE_P(Shipped, Pr2ShippedScenario,
                         testing::Values("arm_trajectory", "gripper_open_close", "base_turn_90", "base_forward_1m"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

// The arm scenario meets its checks (RMS < 0.01 rad per joint, SUCCESSFUL), and its report
// carries them: summary.json both goals of the timeline with result and per-joint RMS,
// trajectory.csv the desired and actual positions of the 7 joints.
TEST(Pr2ShippedScenarioArm, MeetsItsChecksAndReportsTheGoals) {
  // One folder per process: CTest runs tests in parallel, and other build folders may run this one.
  const fs::path out = fs::temp_directory_path() / ("mechsim_pr2_scenarios_" + std::to_string(::getpid()));
  fs::remove_all(out);
  const ScenarioResult r = run_shipped("arm_trajectory", out.string());
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_FALSE(r.checks.empty());
  for (const CheckOutcome& c : r.checks) EXPECT_TRUE(c.passed) << c.detail;
  EXPECT_TRUE(r.passed);
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["trajectory_goals"].size(), 2u);
  const nlohmann::json& g = j["trajectory_goals"][1];
  EXPECT_EQ(g["controller"], "r_arm_controller");
  EXPECT_EQ(g["goal"], 2);
  ASSERT_EQ(g["joints"].size(), 7u);
  for (const auto& joint : g["joints"]) EXPECT_LT(joint["rms_error"].get<double>(), 0.01) << joint["joint"];
  EXPECT_GT(g["samples"].get<int>(), 200);  // 50 Hz over the 5 s goal
  std::ifstream csv(out / "trajectory.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find("r_arm_controller/r_wrist_roll_joint/desired,r_arm_controller/r_wrist_roll_joint/actual"), std::string::npos)
      << header;
  fs::remove_all(out);
}

}  // namespace
}  // namespace mechsim::sim
