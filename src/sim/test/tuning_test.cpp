// `mechsim tune`'s step planning (sim/tuning.hpp): a position step that would leave the joint's
// range (soft limits of its safety controller when it has one) goes the other way, and one that
// leaves it both ways is refused with the joint, its range and the step named; tune_joint applies
// the plan on a small pendulum whose upper limit is where it rests.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "sim/tuning.hpp"
#include "sim/test/tuning_pendulum.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

description::Joint revolute(double lower, double upper) {
  description::Joint j;
  j.name = "elbow";
  j.type = description::JointType::Revolute;
  j.limits = description::JointLimits{lower, upper, 30.0, 3.0};
  return j;
}

TEST(TunePlan, AStepInsideTheLimitsIsKept) {
  const auto plan = plan_position_step(revolute(-1.0, 1.0), 0.0, 0.3);
  EXPECT_DOUBLE_EQ(plan.step, 0.3);
  EXPECT_FALSE(plan.reversed);
  EXPECT_TRUE(plan.limited);
  EXPECT_FALSE(plan.soft);
  EXPECT_DOUBLE_EQ(plan.lower, -1.0);
  EXPECT_DOUBLE_EQ(plan.upper, 1.0);
}

TEST(TunePlan, AStepIntoTheUpperLimitIsReversed) {
  // The PR2 elbow: limits -2.3213..0, resting at its upper limit.
  const auto plan = plan_position_step(revolute(-2.3213, 0.0), 0.0, 0.3);
  EXPECT_DOUBLE_EQ(plan.step, -0.3);
  EXPECT_TRUE(plan.reversed);
}

TEST(TunePlan, ANegativeStepIntoTheLowerLimitIsReversed) {
  const auto plan = plan_position_step(revolute(-0.2, 1.0), 0.0, -0.3);
  EXPECT_DOUBLE_EQ(plan.step, 0.3);
  EXPECT_TRUE(plan.reversed);
}

TEST(TunePlan, TheSafetyControllersSoftLimitsAreTheRangeWhenPresent) {
  description::Joint j = revolute(-2.3213, 0.0);
  j.safety = description::SafetyController{-2.1213, -0.15, 100.0, 3.0};
  // -0.2 + 0.1 = -0.1 is inside the hard limits but beyond the soft upper limit -0.15.
  const auto plan = plan_position_step(j, -0.2, 0.1);
  EXPECT_TRUE(plan.soft);
  EXPECT_DOUBLE_EQ(plan.upper, -0.15);
  EXPECT_DOUBLE_EQ(plan.step, -0.1);
  EXPECT_TRUE(plan.reversed);
}

TEST(TunePlan, AStepOutOfRangeBothWaysIsRefusedNamingJointLimitsAndStep) {
  description::Joint j = revolute(0.0, 0.33);
  j.name = "torso_lift_joint";
  j.type = description::JointType::Prismatic;
  j.safety = description::SafetyController{0.0115, 0.325, 100.0, 2e6};
  try {
    plan_position_step(j, 0.15, 0.2);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("torso_lift_joint"), HasSubstr("soft limits [0.0115, 0.325]"),
                                HasSubstr("step of 0.2"), HasSubstr("from 0.15")));
  }
}

TEST(TunePlan, ContinuousJointsTakeTheStepAsGiven) {
  description::Joint j = revolute(0.0, 0.0);
  j.type = description::JointType::Continuous;
  const auto plan = plan_position_step(j, 0.0, 5.0);
  EXPECT_DOUBLE_EQ(plan.step, 5.0);
  EXPECT_FALSE(plan.reversed);
  EXPECT_FALSE(plan.limited);
}

constexpr const char* kPendulum = sim::test::kTuningPendulumUrdf;  // rests at its upper limit

class TunePendulum : public testing::Test {
 protected:
  void SetUp() override {
    file_ = fs::temp_directory_path() / ("mechsim_tuning_test_" + std::to_string(::getpid()) + "_" +
                                         std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + ".yaml");
    std::ofstream(file_) << "hinge_position_controller:\n"
                            "  type: effort_controllers/JointPositionController\n"
                            "  joint: hinge\n"
                            "  pid: {p: 60.0, i: 0.0, d: 4.0}\n";
    setup_.robot = description::parse_urdf_string(kPendulum, "pendulum", {});
    setup_.controllers_file = file_.string();
    setup_.joint = "hinge";
    setup_.max_evaluations = 6;
  }
  void TearDown() override { fs::remove(file_); }
  fs::path file_;
  TuneSetup setup_;
};

TEST_F(TunePendulum, AStepIntoTheLimitIsTakenTheOtherWayAndReachesItsTarget) {
  setup_.step = 0.3;
  const TuneResult r = tune_joint(setup_);
  EXPECT_NEAR(r.start, 0.0, 0.01);
  EXPECT_TRUE(r.plan.reversed);
  EXPECT_DOUBLE_EQ(r.plan.step, -0.3);
  EXPECT_DOUBLE_EQ(r.before_metrics.step, -0.3);
  // The YAML's gains get there (95 %) instead of pressing on the stop.
  EXPECT_GE(r.before_metrics.rise95, 0.0);
  EXPECT_FALSE(r.before_metrics.diverged);
}

TEST_F(TunePendulum, AStepOutOfRangeBothWaysFailsNamingTheJoint) {
  setup_.step = 1.5;
  try {
    tune_joint(setup_);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("'hinge'"), HasSubstr("limits [-1, 0]"), HasSubstr("step of 1.5")));
  }
}

}  // namespace
}  // namespace mechsim::sim
