// The trajectory controllers in the manager's tick on the unit-inertia joints of
// test_robot.hpp (1 kHz): holding, goals (success, path and goal tolerance aborts, goal time),
// preemption, cancel, partial goals, wrapping, the plain command port, configuration errors.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"
#include "controllers/trajectory/trajectory_controller.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;
using description::JointType;
using testing::JointSpec;

struct Rig {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  double time = 0.0;

  Rig(std::vector<JointSpec> joints, const std::string& yaml) : robot(testing::make_robot(joints)) {
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml),
                                                  builtin_controller_registry());
  }
  Rig(std::size_t n, const std::string& yaml) : robot(testing::make_robot(n)) {
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml),
                                                  builtin_controller_registry());
  }
  void start(const std::string& name = "c") {
    auto r = manager->load_controller(name);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_TRUE(manager->switch_controllers({name}, {}, SwitchStrictness::Strict).ok);
    tick(1);
    ASSERT_EQ(manager->controller_info(name)->state, ControllerLifecycle::Running);
  }
  void tick(int n) { time = testing::run(*manager, *robot, time, n); }
  JointTrajectoryController& jtc(const std::string& name = "c") {
    return *dynamic_cast<JointTrajectoryController*>(manager->controller(name));
  }
  TrajectoryGoalPort& goals(const std::string& name = "c") {
    return *manager->controller(name)->port_as<TrajectoryGoalPort>("follow_joint_trajectory");
  }
  JointTrajectoryControllerState state(const std::string& name = "c") {
    return manager->controller(name)->port_as<StatePort<JointTrajectoryControllerState>>("state")->read();
  }
  mechanism::JointState& joint(const std::string& name) { return robot->joint(name); }
};

const char* kTwoJoints = R"(
c:
  type: effort_controllers/JointTrajectoryController
  joints: [j0, j1]
  gains: {j0: {p: 400, d: 40}, j1: {p: 400, d: 40}}
  constraints:
    goal_time: 0.5
    stopped_velocity_tolerance: 0.05
    j0: {trajectory: 0.1, goal: 0.01}
    j1: {trajectory: 0.1, goal: 0.01}
  state_publish_rate: 0
  action_monitor_rate: 0
)";

// A rest-to-rest move of every named joint to `targets` over `duration` seconds (cubic).
FollowJointTrajectoryGoal move(std::vector<std::string> names, std::vector<double> targets, double duration) {
  FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = std::move(names);
  TrajectoryPoint p;
  p.positions = std::move(targets);
  p.velocities.assign(p.positions.size(), 0.0);
  p.time_from_start = duration;
  g.trajectory.points = {p};
  return g;
}

TEST(JointTrajectoryController, HoldsTheCurrentPositionWhenStartedAndIdle) {
  Rig rig(2, kTwoJoints);
  rig.robot->state.actuators[0].position = 0.7;
  rig.robot->state.actuators[1].position = -0.2;
  rig.start();
  rig.tick(1000);
  EXPECT_NEAR(rig.joint("j0").position, 0.7, 1e-9);
  EXPECT_NEAR(rig.joint("j1").position, -0.2, 1e-9);
  const auto s = rig.state();
  EXPECT_EQ(s.joint_names, (std::vector<std::string>{"j0", "j1"}));
  EXPECT_DOUBLE_EQ(s.desired.positions[0], 0.7);
  EXPECT_DOUBLE_EQ(s.desired.velocities[0], 0.0);
  EXPECT_NEAR(s.error.positions[1], 0.0, 1e-9);
}

