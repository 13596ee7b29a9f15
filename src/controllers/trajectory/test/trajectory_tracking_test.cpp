// Tracking with each variant of the trajectory controller on the ideal plants of
// test_robot.hpp at 1 kHz: the issue's acceptance (7 joints, 5 s, 4 waypoints: RMS tracking error
// < 0.01 rad per joint, final position within the goal tolerance) for the effort and PR2 types,
// and the position and velocity variants.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"
#include "controllers/trajectory/trajectory_controller.hpp"

namespace mechsim::control {
namespace {

constexpr int kJoints = 7;
constexpr double kGoalTolerance = 0.01;  // rad

std::vector<std::string> joint_names() {
  std::vector<std::string> names;
  for (int i = 0; i < kJoints; ++i) names.push_back(std::string("j").append(std::to_string(i)));
  return names;
}

// 4 waypoints over 5 s, different per joint, with velocities as a planner would give them (the
// mean of the neighbouring slopes; at rest at the end): cubic segments.
JointTrajectory waypoints() {
  JointTrajectory t;
  t.joint_names = joint_names();
  const double times[4] = {1.25, 2.5, 3.75, 5.0};
  std::vector<std::vector<double>> p(4, std::vector<double>(kJoints));
  for (int j = 0; j < kJoints; ++j) {
    const double a = 0.3 + 0.1 * j;
    p[0][j] = a;
    p[1][j] = -0.5 * a + 0.05 * j;
    p[2][j] = 0.8 * a - 0.1;
    p[3][j] = 0.2 * j - 0.6;
  }
  for (int k = 0; k < 4; ++k) {
    TrajectoryPoint pt;
    pt.positions = p[k];
    pt.time_from_start = times[k];
    pt.velocities.assign(kJoints, 0.0);
    if (k < 3) {
      for (int j = 0; j < kJoints; ++j) {
        const double prev = k == 0 ? 0.0 : p[k - 1][j];
        const double t_prev = k == 0 ? 0.0 : times[k - 1];
        const double slope_in = (p[k][j] - prev) / (times[k] - t_prev);
        const double slope_out = (p[k + 1][j] - p[k][j]) / (times[k + 1] - times[k]);
        pt.velocities[j] = 0.5 * (slope_in + slope_out);
      }
    }
    t.points.push_back(pt);
  }
  return t;
}

struct Tracking {
  std::vector<double> rms;        // rad, per joint, over the 5 s
  std::vector<double> final_error;  // rad, desired end - actual, after the trajectory
  GoalStatus status = GoalStatus::Pending;
};

// Runs the 5 s goal on the controller "c" of `yaml` and measures the tracking error against the
// desired state the controller reports every tick.
Tracking track(const std::string& yaml, const std::string& label) {
  auto robot = testing::make_robot(kJoints);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(yaml),
                            builtin_controller_registry());
  Tracking out;
  if (!manager.load_controller("c").ok || !manager.switch_controllers({"c"}, {}, SwitchStrictness::Strict).ok) {
    ADD_FAILURE() << "could not start " << label;
    return out;
  }
  double time = testing::run(manager, *robot, 0.0, 1);
  auto* goals = manager.controller("c")->port_as<TrajectoryGoalPort>("follow_joint_trajectory");
  auto* state = manager.controller("c")->port_as<StatePort<JointTrajectoryControllerState>>("state");
  FollowJointTrajectoryGoal goal;
  goal.trajectory = waypoints();
  const GoalSubmission s = goals->submit(goal);
  EXPECT_TRUE(s.accepted) << s.result.error_string;
  std::vector<double> sum(kJoints, 0.0);
  int samples = 0;
  for (int k = 0; k < 5000; ++k) {
    time = testing::run(manager, *robot, time, 1);
    const auto st = state->read();
    for (int j = 0; j < kJoints; ++j) {
      const double e = st.desired.positions[j] - robot->state.joints[j].position;
      sum[j] += e * e;
    }
    ++samples;
  }
  time = testing::run(manager, *robot, time, 1000);
  out.status = goals->status(s.id).value_or(GoalStatus::Pending);
  const TrajectoryPoint& last = goal.trajectory.points.back();
  for (int j = 0; j < kJoints; ++j) {
    out.rms.push_back(std::sqrt(sum[j] / samples));
    out.final_error.push_back(last.positions[j] - robot->state.joints[j].position);
    std::printf("[ %s ] joint j%d: RMS tracking error %.3g rad, final error %.3g rad\n", label.c_str(), j, out.rms[j],
                out.final_error[j]);
  }
  return out;
}

std::string config(const std::string& type, const std::string& gains, bool pr2 = false) {
  std::ostringstream y;
  y << "c:\n  type: " << type << "\n  joints: [j0, j1, j2, j3, j4, j5, j6]\n  state_publish_rate: 0\n";
  if (!gains.empty()) {
    y << "  gains:\n";
    for (const auto& n : joint_names()) y << "    " << n << ": " << gains << "\n";
  }
  y << (pr2 ? "  joint_trajectory_action_node:\n    constraints:\n" : "  constraints:\n");
  const std::string indent = pr2 ? "      " : "    ";
  y << indent << "goal_time: 0.6\n";
  for (const auto& n : joint_names()) y << indent << n << ": {goal: " << kGoalTolerance << "}\n";
  return y.str();
}

void expect_acceptance(const Tracking& t) {
  ASSERT_EQ(t.rms.size(), static_cast<std::size_t>(kJoints));
  EXPECT_EQ(t.status, GoalStatus::Succeeded);
  for (int j = 0; j < kJoints; ++j) {
    EXPECT_LT(t.rms[j], 0.01) << "joint j" << j;
    EXPECT_LT(std::fabs(t.final_error[j]), kGoalTolerance) << "joint j" << j;
  }
}

TEST(TrajectoryTracking, EffortControllerMeetsTheAcceptanceOnUnitInertias) {
  const Tracking t = track(config("effort_controllers/JointTrajectoryController", "{p: 2500, d: 100}"), "effort");
  expect_acceptance(t);
}

TEST(TrajectoryTracking, Pr2JointTrajectoryActionControllerMeetsTheAcceptance) {
  const Tracking t = track(config("robot_mechanism_controllers/JointTrajectoryActionController",
                                  "{p: 2400.0, d: 100.0, i: 800.0, i_clamp: 4.0}", true),
                           "pr2");
  expect_acceptance(t);
}

TEST(TrajectoryTracking, PositionControllerCommandsTheDesiredPosition) {
  const Tracking t = track(config("position_controllers/JointTrajectoryController", ""), "position");
  expect_acceptance(t);
  // With an ideal position servo the joint is one tick behind at most: v_max x 1 ms.
  for (double r : t.rms) EXPECT_LT(r, 2e-3);
}

TEST(TrajectoryTracking, VelocityControllerTracksWithPidAndFeedForward) {
  std::string yaml = config("velocity_controllers/JointTrajectoryController", "{p: 50, d: 0}");
  yaml += "  velocity_ff: {j0: 1, j1: 1, j2: 1, j3: 1, j4: 1, j5: 1, j6: 1}\n";
  const Tracking t = track(yaml, "velocity");
  expect_acceptance(t);
}

TEST(TrajectoryTracking, Pr2ReportsErrorsAsActualMinusDesiredAndReadsItsNodeConstraints) {
  auto robot = testing::make_robot(1);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(R"(
c:
  type: robot_mechanism_controllers/JointTrajectoryActionController
  joints: [j0]
  gains: {j0: {p: 100, d: 20}}
  state_publish_rate: 0
  joint_trajectory_action_node:
    joints: [j0]
    constraints: {goal_time: 0.1, j0: {trajectory: 0.05, goal: 0.0001}}
)"), builtin_controller_registry());
  ASSERT_TRUE(manager.load_controller("c").ok);
  ASSERT_TRUE(manager.switch_controllers({"c"}, {}, SwitchStrictness::Strict).ok);
  double time = testing::run(manager, *robot, 0.0, 1);
  auto* goals = manager.controller("c")->port_as<TrajectoryGoalPort>("follow_joint_trajectory");
  FollowJointTrajectoryGoal goal;
  goal.trajectory.joint_names = {"j0"};
  goal.trajectory.points = {{{0.3}, {0.0}, {}, {}, 1.0}};
  const GoalSubmission s = goals->submit(goal);
  time = testing::run(manager, *robot, time, 300);
  const auto st = manager.controller("c")->port_as<StatePort<JointTrajectoryControllerState>>("state")->read();
  EXPECT_GT(st.desired.positions[0], st.actual.positions[0]);  // lagging on the way up
  EXPECT_NEAR(st.error.positions[0], st.actual.positions[0] - st.desired.positions[0], 1e-12);
  EXPECT_LT(st.error.positions[0], 0.0);
  time = testing::run(manager, *robot, time, 1500);
  // The node's goal tolerance (0.1 mm) is too tight for these gains within 0.1 s.
  EXPECT_EQ(goals->status(s.id), GoalStatus::Aborted);
  EXPECT_EQ(goals->result(s.id)->error_code, TrajectoryResultCode::GoalToleranceViolated);
}

TEST(TrajectoryTracking, GenericTypeTakesItsInterfaceFromTheParameters) {
  auto robot = testing::make_robot(2);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(R"(
a: {type: joint_trajectory_controller/JointTrajectoryController, joints: [j0], hardware_interface: hardware_interface/PositionJointInterface}
b: {type: joint_trajectory_controller/JointTrajectoryController, joints: [j1], command_interfaces: [velocity], gains: {j1: {p: 1}}}
)"), builtin_controller_registry());
  ASSERT_TRUE(manager.load_controller("a").ok);
  ASSERT_TRUE(manager.load_controller("b").ok);
  EXPECT_EQ(manager.controller_info("a")->claims.at(0).interface, HardwareInterface::Position);
  EXPECT_EQ(manager.controller_info("b")->claims.at(0).interface, HardwareInterface::Velocity);
}

}  // namespace
}  // namespace mechsim::control
