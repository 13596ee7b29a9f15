// The PR2 gripper controller on a tiny plant: the gap joint a unit mass (test_robot.hpp's
// physics), optionally blocked by an obstacle (its position clamped). Tracking, max_effort,
// goal reached, stall detected with the holding force at max_effort, preemption, cancel, NaN
// rejection and init errors.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/gripper/pr2_gripper_controller.hpp"
#include "controllers/test/test_robot.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

constexpr const char* kYaml = R"(pr2:
  r_gripper_controller:
    type: pr2_mechanism_controllers/Pr2GripperController
    joint: r_gripper_joint
    pid: {p: 100.0, d: 20.0}
)";

struct Gripper {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  Pr2GripperController* c = nullptr;
  double time = 0.0;
  double obstacle = -1.0;  // m: the gap cannot close below this (an object between the fingers)
  double max_abs_effort = 0.0;

  explicit Gripper(const char* yaml = kYaml) {
    robot = testing::make_robot({{"r_gripper_joint", description::JointType::Prismatic,
                                  description::JointLimits{0.0, 0.09, 1000.0, 0.2}}});
    robot->joint("r_gripper_joint").position = 0.08;
    mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml).child("pr2"),
                                                  builtin_controller_registry());
    c = dynamic_cast<Pr2GripperController*>(testing::load_and_start(*manager, "r_gripper_controller"));
    run(1);
  }
  void run(int ticks) {
    for (int i = 0; i < ticks; ++i) {
      manager->update(time, 0.001);
      robot->step(0.001);
      mechanism::JointState& j = robot->joint("r_gripper_joint");
      if (j.position < obstacle) {
        j.position = obstacle;
        j.velocity = 0.0;
        mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
      }
      max_abs_effort = std::fmax(max_abs_effort, std::abs(c->state_port().read().command));
      time += 0.001;
    }
  }
  double gap() { return robot->joint("r_gripper_joint").position; }
};

TEST(Pr2Gripper, TracksAGapCommand) {
  Gripper g;
  EXPECT_NEAR(g.c->state_port().read().set_point, 0.08, 1e-12);  // holds where it started
  ASSERT_TRUE(g.c->command_port().write({0.02, 100.0}));
  g.run(1500);
  EXPECT_NEAR(g.gap(), 0.02, 1e-4);
  const JointControllerState s = g.c->state_port().read();
  EXPECT_NEAR(s.set_point, 0.02, 1e-12);
  EXPECT_NEAR(s.error, s.process_value - s.set_point, 1e-15);  // the PR2's sign
}

TEST(Pr2Gripper, EffortNeverExceedsMaxEffort) {
  Gripper g;
  ASSERT_TRUE(g.c->command_port().write({0.0, 0.5}));  // p * 0.08 = 8 N wanted; 0.5 N allowed
  g.run(200);
  EXPECT_NEAR(g.max_abs_effort, 0.5, 1e-12);
  EXPECT_LT(g.gap(), 0.08);  // it still moves, slowly
  g.max_abs_effort = 0.0;
  ASSERT_TRUE(g.c->command_port().write({0.0, -1.0}));  // negative: no limit
  g.run(5);
  EXPECT_GT(g.max_abs_effort, 0.5);
}

TEST(Pr2Gripper, GoalSucceedsWithinTheThreshold) {
  Gripper g;
  const GripperSubmission s = g.c->goal_port().submit({0.03, 50.0});
  ASSERT_TRUE(s.accepted) << s.error;
  EXPECT_EQ(g.c->goal_port().status(s.id), GoalStatus::Pending);
  g.run(1);
  EXPECT_EQ(g.c->goal_port().status(s.id), GoalStatus::Active);
  EXPECT_FALSE(g.c->goal_port().result(s.id).has_value());
  g.run(2000);
  ASSERT_EQ(g.c->goal_port().status(s.id), GoalStatus::Succeeded);
  const GripperResult r = *g.c->goal_port().result(s.id);
  EXPECT_TRUE(r.reached_goal);
  EXPECT_FALSE(r.stalled);
  EXPECT_LT(std::abs(r.position - 0.03), 0.01);  // goal_threshold
  EXPECT_GT(r.position, 0.03);                   // it finished on the way, within the threshold
  EXPECT_NEAR(g.gap(), 0.03, 1e-3);              // and kept going to the position
  EXPECT_EQ(g.c->goal_port().feedback().goal_id, s.id);
}

TEST(Pr2Gripper, StallOnAnObstacleAbortsAndKeepsSqueezingWithMaxEffort) {
  Gripper g;
  g.obstacle = 0.05;  // a 5 cm object
  const GripperSubmission s = g.c->goal_port().submit({0.0, 20.0});
  ASSERT_TRUE(s.accepted);
  g.run(3000);
  ASSERT_EQ(g.c->goal_port().status(s.id), GoalStatus::Aborted);
  const GripperResult r = *g.c->goal_port().result(s.id);
  EXPECT_TRUE(r.stalled);
  EXPECT_FALSE(r.reached_goal);
  EXPECT_NEAR(r.position, 0.05, 1e-9);
  EXPECT_NEAR(g.gap(), 0.05, 1e-9);
  // Still holding: the PID wants -p * 0.05 = -5 N... plus the integral of nothing; with p = 100
  // it asks for 5 N < 20 N, so use the state: the effort closes the gripper.
  EXPECT_LT(g.c->state_port().read().command, 0.0);
  const GripperFeedback fb = g.c->goal_port().feedback();
  EXPECT_TRUE(fb.state.stalled);
}