TEST(JointTrajectoryController, GoalWithinToleranceSucceeds) {
  Rig rig(2, kTwoJoints);
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j1", "j0"}, {-0.3, 0.5}, 1.0));
  ASSERT_TRUE(s.accepted) << s.result.error_string;
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Pending);
  rig.tick(500);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Active);
  const FollowJointTrajectoryFeedback fb = rig.goals().feedback();
  EXPECT_EQ(fb.goal_id, s.id);
  EXPECT_NEAR(fb.state.desired.positions[0], 0.25, 0.01);  // half way, by symmetry of the cubic
  EXPECT_NEAR(fb.state.error.positions[0], fb.state.desired.positions[0] - fb.state.actual.positions[0], 1e-12);
  rig.tick(1000);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Succeeded);
  const auto result = rig.goals().result(s.id);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->error_code, TrajectoryResultCode::Successful);
  EXPECT_EQ(result->error_string, "");
  EXPECT_NEAR(rig.joint("j0").position, 0.5, 0.01);
  EXPECT_NEAR(rig.joint("j1").position, -0.3, 0.01);
  // A finished trajectory holds its last point.
  rig.tick(1000);
  EXPECT_NEAR(rig.joint("j0").position, 0.5, 1e-3);
  EXPECT_DOUBLE_EQ(rig.state().desired.positions[1], -0.3);
}

TEST(JointTrajectoryController, PathToleranceViolationAbortsAndHolds) {
  Rig rig(2, kTwoJoints);
  rig.start();
  auto goal = move({"j0", "j1"}, {1.0, 0.0}, 1.0);
  goal.path_tolerance = {{"j0", 0.001, 0.0, 0.0}};
  const GoalSubmission s = rig.goals().submit(goal);
  ASSERT_TRUE(s.accepted);
  rig.tick(300);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Aborted);
  const auto result = rig.goals().result(s.id);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->error_code, TrajectoryResultCode::PathToleranceViolated);
  EXPECT_THAT(result->error_string, HasSubstr("PATH_TOLERANCE_VIOLATED"));
  EXPECT_THAT(result->error_string, HasSubstr("joint 'j0' position error"));
  EXPECT_THAT(result->error_string, HasSubstr("exceeds the tolerance 0.001"));
  // Held where it was when the goal aborted: the desired state no longer moves.
  ASSERT_EQ(rig.jtc().trajectory().segment_count(0), 1u);
  const double held = rig.state().desired.positions[0];
  EXPECT_LT(held, 0.1);
  rig.tick(1000);
  EXPECT_DOUBLE_EQ(rig.state().desired.positions[0], held);
  EXPECT_NEAR(rig.joint("j0").position, held, 1e-3);
}

TEST(JointTrajectoryController, GoalToleranceViolatedAfterTheGoalTime) {
  // Gains too weak to settle within 1 mm in time.
  Rig rig(1, R"(
c:
  type: effort_controllers/JointTrajectoryController
  joints: [j0]
  gains: {j0: {p: 4, d: 4}}
  constraints: {goal_time: 0.3, j0: {goal: 0.001}}
)");
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0"}, {1.0}, 0.5));
  ASSERT_TRUE(s.accepted);
  rig.tick(700);  // t = 0.7: past the end (0.5) but within the goal time
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Active);
  rig.tick(200);  // t = 0.9 > 0.5 + 0.3
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Aborted);
  const auto result = rig.goals().result(s.id);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->error_code, TrajectoryResultCode::GoalToleranceViolated);
  EXPECT_THAT(result->error_string, HasSubstr("GOAL_TOLERANCE_VIOLATED"));
  EXPECT_THAT(result->error_string, HasSubstr("joint 'j0'"));
}

TEST(JointTrajectoryController, WithoutAGoalTimeTheGoalWaitsToSettle) {
  Rig rig(1, R"(
c:
  type: effort_controllers/JointTrajectoryController
  joints: [j0]
  gains: {j0: {p: 25, d: 10}}
  constraints: {j0: {goal: 0.001}}
)");
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0"}, {1.0}, 0.2));
  rig.tick(300);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Active);  // lagging, but no time limit
  rig.tick(5000);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Succeeded);
}

