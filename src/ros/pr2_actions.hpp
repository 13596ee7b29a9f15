#pragma once
// The PR2's own action interfaces over the controllers' goal ports, beside the generic
// follow_joint_trajectory (trajectory_action.hpp), as PolledActionServer policies: goals are
// submitted to the port at once, and a wall timer (20 Hz) relays feedback and finishes goal
// handles as the tick reports them.
//
//   Pr2TrajectoryActionServer  <controller>/joint_trajectory_action
//       pr2_controllers_msgs/JointTrajectoryAction of robot_mechanism_controllers/
//       JointTrajectoryActionController: the goal is a bare trajectory checked against the
//       controller's own constraints (joint_trajectory_action_node/constraints); the result is
//       empty. SUCCEEDED when the joints are within the goal constraints by the end time plus
//       goal_time; ABORTED on a violated constraint or a late goal; PREEMPTED by a newer goal or
//       a `command` trajectory; REJECTED when the controller refuses it (wrong joints, stopped).
//   GripperActionServer        <gripper>/gripper_action
//       pr2_controllers_msgs/Pr2GripperCommandAction with pr2_gripper_action's semantics:
//       SUCCEEDED with reached_goal = true once the gap is within goal_threshold; ABORTED with
//       stalled = true when the gap stops moving short of it (the gripper keeps squeezing);
//       PREEMPTED by a cancel, a newer goal or a plain `command`. Feedback: position, effort,
//       stalled, reached_goal at the timer's rate.

#include <cstdint>
#include <optional>
#include <string>

#include <pr2_controllers_msgs/JointTrajectoryAction.h>
#include <pr2_controllers_msgs/Pr2GripperCommandAction.h>

#include "ros/bridge_names.hpp"
#include "ros/polled_action_server.hpp"
#include "ros/trajectory_action.hpp"

namespace mechsim::ros {

// joint_trajectory_action over the controller's follow_joint_trajectory goal port (a
// control::TrajectoryGoalPort). No feedback; a goal the port no longer knows is aborted.
class Pr2JointTrajectoryPolicy : public TrajectoryGoalPortPolicy {
 public:
  using Action = pr2_controllers_msgs::JointTrajectoryAction;
  using Result = pr2_controllers_msgs::JointTrajectoryResult;

  PolicySubmission<Result> submit(const PortRef& port, const pr2_controllers_msgs::JointTrajectoryGoal& goal);
  std::optional<control::GoalStatus> status(const PortRef& port, std::uint64_t id) {
    return goal_status(port, id).value_or(control::GoalStatus::Aborted);
  }
  bool read_feedback(const PortRef&, std::uint64_t&) { return false; }
  pr2_controllers_msgs::JointTrajectoryFeedback feedback() const { return {}; }
  static Result result(const Outcome&) { return {}; }  // empty, as the PR2's
  static Result unloaded_result() { return {}; }
};

// gripper_action over the gripper controller's gripper_action goal port (a
// control::GripperGoalPort). A goal the port no longer knows is aborted.
class Pr2GripperPolicy {
 public:
  using Action = pr2_controllers_msgs::Pr2GripperCommandAction;
  using Result = pr2_controllers_msgs::Pr2GripperCommandResult;
  using Outcome = GripperStateData;

  PolicySubmission<Result> submit(const PortRef& port, const pr2_controllers_msgs::Pr2GripperCommandGoal& goal);
  bool cancel(const PortRef& port, std::uint64_t id) { return cancel_gripper_goal(port, id); }
  std::optional<control::GoalStatus> status(const PortRef& port, std::uint64_t id) {
    return gripper_goal_status(port, id).value_or(control::GoalStatus::Aborted);
  }
  Outcome outcome(const PortRef& port, std::uint64_t id) { return gripper_goal_result(port, id).value_or(Outcome{}); }
  bool read_feedback(const PortRef& port, std::uint64_t& goal_id) {
    return read_gripper_feedback(port, feedback_, &goal_id, &feedback_sequence_);
  }
  pr2_controllers_msgs::Pr2GripperCommandFeedback feedback() const;
  static Result result(const Outcome& outcome);
  // pr2_gripper_action says why it aborted: "stalled" short of the goal.
  static std::string text(control::GoalStatus status, const Outcome& outcome);
  static Result unloaded_result() { return {}; }

 private:
  std::uint64_t feedback_sequence_ = 0;
  GripperStateData feedback_;
};

using Pr2TrajectoryActionServer = PolledActionServer<Pr2JointTrajectoryPolicy>;
using GripperActionServer = PolledActionServer<Pr2GripperPolicy>;
extern template class PolledActionServer<Pr2JointTrajectoryPolicy>;
extern template class PolledActionServer<Pr2GripperPolicy>;

}  // namespace mechsim::ros
