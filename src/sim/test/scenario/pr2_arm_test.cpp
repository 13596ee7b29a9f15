// The PR2's right arm under its default r_arm_controller (robot_mechanism_controllers/
// JointTrajectoryActionController, published PR2 gains): a 5 s trajectory of the 7 joints through
// 4 waypoints, submitted through the controller's goal port, is followed with an RMS error under
// 0.01 rad per joint and ends within the goal tolerance (0.02 rad per joint); a fast move under a tight path
// tolerance aborts with PATH_TOLERANCE_VIOLATED. Simulated time: 8.6 s + 2.5 s.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "controllers/trajectory/trajectory_controller.hpp"
#include "sim/test/scenario/pr2_util.hpp"

namespace mechsim::sim {
namespace {

const std::vector<std::string> kJoints = {"r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
                                          "r_elbow_flex_joint",   "r_forearm_roll_joint",  "r_wrist_flex_joint",
                                          "r_wrist_roll_joint"};

// Waypoints (rad) inside the PR2's joint limits, at 1.25 s intervals.
const std::vector<std::vector<double>> kWaypoints = {
    {-0.3, 0.2, -0.3, -0.5, 0.3, -0.4, 0.3},
    {-0.6, 0.4, -0.6, -1.0, 0.6, -0.8, 0.6},
    {-0.3, 0.1, -0.3, -0.6, 0.2, -0.5, 0.2},
    {-0.1, 0.0, -0.1, -0.3, 0.0, -0.3, 0.0},
};

// Cubic segments: the velocity at an inner waypoint is the slope between its neighbours; the
// arm starts and ends at rest.
control::FollowJointTrajectoryGoal arm_goal(const std::vector<double>& start) {
  control::FollowJointTrajectoryGoal goal;
  goal.trajectory.joint_names = kJoints;
  const double dt = 1.25;
  for (std::size_t k = 0; k < kWaypoints.size(); ++k) {
    control::TrajectoryPoint p;
    p.positions = kWaypoints[k];
    p.time_from_start = dt * static_cast<double>(k + 1);
    for (std::size_t j = 0; j < kJoints.size(); ++j) {
      if (k + 1 == kWaypoints.size()) {
        p.velocities.push_back(0.0);
      } else {
        const double before = k == 0 ? start[j] : kWaypoints[k - 1][j];
        p.velocities.push_back((kWaypoints[k + 1][j] - before) / (2.0 * dt));
      }
    }
    goal.trajectory.points.push_back(p);
  }
  return goal;
}

TEST(Pr2Arm, FollowsA5sTrajectoryThrough4WaypointsWithin10mradRms) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  auto sim = make_pr2_simulation({"r_arm_controller", "l_arm_controller", "torso_controller", "head_traj_controller", "base_controller"});
  ASSERT_TRUE(sim->run_for(0.1));
  auto& arm = pr2_controller<control::JointTrajectoryController>(*sim, "r_arm_controller");
  // The arm spawns with its elbow and wrist flexed to 0, beyond their soft limits (-0.15 and
  // -0.1 rad), where the safety controller fights any command: move to the last waypoint first.
  {
    control::FollowJointTrajectoryGoal to_start;
    to_start.trajectory.joint_names = kJoints;
    control::TrajectoryPoint p;
    p.positions = kWaypoints.back();
    p.velocities.assign(kJoints.size(), 0.0);
    p.time_from_start = 1.5;
    to_start.trajectory.points.push_back(p);
    ASSERT_TRUE(arm.goal_port().submit(to_start).accepted);
    ASSERT_TRUE(sim->run_for(2.5));
  }
  std::vector<double> start;
  for (const std::string& j : kJoints) start.push_back(sim->physics().position(pr2_physics_joint(*sim, j)));