TEST(JointTrajectoryController, ANewGoalPreemptsTheActiveOneWithoutAJumpInTheDesiredState) {
  Rig rig(2, kTwoJoints);
  rig.start();
  const GoalSubmission a = rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 4.0));
  rig.tick(1000);
  const auto before = rig.state();
  const GoalSubmission b = rig.goals().submit(move({"j0", "j1"}, {-0.5, 0.0}, 1.0));
  rig.tick(1);
  const auto after = rig.state();
  EXPECT_EQ(rig.goals().status(a.id), GoalStatus::Preempted);
  EXPECT_EQ(rig.goals().status(b.id), GoalStatus::Active);
  EXPECT_THAT(rig.goals().result(a.id)->error_string, HasSubstr("preempted"));
  // One tick apart: the desired state moves by about velocity x 1 ms, not a jump.
  EXPECT_NEAR(after.desired.positions[0], before.desired.positions[0], 2e-3);
  EXPECT_NEAR(after.desired.velocities[0], before.desired.velocities[0], 2e-2);
  rig.tick(1500);
  EXPECT_EQ(rig.goals().status(b.id), GoalStatus::Succeeded);
  EXPECT_NEAR(rig.joint("j0").position, -0.5, 0.01);
}

TEST(JointTrajectoryController, CancelPreemptsAndHoldsTheCurrentPosition) {
  Rig rig(2, kTwoJoints);
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 2.0));
  rig.tick(800);
  EXPECT_TRUE(rig.goals().cancel(s.id));
  rig.tick(1);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Preempted);
  EXPECT_FALSE(rig.goals().cancel(s.id));
  const double held = rig.state().desired.positions[0];
  EXPECT_GT(held, 0.1);
  EXPECT_LT(held, 0.9);
  rig.tick(1500);
  EXPECT_DOUBLE_EQ(rig.state().desired.positions[0], held);
  EXPECT_NEAR(rig.joint("j0").position, held, 2e-3);
}

TEST(JointTrajectoryController, AGoalCanceledBeforeItStartsNeverRuns) {
  Rig rig(1, R"(
c: {type: effort_controllers/JointTrajectoryController, joints: [j0], gains: {j0: {p: 100, d: 20}}}
)");
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0"}, {1.0}, 1.0));
  EXPECT_TRUE(rig.goals().cancel(s.id));
  rig.tick(500);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Preempted);
  EXPECT_NEAR(rig.joint("j0").position, 0.0, 1e-9);
}

TEST(JointTrajectoryController, PartialGoalsLeaveTheOtherJointsOnTheirTrajectory) {
  std::string yaml = kTwoJoints;
  yaml += "  allow_partial_joints_goal: true\n";
  Rig rig(2, yaml);
  rig.start();
  const GoalSubmission a = rig.goals().submit(move({"j0", "j1"}, {1.0, 0.5}, 2.0));
  rig.tick(500);
  const GoalSubmission b = rig.goals().submit(move({"j1"}, {-0.5}, 1.0));
  ASSERT_TRUE(b.accepted) << b.result.error_string;
  rig.tick(2500);
  EXPECT_EQ(rig.goals().status(a.id), GoalStatus::Preempted);
  EXPECT_EQ(rig.goals().status(b.id), GoalStatus::Succeeded);
  EXPECT_NEAR(rig.joint("j0").position, 1.0, 0.01);  // kept goal a's trajectory
  EXPECT_NEAR(rig.joint("j1").position, -0.5, 0.01);
}

TEST(JointTrajectoryController, ContinuousJointsWrapTheShortWay) {
  Rig rig({JointSpec{"w", JointType::Continuous}}, R"(
c: {type: effort_controllers/JointTrajectoryController, joints: [w], gains: {w: {p: 400, d: 40}}}
)");
  rig.robot->state.actuators[0].position = 3.0;
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"w"}, {-3.0}, 1.0));
  double lowest = 10.0;
  for (int k = 0; k < 1500; ++k) {
    rig.tick(1);
    lowest = std::min(lowest, rig.joint("w").position);
  }
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Succeeded);
  EXPECT_NEAR(rig.joint("w").position, 2 * std::numbers::pi - 3.0, 0.01);
  EXPECT_GT(lowest, 2.99);  // never turned back through zero
  EXPECT_NEAR(rig.state().error.positions[0], 0.0, 0.01);
}

