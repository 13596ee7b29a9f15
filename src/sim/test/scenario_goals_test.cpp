// Trajectory goals, joint checks and the new scenario keys through the runner, on a pendulum
// (1 kg at 0.5 m on an effort-driven hinge) under effort_controllers/JointTrajectoryController:
// the goal's tracking error and result reach the checks and the summary; bad events and checks
// are clear errors naming the file and line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/test/pendulum_urdf.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

// The test's name as one folder name: a parameterized test is "Name/3", which made a folder
// "Name" holding "3", and only "3" was removed.
std::string test_folder_name() {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

const std::string kPendulum = mechsim::test::pendulum_urdf(1);

constexpr const char* kControllers = R"(p:
  arm:
    type: effort_controllers/JointTrajectoryController
    joints: [hinge]
    gains: {hinge: {p: 400.0, d: 40.0, i: 0.0}}
  push: {type: effort_controllers/JointEffortController, joint: hinge}
)";

// Out to 0.5 rad in 1 s and back in another, cubic (at rest at both ends).
constexpr const char* kGoal = R"(
timeline:
  - at: 0.1
    controller: arm
    trajectory:
      points:
        - {time: 1.0, positions: [0.5], velocities: [0.0]}
        - {time: 2.0, positions: [0.0], velocities: [0.0]}
      goal_time_tolerance: 0.5
)";

class ScenarioGoalsRun : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_scenario_goals_" + std::to_string(::getpid()) + "_" +
                                        test_folder_name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "pendulum.urdf") << kPendulum;
    std::ofstream(dir_ / "controllers.yaml") << kControllers;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& body) {
    const fs::path file = dir_ / "s.yaml";
    std::ofstream(file) << "robot: {description: pendulum.urdf}\ncontrollers: {file: controllers.yaml, namespace: p, start: [arm]}\n"
                        << "duration: 3.0\n" << body;
    return file.string();
  }
  ScenarioResult run(const std::string& body, const std::string& output = "") {
    RunOptions options;
    options.output_dir = output;
    options.plots = false;
    return run_scenario(load_scenario(write(body)), options);
  }
  fs::path dir_;
};

TEST_F(ScenarioGoalsRun, ATrajectoryGoalIsTrackedAndItsResultChecked) {
  const ScenarioResult r = run(std::string(kGoal) + R"(checks:
  - {trajectory: {controller: arm, max_rms_error: 0.05, max_error: 0.1, result: SUCCESSFUL}}
  - {trajectory: {controller: arm, goal: 1, max_rms_error: 0.000001}}
  - {joint: {name: hinge, at: 1.1, position: 0.5, within: 0.05}}
  - {joint: {name: hinge, position: 0.0, within: 0.02}}
)", (dir_ / "out").string());
  ASSERT_TRUE(r.completed) << r.error;
  ASSERT_EQ(r.trajectory_goals.size(), 1u);
  const TrajectoryGoalOutcome& g = r.trajectory_goals[0];
  EXPECT_TRUE(g.accepted);
  EXPECT_TRUE(g.finished);
  EXPECT_EQ(g.status, "succeeded");
  EXPECT_EQ(g.result.error_code, control::TrajectoryResultCode::Successful);
  ASSERT_EQ(g.joints.size(), 1u);
  EXPECT_EQ(g.joints[0], "hinge");
  // 50 Hz state over the 2 s goal (and what the goal time allows after it).
  EXPECT_GE(g.samples, 95u);
  EXPECT_LE(g.samples, 130u);
  EXPECT_GT(g.rms[0], 1e-5);  // gravity pulls the bob off the desired path: a real error
  EXPECT_LT(g.rms[0], 0.05);
  EXPECT_GE(g.max[0], g.rms[0]);
  EXPECT_NEAR(g.finished_at, 2.1, 0.2);
  ASSERT_EQ(r.checks.size(), 4u);
  EXPECT_TRUE(r.checks[0].passed) << r.checks[0].detail;
  EXPECT_FALSE(r.checks[1].passed) << r.checks[1].detail;  // an impossible bound fails
  EXPECT_NE(r.checks[1].detail.find("RMS error"), std::string::npos) << r.checks[1].detail;
  EXPECT_TRUE(r.checks[2].passed) << r.checks[2].detail;
  EXPECT_TRUE(r.checks[3].passed) << r.checks[3].detail;
  EXPECT_FALSE(r.passed);

  // The summary carries the goal, and trajectory.csv the desired and actual positions.
  std::ifstream summary(dir_ / "out" / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  ASSERT_EQ(j["trajectory_goals"].size(), 1u);
  EXPECT_EQ(j["trajectory_goals"][0]["result"], "SUCCESSFUL");
  EXPECT_NEAR(j["trajectory_goals"][0]["joints"][0]["rms_error"].get<double>(), g.rms[0], 1e-12);
  std::ifstream csv(dir_ / "out" / "trajectory.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "time,arm/hinge/desired,arm/hinge/actual");
  std::size_t rows = 0;
  double max_desired = 0.0;
  for (std::string line; std::getline(csv, line); ++rows) {
    double t = 0, desired = 0, actual = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &desired, &actual), 3) << line;
    max_desired = std::max(max_desired, desired);
  }
  EXPECT_GE(rows, 150u);  // 50 Hz over 3 s
  EXPECT_NEAR(max_desired, 0.5, 0.01);
}

