#include "ros/pr2_actions.hpp"

namespace mechsim::ros {

namespace {

// Pr2GripperCommandResult and Pr2GripperCommandFeedback have the same four fields.
template <class Msg>
Msg gripper_msg(const GripperStateData& d) {
  Msg m;
  m.position = d.position;
  m.effort = d.effort;
  m.stalled = d.stalled;
  m.reached_goal = d.reached_goal;
  return m;
}

}  // namespace

// ---------------------------------------------------------------- joint_trajectory_action

PolicySubmission<Pr2JointTrajectoryPolicy::Result> Pr2JointTrajectoryPolicy::submit(
    const PortRef& port, const pr2_controllers_msgs::JointTrajectoryGoal& goal) {
  // No tolerances in the goal: the controller's constraints apply (as the PR2's).
  control::FollowJointTrajectoryGoal g;
  g.trajectory = from_msg(goal.trajectory);
  GoalTicket ticket;
  PolicySubmission<Result> s;
  s.accepted = submit_goal(port, g, ticket) && ticket.accepted;
  s.id = ticket.id;
  if (!s.accepted) s.text = ticket.result.error_string;
  return s;
}

template class PolledActionServer<Pr2JointTrajectoryPolicy>;

// ---------------------------------------------------------------- gripper_action

PolicySubmission<Pr2GripperPolicy::Result> Pr2GripperPolicy::submit(
    const PortRef& port, const pr2_controllers_msgs::Pr2GripperCommandGoal& goal) {
  GripperTicket ticket;
  PolicySubmission<Result> s;
  s.accepted = submit_gripper_goal(port, goal.command.position, goal.command.max_effort, ticket) && ticket.accepted;
  s.id = ticket.id;
  if (!s.accepted) s.text = ticket.error;
  return s;
}

pr2_controllers_msgs::Pr2GripperCommandFeedback Pr2GripperPolicy::feedback() const {
  return gripper_msg<pr2_controllers_msgs::Pr2GripperCommandFeedback>(feedback_);
}

Pr2GripperPolicy::Result Pr2GripperPolicy::result(const Outcome& outcome) { return gripper_msg<Result>(outcome); }

std::string Pr2GripperPolicy::text(control::GoalStatus status, const Outcome& outcome) {
  switch (status) {
    case control::GoalStatus::Succeeded:
    case control::GoalStatus::Preempted: return "";
    default: return outcome.stalled ? "stalled" : "";
  }
}

template class PolledActionServer<Pr2GripperPolicy>;

}  // namespace mechsim::ros