TEST(JointTrajectoryController, CommandPortReplacesTheTrajectoryAtAFutureTime) {
  Rig rig(1, R"(
c: {type: effort_controllers/JointTrajectoryController, joints: [j0], gains: {j0: {p: 400, d: 40}}, state_publish_rate: 0}
)");
  rig.start();  // t = 0.001 after the first tick
  auto* command = rig.manager->controller("c")->port_as<TrajectoryCommandPort>("command");
  ASSERT_NE(command, nullptr);
  JointTrajectory t;
  t.start_time = 0.5;
  t.joint_names = {"j0"};
  t.points = {{{0.4}, {}, {}, {}, 0.5}};  // reach 0.4 at t = 1.0
  std::string error;
  ASSERT_TRUE(command->write(t, &error)) << error;
  rig.tick(400);  // t ~ 0.4: still holding
  EXPECT_DOUBLE_EQ(rig.state().desired.positions[0], 0.0);
  rig.tick(350);  // t ~ 0.75: half way along the linear segment
  EXPECT_NEAR(rig.state().desired.positions[0], 0.2, 2e-3);
  rig.tick(1000);
  EXPECT_NEAR(rig.joint("j0").position, 0.4, 1e-3);
  // An empty command stops where the joint is.
  ASSERT_TRUE(command->write(JointTrajectory{}, &error));
  rig.tick(1);
  EXPECT_EQ(rig.jtc().trajectory().segment_count(0), 1u);
}

TEST(JointTrajectoryController, ACommandPreemptsTheActiveGoal) {
  Rig rig(2, kTwoJoints);
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 2.0));
  rig.tick(100);
  JointTrajectory t = move({"j0", "j1"}, {0.0, 0.0}, 1.0).trajectory;
  ASSERT_TRUE(rig.manager->controller("c")->port_as<TrajectoryCommandPort>("command")->write(t));
  rig.tick(1);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Preempted);
  EXPECT_EQ(rig.jtc().active_goal(), 0u);
}

TEST(JointTrajectoryController, StoppingTheControllerPreemptsItsGoal) {
  Rig rig(2, kTwoJoints);
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 2.0));
  rig.tick(100);
  ASSERT_TRUE(rig.manager->switch_controllers({}, {"c"}, SwitchStrictness::Strict).ok);
  rig.tick(1);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Preempted);
}

// query_state: the running trajectory sampled at any time, from outside the tick (the service's
// thread); refused while the controller is stopped.
TEST(JointTrajectoryController, QueryStateSamplesTheRunningTrajectoryAtAnyTime) {
  Rig rig(2, kTwoJoints);
  rig.robot->state.actuators[0].position = 0.1;
  ASSERT_TRUE(rig.manager->load_controller("c").ok);
  TrajectoryQueryPort& port = *rig.manager->controller("c")->port_as<TrajectoryQueryPort>("query_state");
  std::vector<SplineState> s;
  std::string error;
  EXPECT_FALSE(port.sample(0.0, s, &error)) << "a loaded, stopped controller has nothing to sample";
  EXPECT_THAT(error, HasSubstr("not running"));
  ASSERT_TRUE(rig.manager->switch_controllers({"c"}, {}, SwitchStrictness::Strict).ok);
  rig.tick(1);
  EXPECT_EQ(port.joint_names(), (std::vector<std::string>{"j0", "j1"}));
  ASSERT_TRUE(port.sample(rig.time + 10.0, s, &error)) << error;
  EXPECT_DOUBLE_EQ(s[0].position, 0.1) << "holding where it started";
  EXPECT_DOUBLE_EQ(s[1].position, 0.0);

  const GoalSubmission g = rig.goals().submit(move({"j1", "j0"}, {-0.3, 0.5}, 1.0));
  ASSERT_TRUE(g.accepted) << g.result.error_string;
  rig.tick(1);  // taken at this tick: the move runs from about rig.time to rig.time + 1 s
  const double start = rig.time;
  ASSERT_TRUE(port.sample(start + 0.5, s, &error)) << error;
  EXPECT_NEAR(s[0].position, 0.3, 0.01);  // half way from 0.1 to 0.5 (the cubic's symmetry)
  EXPECT_NEAR(s[1].position, -0.15, 0.01);
  EXPECT_GT(s[0].velocity, 0.5);
  EXPECT_LT(s[1].velocity, -0.3);
  ASSERT_TRUE(port.sample(start + 3.0, s, &error)) << error;
  EXPECT_DOUBLE_EQ(s[0].position, 0.5);
  EXPECT_DOUBLE_EQ(s[1].position, -0.3);
  EXPECT_DOUBLE_EQ(s[0].velocity, 0.0);
  // What the tick itself runs: the state port's desired position (within a tick's travel).
  rig.tick(200);
  const auto state = rig.state();
  ASSERT_TRUE(port.sample(rig.time, s, &error)) << error;
  EXPECT_NEAR(s[0].position, state.desired.positions[0], 0.002);

  ASSERT_TRUE(rig.manager->switch_controllers({}, {"c"}, SwitchStrictness::Strict).ok);
  rig.tick(1);
  EXPECT_FALSE(port.sample(rig.time, s, &error));
  EXPECT_THAT(error, HasSubstr("not running"));
}

