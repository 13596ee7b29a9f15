#pragma once
// control_msgs/GripperCommandAction over a gripper controller's goal port (a
// control::GripperGoalPort), as ros_controllers' gripper_action_controller serves it at
// <controller>/gripper_cmd: SUCCEEDED with reached_goal once within goal_tolerance; ABORTED with
// stalled = true when the joint stops short of the goal for stall_timeout (the gripper keeps
// squeezing at max_effort); PREEMPTED by a cancel or a newer goal. Result and feedback carry
// position, effort, stalled, reached_goal. A PolledActionServer policy (polled_action_server.hpp).

#include <cstdint>
#include <optional>
#include <string>

#include <control_msgs/GripperCommandAction.h>

#include "ros/bridge_names.hpp"
#include "ros/polled_action_server.hpp"

namespace mechsim::ros {

class ControlGripperPolicy {
 public:
  using Action = control_msgs::GripperCommandAction;
  using Result = control_msgs::GripperCommandResult;
  using Outcome = GripperStateData;

  PolicySubmission<Result> submit(const PortRef& port, const control_msgs::GripperCommandGoal& goal);
  bool cancel(const PortRef& port, std::uint64_t id) { return cancel_gripper_goal(port, id); }
  std::optional<control::GoalStatus> status(const PortRef& port, std::uint64_t id) {
    return gripper_goal_status(port, id).value_or(control::GoalStatus::Aborted);
  }
  Outcome outcome(const PortRef& port, std::uint64_t id) { return gripper_goal_result(port, id).value_or(Outcome{}); }
  bool read_feedback(const PortRef& port, std::uint64_t& goal_id) {
    return read_gripper_feedback(port, feedback_, &goal_id, &feedback_sequence_);
  }
  control_msgs::GripperCommandFeedback feedback() const;
  static Result result(const Outcome& outcome);
  static std::string text(control::GoalStatus, const Outcome&) { return {}; }  // ros_controllers sets none
  static Result unloaded_result() { return {}; }

 private:
  std::uint64_t feedback_sequence_ = 0;
  GripperStateData feedback_;
};

using ControlGripperActionServer = PolledActionServer<ControlGripperPolicy>;
extern template class PolledActionServer<ControlGripperPolicy>;

}  // namespace mechsim::ros