TEST_F(ScenarioGoalsRun, APathToleranceViolationIsTheResultTheCheckSees) {
  // Out to 1.5 rad in 0.1 s under a 0.01 rad path tolerance: it cannot follow.
  const ScenarioResult r = run(R"(
timeline:
  - at: 0.1
    controller: arm
    trajectory:
      joints: [hinge]
      points: [{time: 0.1, positions: [1.5]}]
      path_tolerance: {all: {position: 0.01}}
checks:
  - {trajectory: {controller: arm, result: PATH_TOLERANCE_VIOLATED}}
  - {trajectory: {controller: arm, result: SUCCESSFUL}}
)");
  ASSERT_EQ(r.trajectory_goals.size(), 1u);
  EXPECT_EQ(r.trajectory_goals[0].status, "aborted");
  EXPECT_EQ(r.trajectory_goals[0].result.error_code, control::TrajectoryResultCode::PathToleranceViolated);
  ASSERT_EQ(r.checks.size(), 2u);
  EXPECT_TRUE(r.checks[0].passed) << r.checks[0].detail;
  EXPECT_FALSE(r.checks[1].passed) << r.checks[1].detail;
  EXPECT_NE(r.checks[1].detail.find("PATH_TOLERANCE_VIOLATED"), std::string::npos) << r.checks[1].detail;
}

TEST_F(ScenarioGoalsRun, AGoalStillRunningAtTheEndHasNoResult) {
  const ScenarioResult r = run(R"(
timeline:
  - {at: 0.1, controller: arm, trajectory: {points: [{time: 10.0, positions: [0.3]}]}}
checks:
  - {trajectory: {controller: arm, result: SUCCESSFUL}}
)");
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_FALSE(r.checks[0].passed);
  EXPECT_NE(r.checks[0].detail.find("still active"), std::string::npos) << r.checks[0].detail;
  EXPECT_FALSE(r.trajectory_goals[0].finished);
}

struct BindCase {
  const char* name;
  const char* body;
  const char* expected;  // substring of the message
};

class ScenarioGoalsBind : public ScenarioGoalsRun, public testing::WithParamInterface<BindCase> {};

// Found when the run binds the timeline to the loaded controllers, before any tick.
TEST_P(ScenarioGoalsBind, IsAClearErrorBeforeTheRun) {
  const BindCase& c = GetParam();
  try {
    run(c.body);
    FAIL() << "accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ScenarioGoalsBind,
    testing::Values(
        BindCase{"unknown_controller", "timeline:\n  - {at: 0, controller: nope, trajectory: {points: [{time: 1, positions: [0]}]}}\n",
                 "s.yaml:5: timeline event at t=0 s, controller 'nope': no such controller is loaded"},
        BindCase{"wrong_count", "timeline:\n  - {at: 0, controller: arm, trajectory: {points: [{time: 1, positions: [0, 1]}]}}\n",
                 "points[0]/positions has 2 values for 1 joints"},
        BindCase{"unknown_joint", "timeline:\n  - {at: 0, controller: arm, trajectory: {joints: [elbow], points: [{time: 1, positions: [0]}]}}\n",
                 "trajectory/joints: the controller has no joint 'elbow'"},
        BindCase{"unknown_tolerance_joint",
                 "timeline:\n  - {at: 0, controller: arm, trajectory: {points: [{time: 1, positions: [0]}], goal_tolerance: {elbow: {position: 1}}}}\n",
                 "goal_tolerance: the controller has no joint 'elbow'"},
        BindCase{"gripper_to_arm", "timeline:\n  - {at: 0, controller: arm, gripper: {position: 0.05}}\n",
                 "is not a gripper controller"},
        BindCase{"check_without_goal", "checks:\n  - {trajectory: {controller: arm, result: SUCCESSFUL}}\n",
                 "the timeline sends no trajectory goal to controller 'arm'"},
        BindCase{"check_goal_out_of_range",
                 "timeline:\n  - {at: 0, controller: arm, trajectory: {points: [{time: 1, positions: [0]}]}}\n"
                 "checks:\n  - {trajectory: {controller: arm, goal: 2, result: SUCCESSFUL}}\n",
                 "goal 2 of controller 'arm', but the timeline sends it 1"},
        BindCase{"unknown_check_joint", "checks:\n  - {joint: {name: knee, position: 0, within: 1}}\n",
                 "the robot's mechanism has no joint 'knee'"},
        BindCase{"unknown_spawn_joint", "spawn: {joints: {knee: 0.3}}\n", "spawn/joints/knee: the robot's physics has no joint 'knee'"}),
    [](const testing::TestParamInfo<BindCase>& param) { return std::string(param.param.name); });

TEST_F(ScenarioGoalsRun, InitialJointPositionsAreWhereTheRunStarts) {
  // The trajectory controller holds what it measures when it starts: the spawn position.
  const ScenarioResult r = run("spawn: {joints: {hinge: 0.4}}\nchecks:\n  - {joint: {name: hinge, at: 0.5, position: 0.4, within: 0.02}}\n");
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_TRUE(r.checks[0].passed) << r.checks[0].detail;
  const ScenarioResult r0 = run("checks:\n  - {joint: {name: hinge, at: 0.5, position: 0.4, within: 0.02}}\n");
  EXPECT_FALSE(r0.checks[0].passed) << r0.checks[0].detail;  // without it the bob hangs at 0
}

TEST_F(ScenarioGoalsRun, AJointCheckAfterTheEndOfAShortenedRunFails) {
  Scenario s = load_scenario(write("checks:\n  - {joint: {name: hinge, at: 2.0, position: 0.0, within: 1.0}}\n"));
  s.duration = 0.5;  // as `mechsim run --duration 0.5` does
  const ScenarioResult r = run_scenario(s, RunOptions{});
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_FALSE(r.checks[0].passed);
  EXPECT_NE(r.checks[0].detail.find("not sampled, the run ended at t=0.500 s"), std::string::npos) << r.checks[0].detail;
}

}  // namespace
}  // namespace mechsim::sim