TEST(JointTrajectoryController, StopTrajectoryDurationBringsTheJointsToRestSmoothly) {
  std::string yaml = kTwoJoints;
  yaml += "  stop_trajectory_duration: 0.5\n";
  Rig rig(2, yaml);
  rig.start();
  const GoalSubmission s = rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 2.0));
  rig.tick(1000);
  const auto before = rig.state();
  ASSERT_GT(before.actual.velocities[0], 0.3);
  ASSERT_TRUE(rig.goals().cancel(s.id));
  rig.tick(1);
  const auto at = rig.state();
  // Starts from the measured state (no jump in position or velocity)...
  EXPECT_NEAR(at.desired.positions[0], before.actual.positions[0], 2e-3);
  EXPECT_NEAR(at.desired.velocities[0], before.actual.velocities[0], 2e-2);
  rig.tick(600);
  // ... and is at rest after the stop duration, about v * T / 2 further on.
  const auto after = rig.state();
  EXPECT_DOUBLE_EQ(after.desired.velocities[0], 0.0);
  EXPECT_NEAR(after.desired.positions[0], before.actual.positions[0] + 0.5 * before.actual.velocities[0] * 0.5, 0.01);
  EXPECT_EQ(rig.goals().status(s.id), GoalStatus::Preempted);
}

TEST(JointTrajectoryController, RefusesGoalsWhileNotRunning) {
  Rig rig(2, kTwoJoints);
  ASSERT_TRUE(rig.manager->load_controller("c").ok);
  const GoalSubmission s = rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 2.0));
  EXPECT_FALSE(s.accepted);
  EXPECT_THAT(s.result.error_string, HasSubstr("not running"));
  ASSERT_TRUE(rig.manager->switch_controllers({"c"}, {}, SwitchStrictness::Strict).ok);
  rig.tick(1);
  EXPECT_TRUE(rig.goals().submit(move({"j0", "j1"}, {1.0, 1.0}, 2.0)).accepted);
}

