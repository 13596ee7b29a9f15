#include "ros/trajectory_action.hpp"

namespace mechsim::ros {

namespace {

control::TrajectoryPoint from_msg(const trajectory_msgs::JointTrajectoryPoint& p) {
  control::TrajectoryPoint out;
  out.positions = p.positions;
  out.velocities = p.velocities;
  out.accelerations = p.accelerations;
  out.effort = p.effort;
  out.time_from_start = p.time_from_start.toSec();
  return out;
}

std::vector<control::JointTolerance> from_msg(const std::vector<control_msgs::JointTolerance>& list) {
  std::vector<control::JointTolerance> out;
  for (const auto& t : list) out.push_back({t.name, t.position, t.velocity, t.acceleration});
  return out;
}

}  // namespace

control::JointTrajectory from_msg(const trajectory_msgs::JointTrajectory& msg) {
  control::JointTrajectory out;
  out.start_time = msg.header.stamp.toSec();
  out.joint_names = msg.joint_names;
  for (const auto& p : msg.points) out.points.push_back(from_msg(p));
  return out;
}

trajectory_msgs::JointTrajectoryPoint to_msg(const control::TrajectoryPointState& p) {
  trajectory_msgs::JointTrajectoryPoint out;
  out.positions = p.positions;
  out.velocities = p.velocities;
  out.accelerations = p.accelerations;
  out.time_from_start = ::ros::Duration(p.time_from_start);
  return out;
}

PolicySubmission<FollowJointTrajectoryPolicy::Result> FollowJointTrajectoryPolicy::submit(
    const PortRef& port, const control_msgs::FollowJointTrajectoryGoal& goal) {
  control::FollowJointTrajectoryGoal g;
  g.trajectory = from_msg(goal.trajectory);
  g.path_tolerance = from_msg(goal.path_tolerance);
  g.goal_tolerance = from_msg(goal.goal_tolerance);
  g.goal_time_tolerance = goal.goal_time_tolerance.toSec();
  GoalTicket ticket;
  PolicySubmission<Result> s;
  s.accepted = submit_goal(port, g, ticket) && ticket.accepted;
  s.id = ticket.id;
  if (!s.accepted) {
    s.result = result(ticket.result);
    s.text = ticket.result.error_string;
  }
  return s;
}

bool FollowJointTrajectoryPolicy::read_feedback(const PortRef& port, std::uint64_t& goal_id) {
  if (!read_goal_feedback(port, feedback_, &feedback_sequence_)) return false;
  goal_id = feedback_.goal_id;
  return true;
}

FollowJointTrajectoryPolicy::Result FollowJointTrajectoryPolicy::result(const Outcome& outcome) {
  Result out;
  out.error_code = static_cast<int>(outcome.error_code);
  out.error_string = outcome.error_string;
  return out;
}

FollowJointTrajectoryPolicy::Result FollowJointTrajectoryPolicy::unloaded_result() {
  Result out;
  out.error_code = Result::INVALID_GOAL;
  out.error_string = "the controller was unloaded";
  return out;
}

template class PolledActionServer<FollowJointTrajectoryPolicy>;

}  // namespace mechsim::ros
