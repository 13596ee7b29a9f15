#pragma once
// <controller>/follow_joint_trajectory: control_msgs/FollowJointTrajectoryAction over a trajectory
// controller's goal port (PolledActionServer: goals submitted at once, rejected goals answered
// with the controller's error code; feedback and results relayed at 20 Hz, wall; preempted ->
// canceled). Conversions between the ROS messages and controllers/trajectory/trajectory_msgs.hpp live here too.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/JointTrajectoryControllerState.h>
#include <trajectory_msgs/JointTrajectory.h>

#include "ros/bridge_names.hpp"
#include "ros/polled_action_server.hpp"

namespace mechsim::ros {

control::JointTrajectory from_msg(const trajectory_msgs::JointTrajectory& msg);
trajectory_msgs::JointTrajectoryPoint to_msg(const control::TrajectoryPointState& point);

// A message with the fields of control_msgs/JointTrajectoryControllerState (header, joint_names,
// desired, actual, error), as the controller state, the PR2's state message and the
// follow_joint_trajectory feedback have them.
template <class Msg>
Msg trajectory_state_msg(const control::JointTrajectoryControllerState& state) {
  Msg out;
  out.header.stamp = ::ros::Time(state.stamp);
  out.joint_names = state.joint_names;
  out.desired = to_msg(state.desired);
  out.actual = to_msg(state.actual);
  out.error = to_msg(state.error);
  return out;
}

inline control_msgs::JointTrajectoryControllerState to_msg(const control::JointTrajectoryControllerState& state) {
  return trajectory_state_msg<control_msgs::JointTrajectoryControllerState>(state);
}

// What the PolledActionServer policies over a control::TrajectoryGoalPort share
// (follow_joint_trajectory here, the PR2's joint_trajectory_action in pr2_actions.hpp).
class TrajectoryGoalPortPolicy {
 public:
  using Outcome = control::TrajectoryResult;

  bool cancel(const PortRef& port, std::uint64_t id) { return cancel_goal(port, id); }
  Outcome outcome(const PortRef& port, std::uint64_t id) { return goal_result(port, id).value_or(Outcome{}); }
  static std::string text(control::GoalStatus, const Outcome& outcome) { return outcome.error_string; }
};

// follow_joint_trajectory (the goal's tolerances apply). A goal the port no longer knows is
// polled again.
class FollowJointTrajectoryPolicy : public TrajectoryGoalPortPolicy {
 public:
  using Action = control_msgs::FollowJointTrajectoryAction;
  using Result = control_msgs::FollowJointTrajectoryResult;

  PolicySubmission<Result> submit(const PortRef& port, const control_msgs::FollowJointTrajectoryGoal& goal);
  std::optional<control::GoalStatus> status(const PortRef& port, std::uint64_t id) { return goal_status(port, id); }
  bool read_feedback(const PortRef& port, std::uint64_t& goal_id);
  control_msgs::FollowJointTrajectoryFeedback feedback() const {
    return trajectory_state_msg<control_msgs::FollowJointTrajectoryFeedback>(feedback_.state);
  }
  static Result result(const Outcome& outcome);
  static Result unloaded_result();

 private:
  std::uint64_t feedback_sequence_ = 0;
  control::FollowJointTrajectoryFeedback feedback_;
};

using TrajectoryActionServer = PolledActionServer<FollowJointTrajectoryPolicy>;
extern template class PolledActionServer<FollowJointTrajectoryPolicy>;

}  // namespace mechsim::ros