TEST(JointTrajectoryController, GoalsFromAnotherThreadWhileTicking) {
  Rig rig(2, kTwoJoints);
  rig.start();
  std::vector<std::uint64_t> ids;
  std::atomic<bool> done{false};
  std::thread client([&] {
    for (int k = 0; k < 200; ++k) {
      const GoalSubmission s = rig.goals().submit(move({"j0", "j1"}, {0.001 * k, -0.001 * k}, 0.05));
      if (s.accepted) ids.push_back(s.id);
      if (k % 3 == 0) (void)rig.goals().cancel(s.id);
      (void)rig.goals().feedback();
      (void)rig.goals().status(s.id);
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    done = true;
  });
  while (!done) rig.tick(1);
  client.join();
  rig.tick(1000);
  ASSERT_EQ(ids.size(), 200u);
  int succeeded = 0;
  for (std::uint64_t id : ids) {
    const auto st = rig.goals().status(id);
    ASSERT_TRUE(st.has_value());
    EXPECT_TRUE(goal_finished(*st)) << id << ": " << goal_status_name(*st);
    succeeded += *st == GoalStatus::Succeeded;
  }
  EXPECT_EQ(rig.goals().status(ids.back()).value_or(GoalStatus::Pending) == GoalStatus::Succeeded ||
                rig.goals().status(ids.back()).value_or(GoalStatus::Pending) == GoalStatus::Preempted,
            true);
  EXPECT_NEAR(rig.state().desired.positions[0], 0.199, 1e-9);  // the last goal's end (not canceled: 199 % 3 != 0)
  EXPECT_GE(succeeded, 1);
}

TEST(JointTrajectoryController, AGoalThatIsStaleWhenTheTickTakesItIsRejectedAndTheActiveOneGoesOn) {
  Rig rig(2, kTwoJoints);
  rig.start();
  const GoalSubmission a = rig.goals().submit(move({"j0", "j1"}, {0.5, 0.5}, 3.0));
  rig.tick(999);  // the last update ran at t = 0.999 s
  auto stale = move({"j0", "j1"}, {-1.0, -1.0}, 0.0004);
  stale.trajectory.start_time = 0.9995;  // ends at 0.9999 s: after the last update, before the next
  const GoalSubmission b = rig.goals().submit(stale);
  ASSERT_TRUE(b.accepted) << b.result.error_string;
  rig.tick(1);
  EXPECT_EQ(rig.goals().status(b.id), GoalStatus::Rejected);
  const auto result = rig.goals().result(b.id);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->error_code, TrajectoryResultCode::OldHeaderTimestamp);
  EXPECT_THAT(result->error_string, HasSubstr("OLD_HEADER_TIMESTAMP"));
  EXPECT_EQ(rig.goals().status(a.id), GoalStatus::Active);
  rig.tick(3000);
  EXPECT_EQ(rig.goals().status(a.id), GoalStatus::Succeeded);
}

TEST(JointTrajectoryController, ConfigurationErrorsNameTheParameter) {
  Rig rig(2, R"(
nogains: {type: effort_controllers/JointTrajectoryController, joints: [j0]}
badjoint: {type: position_controllers/JointTrajectoryController, joints: [j0, elbow]}
badmax: {type: position_controllers/JointTrajectoryController, joints: [j0], max_trajectory_points: 0}
badrate: {type: position_controllers/JointTrajectoryController, joints: [j0], state_publish_rate: -1}
badiface: {type: joint_trajectory_controller/JointTrajectoryController, joints: [j0], hardware_interface: Torque}
)");
  const auto expect_error = [&](const char* name, const char* text) {
    const ControlResult r = rig.manager->load_controller(name);
    EXPECT_FALSE(r.ok) << name;
    EXPECT_THAT(r.error, HasSubstr(text)) << name;
  };
  expect_error("nogains", "/nogains/gains/j0");
  expect_error("badjoint", "elbow");
  expect_error("badmax", "/badmax/max_trajectory_points");
  expect_error("badrate", "/badrate/state_publish_rate");
  expect_error("badiface", "/badiface/hardware_interface");
}

TEST(JointTrajectoryController, RegisteredUnderTheirRosNames) {
  ControllerRegistry r;
  register_builtin_controllers(r);
  for (const char* type : {"effort_controllers/JointTrajectoryController", "position_controllers/JointTrajectoryController",
                           "velocity_controllers/JointTrajectoryController", "joint_trajectory_controller/JointTrajectoryController",
                           "robot_mechanism_controllers/JointTrajectoryActionController"}) {
    auto c = r.create(type);
    ASSERT_NE(c, nullptr) << type;
    EXPECT_NE(dynamic_cast<JointTrajectoryController*>(c.get()), nullptr) << type;
  }
}

}  // namespace
}  // namespace mechsim::control
