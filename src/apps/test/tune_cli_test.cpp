// `mechsim tune` run as a user would on a pendulum resting at its upper limit: a step into the
// limit is taken the other way and the output says so; a step that fits neither way is an error
// naming the joint, its limits and the step.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_process.hpp"
#include "../../sim/test/tuning_pendulum.hpp"  // the cli tests have no include root

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kUrdf = sim::test::kTuningPendulumUrdf;  // rests at its upper limit
constexpr const char* kControllers =
    "pendulum:\n  hinge_position_controller:\n    type: effort_controllers/JointPositionController\n"
    "    joint: hinge\n    pid: {p: 60.0, i: 0.0, d: 4.0}\n";

class TuneCli : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_tune_cli_" + std::to_string(::getpid()) + "_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "pendulum.urdf") << kUrdf;
    std::ofstream(dir_ / "controllers.yaml") << kControllers;
  }
  void TearDown() override { fs::remove_all(dir_); }
  ProcessResult tune(const std::string& step) {
    return run_process({MECHSIM_EXE, "tune", (dir_ / "pendulum.urdf").string(), "--controllers", (dir_ / "controllers.yaml").string(),
                        "--joint", "hinge", "--step", step, "--evaluations", "4"},
                       60.0);
  }
  fs::path dir_;
};

TEST_F(TuneCli, AStepIntoTheLimitIsReversedAndSaid) {
  const ProcessResult r = tune("0.3");
  ASSERT_TRUE(r.started);
  ASSERT_FALSE(r.timed_out);
  EXPECT_THAT(r.out, HasSubstr("would leave the limits [-1, 0]; stepping -0.3 rad instead")) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("step -0.3 rad: 95% at 0."));  // reached, not "never"
}

TEST_F(TuneCli, AStepInsideTheLimitsIsNotReported) {
  const ProcessResult r = tune("-0.3");
  ASSERT_TRUE(r.started);
  EXPECT_THAT(r.out, Not(HasSubstr("instead"))) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("step -0.3 rad"));
}

TEST_F(TuneCli, AStepThatFitsNeitherWayIsAnErrorNamingJointLimitsAndStep) {
  const ProcessResult r = tune("1.5");
  ASSERT_TRUE(r.started);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("joint 'hinge'")) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("limits [-1, 0]"));
  EXPECT_THAT(r.err, HasSubstr("step of 1.5"));
}

}  // namespace
}  // namespace mechsim::apps::test
