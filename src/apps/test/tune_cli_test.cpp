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
using ::testing::AllOf;
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
  ProcessResult tune(const std::string& step, const std::vector<std::string>& more = {}) {
    std::vector<std::string> args{MECHSIM_EXE, "tune", (dir_ / "pendulum.urdf").string(), "--controllers",
                                  (dir_ / "controllers.yaml").string(), "--joint", "hinge", "--step", step, "--evaluations", "4"};
    args.insert(args.end(), more.begin(), more.end());
    return run_process(args, 60.0);
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

// --conditions: every condition's metrics before and after; the verdict covers all of them.
TEST_F(TuneCli, RobustTuningReportsEveryCondition) {
  std::ofstream(dir_ / "conditions.yaml") << "conditions:\n  - payload: {link: arm, mass: 3}\n  - step_scale: 0.2\n";
  const ProcessResult r = tune("-0.3", {"--conditions", (dir_ / "conditions.yaml").string()});
  ASSERT_TRUE(r.started);
  EXPECT_THAT(r.out, HasSubstr("in every condition")) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("condition nominal:"));
  EXPECT_THAT(r.out, HasSubstr("condition payload 3 kg on arm:"));
  EXPECT_THAT(r.out, HasSubstr("condition step x0.2:\n    before (NOT met) step -0.06 rad"));
  std::ofstream(dir_ / "bad.yaml") << "conditions:\n  - payload: {link: arm, mass: 3}\n    stepscale: 2\n";
  const ProcessResult bad = tune("-0.3", {"--conditions", (dir_ / "bad.yaml").string()});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_THAT(bad.err, AllOf(HasSubstr("bad.yaml:3"), HasSubstr("unknown key 'stepscale'"))) << bad.out << bad.err;
}

}  // namespace
}  // namespace mechsim::apps::test