  std::vector<double> sum_sq(kJoints.size(), 0.0), worst(kJoints.size(), 0.0);
  std::size_t samples = 0;
  std::uint64_t seen = arm.state_port().sequence();
  bool tracking = false;
  sim->add_observer([&](const Simulation&) {
    if (!tracking || arm.state_port().sequence() == seen) return;
    seen = arm.state_port().sequence();
    const control::JointTrajectoryControllerState s = arm.state_port().read();
    for (std::size_t j = 0; j < kJoints.size(); ++j) {
      const double e = s.desired.positions[j] - s.actual.positions[j];
      sum_sq[j] += e * e;
      worst[j] = std::max(worst[j], std::abs(e));
    }
    ++samples;
  });
  const control::GoalSubmission goal = arm.goal_port().submit(arm_goal(start));
  ASSERT_TRUE(goal.accepted) << goal.result.error_string;
  tracking = true;
  ASSERT_TRUE(sim->run_for(5.0));
  tracking = false;
  ASSERT_TRUE(sim->run_for(1.0));  // goal_time 0.6 s

  ASSERT_GT(samples, 200u);  // 50 Hz state over 5 s
  std::cout << "[ figures  ] r_arm 5 s trajectory, " << samples << " samples; RMS / max error (rad):";
  for (std::size_t j = 0; j < kJoints.size(); ++j) {
    const double rms = std::sqrt(sum_sq[j] / static_cast<double>(samples));
    std::cout << "\n             " << kJoints[j] << " " << rms << " / " << worst[j];
    EXPECT_LT(rms, 0.01) << kJoints[j];
  }
  std::cout << "\n";
  // The controller's verdict: within the goal tolerance and stopped (the default
  // stopped_velocity_tolerance, 0.01 rad/s) within goal_time.
  const auto result = arm.goal_port().result(goal.id);
  ASSERT_TRUE(result.has_value());
  std::cout << "[ figures  ] goal result: " << control::result_code_name(result->error_code) << " "
            << result->error_string << "\n";
  EXPECT_EQ(result->error_code, control::TrajectoryResultCode::Successful);
  for (std::size_t j = 0; j < kJoints.size(); ++j) {
    const double final_error = sim->physics().position(pr2_physics_joint(*sim, kJoints[j])) - kWaypoints.back()[j];
    std::cout << "[ figures  ] " << kJoints[j] << " final error " << final_error << " rad\n";
    EXPECT_LT(std::abs(final_error), 0.02) << kJoints[j];  // the controller's goal tolerance
  }
}

// The elbow asked to move 1 rad in 0.2 s with a path tolerance of 0.05 rad: the arm cannot follow
// and the goal aborts with PATH_TOLERANCE_VIOLATED; the arm then holds where it was.
TEST(Pr2Arm, AFastMoveUnderATightPathToleranceAbortsWithPathToleranceViolated) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  auto sim = make_pr2_simulation({"r_arm_controller"});
  ASSERT_TRUE(sim->run_for(0.5));
  auto& arm = pr2_controller<control::JointTrajectoryController>(*sim, "r_arm_controller");
  control::FollowJointTrajectoryGoal goal;
  goal.trajectory.joint_names = kJoints;
  control::TrajectoryPoint p;
  for (const std::string& j : kJoints) p.positions.push_back(sim->physics().position(pr2_physics_joint(*sim, j)));
  p.positions[3] -= 1.0;  // elbow flex
  p.time_from_start = 0.2;
  goal.trajectory.points.push_back(p);
  for (const std::string& j : kJoints) goal.path_tolerance.push_back({j, 0.05, 0.0, 0.0});
  const control::GoalSubmission g = arm.goal_port().submit(goal);
  ASSERT_TRUE(g.accepted) << g.result.error_string;
  ASSERT_TRUE(sim->run_for(2.0));
  EXPECT_EQ(arm.goal_port().status(g.id), control::GoalStatus::Aborted);
  const auto result = arm.goal_port().result(g.id);
  ASSERT_TRUE(result.has_value());
  std::cout << "[ figures  ] fast elbow move: " << control::result_code_name(result->error_code) << ": "
            << result->error_string << "\n";
  EXPECT_EQ(result->error_code, control::TrajectoryResultCode::PathToleranceViolated);
}

}  // namespace
}  // namespace mechsim::sim
