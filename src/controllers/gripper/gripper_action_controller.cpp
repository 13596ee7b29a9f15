#include "controllers/gripper/gripper_action_controller.hpp"

#include <algorithm>
#include <cmath>

#include "controllers/param_checks.hpp"

namespace mechsim::control {

bool GripperActionController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string joint_path = join_param_path(params.path(), "joint");
  if (!params.has("joint")) throw ControllerConfigError("no joint given: parameter " + joint_path + " not found");
  const std::string joint = params.get<std::string>("joint");
  joint_ = hardware.claim_joint(joint, iface_, joint_path);
  if (iface_ == HardwareInterface::Effort) pid_.init(params, "gains/" + joint);
  goal_tolerance_ = non_negative_param(params, "goal_tolerance", 0.01);
  default_max_effort_ = non_negative_param(params, "max_effort", 0.0);
  stall_velocity_threshold_ = non_negative_param(params, "stall_velocity_threshold", 0.001);
  stall_timeout_ = non_negative_param(params, "stall_timeout", 1.0);
  state_.init(JointControllerState{});
  return true;
}

void GripperActionController::hold(double time) noexcept {
  command_ = {joint_.position(), default_max_effort_};
  last_movement_ = time;
}

void GripperActionController::starting(double time) {
  hold(time);
  GripperGoalRequest ignored;
  (void)goals_.take_from_rt(ignored);  // a goal sent before the start is not run
  goal_id_ = 0;
  pid_.reset();
  computed_command_ = 0.0;
  goals_.set_running_from_rt(true);
}

void GripperActionController::stopping(double /*time*/) {
  goals_.set_running_from_rt(false);
  if (goal_id_ != 0) finish_goal(GoalStatus::Preempted);
}

void GripperActionController::finish_goal(GoalStatus status) noexcept {
  goals_.report_from_rt({goal_id_, status, result_});
  goal_id_ = 0;
}

UpdateStatus GripperActionController::update(double time, double period) {
  GripperGoalRequest request;
  if (goals_.take_from_rt(request)) {
    if (goal_id_ != 0) finish_goal(GoalStatus::Preempted);
    goal_id_ = last_goal_id_ = request.id;
    command_ = request.command;
    last_movement_ = time;
    goals_.report_from_rt({goal_id_, GoalStatus::Active, {}});
  }
  if (goal_id_ != 0 && goals_.cancel_request_from_rt() == goal_id_) {
    finish_goal(GoalStatus::Preempted);
    hold(time);
  }

  const double position = joint_.position(), velocity = joint_.velocity();
  const double error = command_.position - position;
  // 1. Goal monitoring (the result's effort is the previous command, as ros_controllers').
  result_.position = position;
  result_.effort = computed_command_;
  result_.reached_goal = std::abs(error) < goal_tolerance_;
  result_.stalled = false;
  if (std::abs(velocity) > stall_velocity_threshold_) {
    last_movement_ = time;
  } else if (!result_.reached_goal && time - last_movement_ > stall_timeout_) {
    result_.stalled = true;
  }
  if (goal_id_ != 0) {
    if (result_.reached_goal) finish_goal(GoalStatus::Succeeded);
    else if (result_.stalled) finish_goal(GoalStatus::Aborted);
  }

  // 2. The command.
  const double max_effort = std::abs(command_.max_effort);
  if (iface_ == HardwareInterface::Position) {
    joint_.set_command(command_.position);
    computed_command_ = max_effort;
  } else {
    double effort = period > 0.0 ? pid_.compute_command(error, -velocity, period) : 0.0;
    effort = std::clamp(std::isfinite(effort) ? effort : 0.0, -max_effort, max_effort);
    joint_.set_command(effort);
    computed_command_ = effort;
  }

  state_.publish_from_rt([&](JointControllerState& s) {
    s.stamp = time;
    s.set_point = command_.position;
    s.process_value = position;
    s.process_value_dot = velocity;
    s.error = error;
    s.time_step = period;
    s.command = computed_command_;
    s.gains = pid_.rt_gains();
  });
  goals_.publish_feedback_from_rt([&](GripperFeedback& f) {
    f.stamp = time;
    f.goal_id = last_goal_id_;
    f.state = result_;
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