TEST(Pr2Gripper, HoldingForceOnAnObstacleEqualsMaxEffort) {
  Gripper g;
  g.obstacle = 0.05;
  const GripperSubmission s = g.c->goal_port().submit({0.0, 3.0});  // the PID asks for 5 N; 3 N allowed
  ASSERT_TRUE(s.accepted);
  g.run(3000);
  ASSERT_EQ(g.c->goal_port().status(s.id), GoalStatus::Aborted);
  EXPECT_TRUE(g.c->goal_port().result(s.id)->stalled);
  EXPECT_DOUBLE_EQ(g.c->state_port().read().command, -3.0);
  EXPECT_DOUBLE_EQ(g.c->goal_port().result(s.id)->effort, -3.0);
}

TEST(Pr2Gripper, NewerGoalOrCommandPreemptsAndCancelPreempts) {
  Gripper g;
  const GripperSubmission a = g.c->goal_port().submit({0.01, 10.0});
  g.run(5);
  const GripperSubmission b = g.c->goal_port().submit({0.03, 10.0});
  g.run(5);
  EXPECT_EQ(g.c->goal_port().status(a.id), GoalStatus::Preempted);
  EXPECT_EQ(g.c->goal_port().status(b.id), GoalStatus::Active);
  ASSERT_TRUE(g.c->command_port().write({0.06, 10.0}));
  g.run(1);
  EXPECT_EQ(g.c->goal_port().status(b.id), GoalStatus::Preempted);
  const GripperSubmission d = g.c->goal_port().submit({0.0, 10.0});
  g.run(5);
  EXPECT_TRUE(g.c->goal_port().cancel(d.id));
  g.run(1);
  EXPECT_EQ(g.c->goal_port().status(d.id), GoalStatus::Preempted);
  EXPECT_FALSE(g.c->goal_port().cancel(d.id));  // finished
  EXPECT_FALSE(g.c->goal_port().cancel(999));   // unknown
}

TEST(Pr2Gripper, RejectsNonFiniteCommandsAndGoals) {
  Gripper g;
  std::string error;
  EXPECT_FALSE(g.c->command_port().write({NAN, 10.0}, &error));
  EXPECT_THAT(error, HasSubstr("not finite"));
  EXPECT_EQ(g.c->command_port().count(), 1u);
  const GripperSubmission s = g.c->goal_port().submit({0.02, INFINITY});
  EXPECT_FALSE(s.accepted);
  EXPECT_EQ(g.c->goal_port().status(s.id), GoalStatus::Rejected);
  g.run(10);
  EXPECT_NEAR(g.c->state_port().read().set_point, 0.08, 1e-12);
}

TEST(Pr2Gripper, GoalsAreRefusedWhileStopped) {
  Gripper g;
  ASSERT_TRUE(g.manager->switch_controllers({}, {"r_gripper_controller"}, SwitchStrictness::Strict).ok);
  g.run(1);
  const GripperSubmission s = g.c->goal_port().submit({0.02, 10.0});
  EXPECT_FALSE(s.accepted);
  EXPECT_THAT(s.error, HasSubstr("not running"));
}

TEST(Pr2Gripper, InitErrorsNameTheParameterPath) {
  auto robot = testing::make_robot({{"r_gripper_joint", description::JointType::Prismatic,
                                     description::JointLimits{0.0, 0.09, 1000.0, 0.2}}});
  const auto load = [&](const std::string& yaml) {
    ControllerManager m(robot->model, robot->state, Params::from_yaml_string(yaml).child("pr2"),
                        builtin_controller_registry());
    return m.load_controller("g").error;
  };
  EXPECT_THAT(load("pr2:\n  g:\n    type: pr2_mechanism_controllers/Pr2GripperController\n    pid: {p: 1}\n"),
              HasSubstr("/pr2/g/joint"));
  EXPECT_THAT(load("pr2:\n  g:\n    type: pr2_mechanism_controllers/Pr2GripperController\n    joint: l_gripper_joint\n"
                   "    pid: {p: 1}\n"),
              HasSubstr("l_gripper_joint"));
  EXPECT_THAT(load("pr2:\n  g:\n    type: pr2_mechanism_controllers/Pr2GripperController\n    joint: r_gripper_joint\n"),
              HasSubstr("/pr2/g/pid"));
  EXPECT_THAT(load("pr2:\n  g:\n    type: pr2_mechanism_controllers/Pr2GripperController\n    joint: r_gripper_joint\n"
                   "    pid: {p: 1}\n    stall_timeout: -1\n"),
              HasSubstr("/pr2/g/stall_timeout"));
}

}  // namespace
}  // namespace mechsim::control
