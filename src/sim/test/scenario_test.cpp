// Scenario files: what is read, and bad input named by file and parameter path.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "sim/scenario.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

class ScenarioFile : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_scenario_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "robot.urdf") << "<robot name='r'><link name='a'/></robot>\n";
    std::ofstream(dir_ / "controllers.yaml") << "r:\n  c: {type: joint_state_controller/JointStateController, publish_rate: 50}\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& body) {
    const fs::path file = dir_ / "s.yaml";
    std::ofstream(file) << "robot: {description: robot.urdf}\ncontrollers: {file: controllers.yaml, namespace: r, start: [c]}\n" << body;
    return file.string();
  }
  fs::path dir_;
};

TEST_F(ScenarioFile, ReadsEverythingWithPathsRelativeToTheFile) {
  const Scenario s = load_scenario(write(R"(name: demo
duration: 12.5
period: 0.002
spawn: {x: 1, y: -2, z: 0.1, yaw: 1.5}
world: {name: mars_yard_2024, seed: 7}
timeline:
  - {at: 2.0, controller: c, twist: {vx: 0.5, wz: 0.1}}
  - {at: 1.0, controller: c, command: 0.3}
  - {at: 3.0, controller: c, route: {waypoints: [[1, 2], [3, 4]], speed: 0.7}}
checks:
  - {reach: {x: 1, y: 2, within: 0.5, by: 10}}
  - {final_heading: {yaw_deg: 90, within_deg: 5}}
  - {direction: {deg: 45, within_deg: 3}}
)"));
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.description, (dir_ / "robot.urdf").lexically_normal().string());
  EXPECT_EQ(s.controllers_file, (dir_ / "controllers.yaml").lexically_normal().string());
  EXPECT_EQ(s.controllers_namespace, "r");
  EXPECT_DOUBLE_EQ(s.duration, 12.5);
  EXPECT_DOUBLE_EQ(s.period, 0.002);
  EXPECT_DOUBLE_EQ(s.spawn.y, -2.0);
  EXPECT_DOUBLE_EQ(s.spawn.yaw, 1.5);
  EXPECT_EQ(s.world.name, "mars_yard_2024");
  EXPECT_EQ(s.world.seed, 7u);
  ASSERT_EQ(s.timeline.size(), 3u);
  EXPECT_EQ(s.timeline[0].kind, TimelineEvent::Kind::Scalar);  // sorted by time
  EXPECT_EQ(s.timeline[1].kind, TimelineEvent::Kind::Twist);
  EXPECT_DOUBLE_EQ(s.timeline[1].twist.linear.x, 0.5);
  EXPECT_DOUBLE_EQ(s.timeline[1].twist.angular.z, 0.1);
  EXPECT_EQ(s.timeline[2].kind, TimelineEvent::Kind::Route);
  ASSERT_EQ(s.timeline[2].route.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(s.timeline[2].route.waypoints[1][0], 3.0);
  EXPECT_DOUBLE_EQ(s.timeline[2].route.speed, 0.7);
  ASSERT_EQ(s.checks.size(), 3u);
  EXPECT_EQ(s.checks[0].kind, Check::Kind::Reach);
  EXPECT_NEAR(s.checks[1].yaw, M_PI / 2, 1e-12);
  EXPECT_EQ(s.checks[2].kind, Check::Kind::Direction);
  EXPECT_EQ(s.integrator, physics::Integrator::Implicit);  // the default when absent
}

TEST_F(ScenarioFile, ReadsTheIntegrator) {
  EXPECT_EQ(load_scenario(write("duration: 1\nintegrator: euler\n")).integrator, physics::Integrator::Euler);
  EXPECT_EQ(load_scenario(write("duration: 1\nintegrator: rk4\n")).integrator, physics::Integrator::Rk4);
  EXPECT_EQ(load_scenario(write("duration: 1\nintegrator: implicit\n")).integrator, physics::Integrator::Implicit);
}

struct BadCase {
  const char* name;
  const char* body;
  const char* expected;  // substring of the message
};

class ScenarioBadInput : public ScenarioFile, public testing::WithParamInterface<BadCase> {};

TEST_P(ScenarioBadInput, IsAClearError) {
  const BadCase& c = GetParam();
  try {
    load_scenario(write(c.body));
    FAIL() << "accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ScenarioBadInput,
    testing::Values(BadCase{"missing_duration", "name: x\n", "/duration"},
                    BadCase{"negative_duration", "duration: -1\n", "/duration"},
                    BadCase{"bad_period", "duration: 1\nperiod: 0\n", "/period"},
                    BadCase{"bad_integrator", "duration: 1\nintegrator: verlet\n", "/integrator: expected 'implicit', 'euler' or 'rk4', got 'verlet'"},
                    BadCase{"two_commands", "duration: 1\ntimeline:\n  - {at: 0, controller: c, command: 1, twist: {vx: 1}}\n",
                            "exactly one of"},
                    BadCase{"unknown_check", "duration: 1\nchecks:\n  - {fly: {x: 1}}\n", "unknown check 'fly'"},
                    BadCase{"bad_waypoint", "duration: 1\ntimeline:\n  - {at: 0, controller: c, route: {waypoints: [[1, 2, 3]]}}\n",
                            "[x, y]"},
                    BadCase{"negative_time", "duration: 1\ntimeline:\n  - {at: -1, controller: c, command: 1}\n", "/timeline"},
                    BadCase{"malformed", "duration: [1\n", "s.yaml"}),
    [](const testing::TestParamInfo<BadCase>& param) { return std::string(param.param.name); });

TEST(ScenarioFileMissing, NamesTheFile) {
  try {
    load_scenario("/nonexistent/dir/s.yaml");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/s.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace mechsim::sim
