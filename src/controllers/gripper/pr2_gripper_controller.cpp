#include "controllers/gripper/pr2_gripper_controller.hpp"

#include <cmath>

#include "controllers/param_checks.hpp"

namespace mechsim::control {

bool Pr2GripperController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string joint_path = join_param_path(params.path(), "joint");
  if (!params.has("joint")) throw ControllerConfigError("no joint given: parameter " + joint_path + " not found");
  joint_ = hardware.claim_joint(params.get<std::string>("joint"), HardwareInterface::Effort, joint_path);
  pid_.init(params, "pid");
  goal_threshold_ = non_negative_param(params, "goal_threshold", 0.01);
  stall_velocity_threshold_ = non_negative_param(params, "stall_velocity_threshold", 0.001);
  stall_timeout_ = non_negative_param(params, "stall_timeout", 0.1);
  initial_max_effort_ = params.get<double>("max_effort", -1.0);
  if (!std::isfinite(initial_max_effort_)) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "max_effort") + " is not finite");
  }
  state_.init(JointControllerState{});
  return true;
}

void Pr2GripperController::starting(double /*time*/) {
  active_ = {joint_.position(), initial_max_effort_};
  command_.reset_from_rt(active_);
  last_command_seq_ = command_.accepted();
  GripperGoalRequest ignored;
  (void)goals_.take_from_rt(ignored);  // a goal left from before the start is not run
  goal_id_ = 0;
  stall_time_ = 0.0;
  pid_.reset();
  goals_.set_running_from_rt(true);
}

void Pr2GripperController::stopping(double /*time*/) {
  goals_.set_running_from_rt(false);
  if (goal_id_ != 0) finish_goal(GoalStatus::Aborted);
}

void Pr2GripperController::finish_goal(GoalStatus status) noexcept {
  goals_.report_from_rt({goal_id_, status, result_});
  goal_id_ = 0;
}

UpdateStatus Pr2GripperController::update(double time, double period) {
  if (!(period > 0.0)) return UpdateStatus::Ok();

  // 1. Newest command or goal.
  const GripperCommand& plain = command_.read_from_rt();
  const std::uint64_t seq = command_.accepted();
  if (seq != last_command_seq_) {
    last_command_seq_ = seq;
    active_ = plain;
    if (goal_id_ != 0) finish_goal(GoalStatus::Preempted);
  }
  GripperGoalRequest request;
  if (goals_.take_from_rt(request)) {
    if (goal_id_ != 0) finish_goal(GoalStatus::Preempted);
    goal_id_ = request.id;
    last_goal_id_ = request.id;
    active_ = request.command;
    stall_time_ = 0.0;
    goals_.report_from_rt({goal_id_, GoalStatus::Active, {}});
  }
  if (goal_id_ != 0 && goals_.cancel_request_from_rt() == goal_id_) finish_goal(GoalStatus::Preempted);

  // 2. The PID on the gap, clamped to max_effort.
  const double gap = joint_.position(), rate = joint_.velocity();
  double effort = pid_.compute_command(active_.position - gap, -rate, period);
  if (active_.max_effort >= 0.0) effort = std::fmin(std::fmax(effort, -active_.max_effort), active_.max_effort);
  if (!std::isfinite(effort)) effort = 0.0;
  joint_.set_command(effort);

  // 3. Goal monitoring.
  result_.position = gap;
  result_.effort = effort;
  result_.reached_goal = std::abs(gap - active_.position) < goal_threshold_;
  stall_time_ = std::abs(rate) < stall_velocity_threshold_ ? stall_time_ + period : 0.0;
  result_.stalled = !result_.reached_goal && stall_time_ >= stall_timeout_;
  if (goal_id_ != 0) {
    if (result_.reached_goal) {
      finish_goal(GoalStatus::Succeeded);
    } else if (result_.stalled) {
      finish_goal(GoalStatus::Aborted);
    }
  }

  state_.publish_from_rt([&](JointControllerState& s) {
    s.stamp = time;
    s.set_point = active_.position;
    s.process_value = gap;
    s.process_value_dot = rate;
    s.error = gap - active_.position;
    s.time_step = period;
    s.command = effort;
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
