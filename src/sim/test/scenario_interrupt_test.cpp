// A run that is stopped or cannot write its report: the report says so, never reads complete.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class ScenarioInterrupt : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_scenario_interrupt_" + std::to_string(::getpid()) + "_" +
                                        testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "robot.urdf")
        << "<robot name='r'><link name='a'><inertial><mass value='1'/>"
           "<inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>"
           "<collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link></robot>\n";
    std::ofstream(dir_ / "controllers.yaml") << "r:\n  c: {type: joint_state_controller/JointStateController, publish_rate: 50}\n";
    std::ofstream(dir_ / "s.yaml") << "robot: {description: robot.urdf}\n"
                                      "controllers: {file: controllers.yaml, namespace: r, start: [c]}\n"
                                      "duration: 2.0\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  nlohmann::json summary(const fs::path& report) const {
    std::ifstream in(report / "summary.json");
    return nlohmann::json::parse(in);  // throws on a half-written file
  }
  fs::path dir_;
};

TEST_F(ScenarioInterrupt, SummarySaysRunningWhileTheRunGoes) {
  const Scenario s = load_scenario((dir_ / "s.yaml").string());
  RunOptions options;
  options.output_dir = (dir_ / "report").string();
  options.plots = false;
  int seen = 0;
  options.progress = [&](const RunProgress&) {
    const nlohmann::json j = summary(dir_ / "report");
    EXPECT_EQ(j["status"], "running");
    EXPECT_EQ(j["completed"], false);
    ++seen;
  };
  const ScenarioResult r = run_scenario(s, options);
  EXPECT_GT(seen, 0);
  ASSERT_TRUE(r.completed) << r.error;
  const nlohmann::json done = summary(dir_ / "report");
  EXPECT_EQ(done["completed"], true);
  EXPECT_FALSE(done.contains("status"));
  EXPECT_FALSE(fs::exists(dir_ / "report" / "summary.json.partial"));
}

TEST_F(ScenarioInterrupt, InterruptedRunWritesAReportMarkedIncomplete) {
  const Scenario s = load_scenario((dir_ / "s.yaml").string());
  std::atomic<int> interrupt{0};
  RunOptions options;
  options.output_dir = (dir_ / "report").string();
  options.plots = false;
  options.interrupt = &interrupt;
  options.progress = [&](const RunProgress& p) {
    if (p.time >= 0.9) interrupt.store(SIGINT);
  };
  const ScenarioResult r = run_scenario(s, options);
  EXPECT_FALSE(r.completed);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.interrupted_by, SIGINT);
  EXPECT_GT(r.sim_time, 0.9);
  EXPECT_LT(r.sim_time, 1.5);
  const nlohmann::json j = summary(dir_ / "report");
  EXPECT_EQ(j["completed"], false);
  EXPECT_EQ(j["interrupted_by_signal"], SIGINT);
  EXPECT_THAT(j["error"].get<std::string>(), HasSubstr("interrupted by signal 2"));
  EXPECT_TRUE(fs::exists(dir_ / "report" / "joints.csv"));
}

TEST_F(ScenarioInterrupt, UnwritableReportFolderIsAnErrorBeforeTheRun) {
  const Scenario s = load_scenario((dir_ / "s.yaml").string());
  RunOptions options;
  options.output_dir = (dir_ / "robot.urdf" / "report").string();  // under a file
  options.progress = [](const RunProgress&) { ADD_FAILURE() << "the run started"; };
  try {
    run_scenario(s, options);
    FAIL() << "accepted";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot create the report folder '" + options.output_dir + "'"));
  }
}

TEST_F(ScenarioInterrupt, AStaleCompleteSummaryIsReplacedAtTheStart) {
  fs::create_directories(dir_ / "report");
  std::ofstream(dir_ / "report" / "summary.json") << R"({"completed": true, "passed": true})";
  const Scenario s = load_scenario((dir_ / "s.yaml").string());
  RunOptions options;
  options.output_dir = (dir_ / "report").string();
  options.plots = false;
  bool checked = false;
  options.progress = [&](const RunProgress&) {
    if (!checked) {
      EXPECT_EQ(summary(dir_ / "report")["completed"], false);
    }
    checked = true;
  };
  run_scenario(s, options);
  EXPECT_TRUE(checked);
}

}  // namespace
}  // namespace mechsim::sim
