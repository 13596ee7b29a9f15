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


// Robust tuning (`mechsim tune --robust`): gains tuned on the nominal step alone overshoot and
// settle late with 3 kg more on the pendulum; tuned for the worst of the conditions they meet the
// targets in all of them.
TEST_F(TunePendulum, RobustGainsMeetTheTargetsUnderAPayloadWhereNominalOnesMissThem) {
  setup_.step = 0.3;
  setup_.max_evaluations = 80;
  const TuneResult nominal = tune_joint(setup_);
  ASSERT_TRUE(nominal.targets_met);
  EXPECT_TRUE(nominal.conditions.empty());

  TuneSetup loaded = setup_;
  loaded.step = -0.3;  // the planned step
  for (description::Link& l : loaded.robot.links)
    if (l.name == "arm") l.inertial->mass += 3.0;
  const StepMetrics with_payload = measure_step(loaded, nominal.controller, false, nominal.after);
  const bool nominal_meets = with_payload.overshoot <= 5.0 && with_payload.settling_time >= 0 && with_payload.settling_time <= 0.3;
  EXPECT_FALSE(nominal_meets) << "overshoot " << with_payload.overshoot << " %, settles at " << with_payload.settling_time;

  setup_.robust = true;
  setup_.conditions = {{"3 kg on the arm", 1.0, {}, "arm", 3.0}, {"small step", 0.2, {}, "", 0.0}};
  const TuneResult robust = tune_joint(setup_);
  ASSERT_EQ(robust.conditions.size(), 3u);
  EXPECT_EQ(robust.conditions[0].name, "nominal");
  EXPECT_EQ(robust.conditions[1].name, "3 kg on the arm");
  EXPECT_DOUBLE_EQ(robust.conditions[2].after.step, -0.06);
  for (const TuneResult::ConditionOutcome& c : robust.conditions) {
    EXPECT_TRUE(c.met_after) << c.name << ": overshoot " << c.after.overshoot << " %, settles at " << c.after.settling_time;
  }
  EXPECT_TRUE(robust.targets_met);
  // The payload condition is really loaded: the YAML's gains fare worse there than nominally.
  EXPECT_GT(std::abs(robust.conditions[1].before.steady_state_error), std::abs(robust.conditions[0].before.steady_state_error));
}

// Gains that already meet the targets stay as they are (the search starts from raised gains and
// would otherwise move them for nothing).
TEST_F(TunePendulum, GainsThatAlreadyMeetTheTargetsAreKept) {
  std::ofstream(file_) << "hinge_position_controller:\n"
                          "  type: effort_controllers/JointPositionController\n"
                          "  joint: hinge\n"
                          "  pid: {p: 1450.0, i: 0.373, d: 70.9}\n";
  setup_.step = 0.3;
  setup_.max_evaluations = 20;
  const TuneResult r = tune_joint(setup_);
  ASSERT_TRUE(r.targets_met);
  EXPECT_DOUBLE_EQ(r.after.p, 1450.0);
  EXPECT_DOUBLE_EQ(r.after.i, 0.373);
  EXPECT_DOUBLE_EQ(r.after.d, 70.9);
}

TEST_F(TunePendulum, DefaultRobustConditionsNameAStepTurnedBackIntoTheRange) {
  setup_.step = 0.3;
  setup_.robust = true;
  const TuneResult r = tune_joint(setup_);
  ASSERT_EQ(r.conditions.size(), 4u);  // nominal, small step, reversed, payload
  EXPECT_THAT(r.conditions[2].name, AllOf(HasSubstr("reversed step"), HasSubstr("the other way")));
  EXPECT_THAT(r.conditions[3].name, HasSubstr("payload 0.5 kg on arm"));
}

TEST_F(TunePendulum, APayloadOnAMissingLinkIsAnErrorNamingTheCondition) {
  setup_.step = 0.3;
  setup_.robust = true;
  setup_.conditions = {{"in the gripper", 1.0, {}, "gripper", 1.0}};
  try {
    tune_joint(setup_);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("'in the gripper'"), HasSubstr("no link 'gripper'")));
  }
}

TEST(TuneConditions, TheCc8sShippedFileReads) {
  const std::vector<TuneCondition> c =
      read_tune_conditions(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/tune_conditions.yaml");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_TRUE(c[1].world && c[1].world->soil.has_value());
  EXPECT_EQ(c[2].world->name, "slope");
}

TEST(TuneConditions, AreReadWithTheirWorldsAndBadOnesNameFileLineAndKey) {
  const fs::path file = fs::temp_directory_path() / ("mechsim_tune_conditions_" + std::to_string(::getpid()) + ".yaml");
  struct Removed {
    fs::path path;
    ~Removed() { fs::remove(path); }
  } removed{file};
  std::ofstream(file) << "conditions:\n"
                         "  - step_scale: 0.5\n"
                         "  - name: on the slope\n"
                         "    world: {name: slope, slope_deg: 12}\n"
                         "  - payload: {link: arm, mass: 2}\n";
  const std::vector<TuneCondition> c = read_tune_conditions(file.string());
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].name, "step x0.5");
  EXPECT_DOUBLE_EQ(c[0].step_scale, 0.5);
  EXPECT_EQ(c[1].name, "on the slope");
  ASSERT_TRUE(c[1].world.has_value());
  EXPECT_EQ(c[1].world->name, "slope");
  EXPECT_DOUBLE_EQ(c[1].world->slope_deg.value_or(0.0), 12.0);
  EXPECT_EQ(c[2].payload_link, "arm");
  EXPECT_DOUBLE_EQ(c[2].payload_mass, 2.0);

  auto error_of = [&](const std::string& text) {
    std::ofstream(file) << text;
    try {
      read_tune_conditions(file.string());
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(error_of("conditions:\n  - step_scale: 0.5\n    payloads: {}\n"),
              AllOf(HasSubstr(file.string() + ":3"), HasSubstr("unknown key 'payloads'")));
  EXPECT_THAT(error_of("conditions: []\n"), HasSubstr("non-empty list 'conditions'"));
  EXPECT_THAT(error_of("conditions:\n  - payload: {link: arm, mass: -1}\n"), AllOf(HasSubstr(":2"), HasSubstr("mass > 0")));
  EXPECT_THAT(error_of("conditions:\n  - step_scale: 0\n"), HasSubstr("non-zero scale"));
}

}  // namespace
}  // namespace mechsim::sim
