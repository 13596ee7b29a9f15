// position_ and effort_controllers/GripperActionController on a one-joint plant (the test robot's
// unit inertia), optionally blocked by an object (the joint clamped): a goal reached within
// goal_tolerance succeeds; a goal past the object stalls (aborted, stalled) after stall_timeout
// and the gripper keeps squeezing at max_effort; a newer goal preempts; a cancel preempts and
// holds; the effort variant needs its gains.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/gripper/gripper_action_controller.hpp"
#include "controllers/test/test_robot.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

std::string yaml(const char* type) {
  return std::string("bot:\n  gripper:\n    type: ") + type +
         "\n    joint: finger\n    goal_tolerance: 0.01\n    stall_timeout: 0.3\n    max_effort: 2.0\n"
         "    gains:\n      finger: {p: 50.0, d: 10.0}\n";
}

struct Plant {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  GripperActionController* c = nullptr;
  double time = 0.0;
  double obstacle = 1e9;  // rad: the joint cannot go above this

  explicit Plant(const char* type) {
    robot = testing::make_robot({{"finger", description::JointType::Revolute, description::JointLimits{-1.0, 1.0, 100.0, 10.0}}});
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml(type)).child("bot"),
                                                  builtin_controller_registry());
    c = dynamic_cast<GripperActionController*>(testing::load_and_start(*manager, "gripper"));
    run(1);
  }
  void run(int ticks) {
    for (int i = 0; i < ticks; ++i) {
      manager->update(time, 0.001);
      robot->step(0.001);
      mechanism::JointState& j = robot->joint("finger");
      if (j.position > obstacle) {
        j.position = obstacle;
        j.velocity = 0.0;
        mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
      }
      time += 0.001;
    }
  }
  double position() { return robot->joint("finger").position; }
};

TEST(GripperActionController, EffortGoalSucceedsWithinTheTolerance) {
  Plant p(kEffortGripperActionType);
  ASSERT_NE(p.c, nullptr);
  const GripperSubmission s = p.c->goal_port().submit({0.3, 5.0});
  ASSERT_TRUE(s.accepted) << s.error;
  p.run(1);
  EXPECT_EQ(p.c->goal_port().status(s.id), GoalStatus::Active);
  p.run(3000);
  ASSERT_EQ(p.c->goal_port().status(s.id), GoalStatus::Succeeded);
  const GripperResult r = *p.c->goal_port().result(s.id);
  EXPECT_TRUE(r.reached_goal);
  EXPECT_FALSE(r.stalled);
  EXPECT_LT(std::abs(r.position - 0.3), 0.01);
  EXPECT_NEAR(p.position(), 0.3, 1e-3);
}

TEST(GripperActionController, StallsOnAnObjectAndSqueezesWithMaxEffort) {
  Plant p(kEffortGripperActionType);
  p.obstacle = 0.2;
  const GripperSubmission s = p.c->goal_port().submit({0.5, 1.5});  // the PID wants 15 N m; 1.5 allowed
  ASSERT_TRUE(s.accepted);
  p.run(3000);
  ASSERT_EQ(p.c->goal_port().status(s.id), GoalStatus::Aborted);
  const GripperResult r = *p.c->goal_port().result(s.id);
  EXPECT_TRUE(r.stalled);
  EXPECT_FALSE(r.reached_goal);
  EXPECT_NEAR(r.position, 0.2, 1e-9);
  EXPECT_DOUBLE_EQ(r.effort, 1.5);
  // The command stays after the abort: still squeezing at max_effort.
  EXPECT_DOUBLE_EQ(p.robot->joint("finger").commanded_effort, 1.5);
  EXPECT_TRUE(p.c->goal_port().feedback().state.stalled);
}

TEST(GripperActionController, PositionVariantCommandsThePositionAndReportsMaxEffort) {
  Plant p(kPositionGripperActionType);
  p.obstacle = 0.2;
  const GripperSubmission s = p.c->goal_port().submit({0.5, 0.7});
  p.run(1000);
  EXPECT_EQ(p.robot->joint("finger").command_mode, HardwareInterface::Position);
  EXPECT_DOUBLE_EQ(p.robot->joint("finger").commanded_position, 0.5);
  ASSERT_EQ(p.c->goal_port().status(s.id), GoalStatus::Aborted);
  EXPECT_TRUE(p.c->goal_port().result(s.id)->stalled);
  EXPECT_DOUBLE_EQ(p.c->goal_port().result(s.id)->effort, 0.7);
}

TEST(GripperActionController, NewerGoalPreemptsAndCancelHolds) {
  Plant p(kEffortGripperActionType);
  const GripperSubmission a = p.c->goal_port().submit({0.8, 5.0});
  p.run(5);
  const GripperSubmission b = p.c->goal_port().submit({-0.5, 5.0});
  p.run(2);
  EXPECT_EQ(p.c->goal_port().status(a.id), GoalStatus::Preempted);
  EXPECT_EQ(p.c->goal_port().status(b.id), GoalStatus::Active);
  ASSERT_TRUE(p.c->goal_port().cancel(b.id));
  p.run(2);
  EXPECT_EQ(p.c->goal_port().status(b.id), GoalStatus::Preempted);
  // Holding where it was at the cancel, with the default max_effort (2 N m).
  EXPECT_NEAR(p.c->goal_port().feedback().state.position, p.position(), 0.01);
  EXPECT_LE(std::abs(p.robot->joint("finger").commanded_effort), 2.0 + 1e-12);
}

TEST(GripperActionController, EffortVariantNeedsItsGains) {
  auto robot = testing::make_robot({{"finger"}});
  ControllerManager m(robot->model, robot->state,
                      Params::from_yaml_string("bot:\n  gripper: {type: effort_controllers/GripperActionController, joint: finger}\n")
                          .child("bot"),
                      builtin_controller_registry());
  const ControlResult r = m.load_controller("gripper");
  ASSERT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("/bot/gripper/gains/finger"));
  ControllerManager pos(robot->model, robot->state,
                        Params::from_yaml_string("bot:\n  gripper: {type: position_controllers/GripperActionController, "
                                                 "joint: finger, goal_tolerance: -1}\n")
                            .child("bot"),
                        builtin_controller_registry());
  EXPECT_THAT(pos.load_controller("gripper").error, HasSubstr("/bot/gripper/goal_tolerance must be finite and >= 0"));
}

}  // namespace
}  // namespace mechsim::control
