#include "ros/gripper_command_action.hpp"

namespace mechsim::ros {
namespace {

// GripperCommandResult and GripperCommandFeedback have the same four fields.
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

PolicySubmission<ControlGripperPolicy::Result> ControlGripperPolicy::submit(const PortRef& port,
                                                                            const control_msgs::GripperCommandGoal& goal) {
  GripperTicket ticket;
  PolicySubmission<Result> s;
  s.accepted = submit_gripper_goal(port, goal.command.position, goal.command.max_effort, ticket) && ticket.accepted;
  s.id = ticket.id;
  if (!s.accepted) s.text = ticket.error;
  return s;
}

control_msgs::GripperCommandFeedback ControlGripperPolicy::feedback() const {
  return gripper_msg<control_msgs::GripperCommandFeedback>(feedback_);
}

ControlGripperPolicy::Result ControlGripperPolicy::result(const Outcome& outcome) { return gripper_msg<Result>(outcome); }

template class PolledActionServer<ControlGripperPolicy>;

}  // namespace mechsim::ros
