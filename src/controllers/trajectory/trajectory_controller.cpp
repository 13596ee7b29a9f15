#include "controllers/trajectory/trajectory_controller.hpp"

#include <algorithm>
#include <cmath>

#include "control/angles.hpp"
#include "control/controller_params.hpp"
#include "controllers/param_checks.hpp"

namespace mechsim::control {
namespace {

double period_of(double rate) noexcept { return rate > 0.0 ? 1.0 / rate : 0.0; }

TrajectoryPointState sized(std::size_t n) {
  TrajectoryPointState p;
  p.positions.assign(n, 0.0);
  p.velocities.assign(n, 0.0);
  p.accelerations.assign(n, 0.0);
  return p;
}

HardwareInterface read_interface(const Params& params) {
  HardwareInterface iface = HardwareInterface::Effort;
  if (params.has("hardware_interface")) {
    const std::string text = params.get<std::string>("hardware_interface");
    if (!parse_interface_name(text, iface)) {
      throw ControllerConfigError("parameter " + join_param_path(params.path(), "hardware_interface") + ": unknown interface '" +
                                  text + "' (EffortJointInterface, PositionJointInterface or VelocityJointInterface)");
    }
  } else if (params.has("command_interfaces")) {
    const auto list = params.get<std::vector<std::string>>("command_interfaces");
    const std::string path = join_param_path(params.path(), "command_interfaces");
    if (list.size() != 1) throw ControllerConfigError("parameter " + path + " must name exactly one interface");
    if (list[0] == "effort") {
      iface = HardwareInterface::Effort;
    } else if (list[0] == "position") {
      iface = HardwareInterface::Position;
    } else if (list[0] == "velocity") {
      iface = HardwareInterface::Velocity;
    } else {
      throw ControllerConfigError("parameter " + path + ": unknown interface '" + list[0] + "' (effort, position or velocity)");
    }
  }
  return iface;
}

std::vector<std::string> string_list(const Params& params, const char* key) {
  const std::string path = join_param_path(params.path(), key);
  if (!params.has(key)) {
    throw ControllerConfigError("parameter " + path + " not set (ros2_controllers' joint_trajectory_controller requires it)");
  }
  const Params p = params.child(key);
  std::vector<std::string> out = p.is_scalar() ? std::vector<std::string>{p.as<std::string>()} : p.as<std::vector<std::string>>();
  if (out.empty()) throw ControllerConfigError("parameter " + path + " is empty");
  return out;
}

bool listed(const std::vector<std::string>& list, const char* name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// ros2_controllers' command_interfaces: the interface the joints are commanded through, and the
// others a combination lists (which the joints must offer too).
HardwareInterface read_ros2_interface(const Params& params, std::vector<HardwareInterface>& also_offered) {
  const std::vector<std::string> list = string_list(params, "command_interfaces");
  const std::string path = join_param_path(params.path(), "command_interfaces");
  for (const std::string& name : list) {
    if (name != "position" && name != "velocity" && name != "acceleration" && name != "effort") {
      throw ControllerConfigError("parameter " + path + ": unknown interface '" + name +
                                  "' (position, velocity, acceleration or effort)");
    }
    if (std::count(list.begin(), list.end(), name) > 1) {
      throw ControllerConfigError("parameter " + path + " lists '" + name + "' twice");
    }
  }
  if (listed(list, "effort")) {
    if (list.size() != 1) throw ControllerConfigError("parameter " + path + ": 'effort' cannot be combined with other interfaces");
    return HardwareInterface::Effort;
  }
  if (listed(list, "position")) {
    if (listed(list, "acceleration") && !listed(list, "velocity")) {
      throw ControllerConfigError("parameter " + path + ": 'acceleration' needs 'velocity' with 'position'");
    }
    if (listed(list, "velocity")) also_offered.push_back(HardwareInterface::Velocity);
    return HardwareInterface::Position;
  }
  if (list.size() == 1 && list[0] == "velocity") return HardwareInterface::Velocity;
  throw ControllerConfigError("parameter " + path + ": the combination is not supported (position, position + velocity "
                              "[+ acceleration], velocity, or effort)");
}

PidGains read_ros2_gains(const Params& params, const std::string& joint) {
  PidGains g;
  const std::optional<Params> p = params.find("gains/" + joint);
  if (!p) return g;
  g.p = p->get<double>("p", 0.0);
  g.i = p->get<double>("i", 0.0);
  g.d = p->get<double>("d", 0.0);
  const double i_clamp = p->get<double>("i_clamp", 0.0);
  g.i_max = std::abs(i_clamp);
  g.i_min = -std::abs(i_clamp);
  if (p->has("i_clamp_max")) g.i_max = p->get<double>("i_clamp_max");
  if (p->has("i_clamp_min")) g.i_min = p->get<double>("i_clamp_min");
  for (double v : {g.p, g.i, g.d}) {
    if (!std::isfinite(v)) throw ControllerConfigError("parameter " + p->path() + ": the gains must be finite");
  }
  return g;
}

}  // namespace

std::unique_ptr<JointTrajectoryController> JointTrajectoryController::ros2() {
  auto c = std::make_unique<JointTrajectoryController>(HardwareInterface::Position);
  c->ros2_ = true;
  return c;
}

bool JointTrajectoryController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  if (generic_) iface_ = read_interface(params);
  const std::vector<std::string> names = read_joint_names(params);
  const std::string joints_path = join_param_path(params.path(), "joints");
  std::vector<HardwareInterface> also_offered;
  std::vector<std::string> state_interfaces;
  if (ros2_) {
    if (params.has("command_joints")) {
      const auto command_joints = params.get<std::vector<std::string>>("command_joints");
      if (!command_joints.empty() && command_joints != names) {
        throw ControllerConfigError("parameter " + join_param_path(params.path(), "command_joints") +
                                    " differs from joints: commanding a subset of the joints is not simulated");
      }
    }
    iface_ = read_ros2_interface(params, also_offered);
    state_interfaces = string_list(params, "state_interfaces");
    const std::string path = join_param_path(params.path(), "state_interfaces");
    for (const std::string& s : state_interfaces) {
      if (s == "acceleration") throw ControllerConfigError("parameter " + path + ": state interface 'acceleration' is not simulated");
      if (s != "position" && s != "velocity") {
        throw ControllerConfigError("parameter " + path + ": unknown state interface '" + s + "' (position, velocity)");
      }
    }
    if (!listed(state_interfaces, "position")) {
      throw ControllerConfigError("parameter " + path + " must list 'position' (ros2_controllers requires it)");
    }
    // ros2_controllers: the PID laws need the velocity too.
    if (iface_ != HardwareInterface::Position && !listed(state_interfaces, "velocity")) {
      throw ControllerConfigError("parameter " + path + " must list 'velocity' with command interface " +
                                  std::string(interface_short_name(iface_)) + " (ros2_controllers requires it)");
    }
  }
  const bool pid_law = iface_ != HardwareInterface::Position;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string joint_path = joints_path + "[" + std::to_string(i) + "]";
    joints_.push_back(hardware.claim_joint(names[i], iface_, joint_path));
    const mechanism::JointInfo& info = joints_.back().info();
    for (HardwareInterface other : also_offered) {
      if (!info.has_interface(other)) {
        throw ControllerConfigError("joint '" + names[i] + "' (" + joint_path + ") has no " + interface_short_name(other) +
                                    " command interface, which " + join_param_path(params.path(), "command_interfaces") +
                                    " lists");
      }
    }
    for (const std::string& s : state_interfaces) {
      if (!info.has_state_interface(s)) {
        throw ControllerConfigError("joint '" + names[i] + "' (" + joint_path + ") has no " + s + " state interface, which " +
                                    join_param_path(params.path(), "state_interfaces") + " lists");
      }
    }
    continuous_.push_back(info.continuous || info.type == description::JointType::Continuous ? 1 : 0);
    if (ros2_) {
      velocity_ff_.push_back(pid_law ? params.get<double>("gains/" + names[i] + "/ff_velocity_scale", 0.0) : 0.0);
    } else {
      velocity_ff_.push_back(pid_law ? params.get<double>("velocity_ff/" + names[i], 0.0) : 0.0);
    }
    if (pid_law) {
      pids_.push_back(std::make_unique<Pid>());
      if (ros2_) {
        pids_.back()->init(read_ros2_gains(params, names[i]));
      } else {
        pids_.back()->init(params, "gains/" + names[i]);
      }
      gains_.push_back(std::make_unique<PidGainsPort>("gains/" + names[i], pids_.back().get()));
    }
  }

  std::optional<Params> constraints;
  if (flavour_ == ControllerFlavour::Pr2) constraints = params.find("joint_trajectory_action_node/constraints");
  if (!constraints) constraints = params.find("constraints");
  TrajectoryChannelConfig config;
  config.joints = names;
  config.default_tolerances = read_default_tolerances(constraints, names);
  config.allow_partial_joints_goal = params.get<bool>("allow_partial_joints_goal", false);
  const int max_points = params.get<int>("max_trajectory_points", static_cast<int>(kDefaultMaxTrajectoryPoints));
  if (max_points < 1) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "max_trajectory_points") +
                                " must be at least 1, got " + std::to_string(max_points));
  }
  config.max_points = static_cast<std::size_t>(max_points);
  state_period_ = period_of(non_negative_param(params, "state_publish_rate", 50.0));
  monitor_period_ = period_of(non_negative_param(params, "action_monitor_rate", 20.0));
  stop_duration_ = non_negative_param(params, "stop_trajectory_duration", 0.0);

  const std::size_t n = names.size();
  // Room for the kept part of the current trajectory, the bridge and the new points.
  const std::size_t capacity = 2 * (config.max_points + 2);
  goal_tolerances_ = config.default_tolerances;
  channel_ = std::make_unique<TrajectoryChannel>(std::move(config));
  command_ = std::make_unique<TrajectoryCommandPort>("command", channel_.get());
  goal_ = std::make_unique<TrajectoryGoalPort>("follow_joint_trajectory", channel_.get());
  query_ = std::make_unique<TrajectoryQueryPort>("query_state", names, capacity);
  trajectories_[0] = Trajectory(n, capacity);
  trajectories_[1] = Trajectory(n, capacity);
  desired_.assign(n, SplineState{});
  actual_.assign(n, SplineState{});
  error_.assign(n, SplineState{});
  previous_velocity_.assign(n, 0.0);
  goal_joints_.assign(n, 0);

  JointTrajectoryControllerState prototype;
  prototype.joint_names = names;
  prototype.desired = sized(n);
  prototype.actual = sized(n);
  prototype.error = sized(n);
  state_.init(prototype);
  FollowJointTrajectoryFeedback feedback;
  feedback.state = prototype;
  goal_->init_feedback(feedback);
  return true;
}

std::vector<Port*> JointTrajectoryController::ports() {
  std::vector<Port*> out{command_.get(), goal_.get(), &state_, query_.get()};
  for (auto& g : gains_) out.push_back(g.get());
  return out;
}

void JointTrajectoryController::starting(double time) {
  for (auto& pid : pids_) pid->reset();
  have_previous_velocity_ = false;
  last_state_publish_ = last_feedback_publish_ = -1e300;
  // A request posted just before the last stop is dropped: the controller starts holding.
  if (const TrajectoryRequest* r = channel_->take_from_rt()) {
    TrajectoryEvent e;
    e.kind = TrajectoryEvent::Kind::Taken;
    e.sequence = r->sequence;
    e.goal_id = r->goal_id;
    e.time = time;
    channel_->report_from_rt(e);
    if (r->goal_id != 0) {
      e.kind = TrajectoryEvent::Kind::Finished;
      e.status = GoalStatus::Rejected;
      e.code = TrajectoryResultCode::InvalidGoal;
      e.reason = "the controller was stopped before the goal started";
      channel_->report_from_rt(e);
    }
  }
  active_goal_ = 0;
  hold_current(time);
  query_stale_ = !query_->publish_from_rt(*active_);
  query_->set_running_from_rt(true);
  channel_->set_running_from_rt(true);
}

void JointTrajectoryController::stopping(double time) {
  channel_->set_running_from_rt(false);
  query_->set_running_from_rt(false);
  if (active_goal_ != 0) finish_goal(GoalStatus::Preempted, TrajectoryResultCode::Successful, "the controller stopped", time);
}

void JointTrajectoryController::hold_current(double time) noexcept {
  query_stale_ = true;
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const double p = joints_[j].position();
    const double v = joints_[j].velocity();
    if (stop_duration_ <= 0.0 || v == 0.0) {
      active_->hold(j, time, p);
      continue;
    }
    // Decelerate smoothly to rest, covering the distance a linear ramp of the velocity would.
    active_->clear(j);
    (void)active_->push(j, SplineSegment(time, SplineState{p, v, 0.0}, time + stop_duration_,
                                         SplineState{p + 0.5 * v * stop_duration_, 0.0, 0.0}, SplineOrder::Quintic));
  }
}

void JointTrajectoryController::finish_goal(GoalStatus status, TrajectoryResultCode code, const char* reason,
                                            double time, const ToleranceViolation* violation) noexcept {
  TrajectoryEvent e;
  e.kind = TrajectoryEvent::Kind::Finished;
  e.goal_id = active_goal_;
  e.status = status;
  e.code = code;
  e.reason = reason;
  e.time = time;
  if (violation != nullptr) e.violation = *violation;
  channel_->report_from_rt(e);
  active_goal_ = 0;
}

bool JointTrajectoryController::canceled_before_start(std::uint64_t id) const noexcept {
  return std::find(canceled_.begin(), canceled_.end(), id) != canceled_.end();
}

void JointTrajectoryController::take(const TrajectoryRequest& r, double time) noexcept {
  TrajectoryEvent taken;
  taken.kind = TrajectoryEvent::Kind::Taken;
  taken.sequence = r.sequence;
  taken.goal_id = r.goal_id;
  taken.time = time;
  channel_->report_from_rt(taken);

  TrajectoryEvent done;
  done.kind = TrajectoryEvent::Kind::Finished;
  done.goal_id = r.goal_id;
  done.time = time;
  if (r.goal_id != 0 && canceled_before_start(r.goal_id)) {
    done.status = GoalStatus::Preempted;
    done.reason = "canceled before it started";
    channel_->report_from_rt(done);
    return;
  }
  if (r.stop) {
    if (active_goal_ != 0) finish_goal(GoalStatus::Preempted, TrajectoryResultCode::Successful, "stopped by an empty trajectory", time);
    hold_current(time);
    if (r.goal_id != 0) {
      done.status = GoalStatus::Succeeded;
      channel_->report_from_rt(done);
    }
    return;
  }
  const ReplaceOutcome outcome = replace_trajectory(*active_, r, continuous_, time, *spare_);
  if (outcome.code != TrajectoryResultCode::Successful) {
    if (r.goal_id != 0) {
      done.status = GoalStatus::Rejected;
      done.code = outcome.code;
      done.reason = outcome.reason;
      channel_->report_from_rt(done);
    }
    return;  // the current trajectory and goal go on
  }
  std::swap(active_, spare_);
  query_stale_ = true;
  if (active_goal_ != 0) finish_goal(GoalStatus::Preempted, TrajectoryResultCode::Successful, "preempted by a newer trajectory", time);
  if (r.goal_id == 0) return;
  active_goal_ = r.goal_id;
  goal_start_ = outcome.start;
  goal_end_ = outcome.end;
  std::copy(r.joint_in_request.begin(), r.joint_in_request.end(), goal_joints_.begin());
  std::copy(r.tolerances.path.begin(), r.tolerances.path.end(), goal_tolerances_.path.begin());
  std::copy(r.tolerances.goal.begin(), r.tolerances.goal.end(), goal_tolerances_.goal.begin());
  goal_tolerances_.goal_time = r.tolerances.goal_time;
}

void JointTrajectoryController::check_goal(double time) noexcept {
  if (active_goal_ == 0 || time < goal_start_) return;
  ToleranceViolation v;
  if (time < goal_end_) {
    for (std::size_t j = 0; j < joints_.size(); ++j) {
      if (goal_joints_[j] == 0) continue;
      if (!within_tolerance(goal_tolerances_.path[j], error_[j].position, error_[j].velocity, error_[j].acceleration, &v)) {
        v.joint = static_cast<int>(j);
        finish_goal(GoalStatus::Aborted, TrajectoryResultCode::PathToleranceViolated, "path tolerance violated", time, &v);
        hold_current(time);
        return;
      }
    }
    return;
  }
  bool inside = true;
  for (std::size_t j = 0; j < joints_.size() && inside; ++j) {
    if (goal_joints_[j] == 0) continue;
    if (!within_tolerance(goal_tolerances_.goal[j], error_[j].position, error_[j].velocity, error_[j].acceleration, &v)) {
      v.joint = static_cast<int>(j);
      inside = false;
    }
  }
  if (inside) {
    finish_goal(GoalStatus::Succeeded, TrajectoryResultCode::Successful, "", time);
  } else if (goal_tolerances_.goal_time > 0.0 && time > goal_end_ + goal_tolerances_.goal_time) {
    finish_goal(GoalStatus::Aborted, TrajectoryResultCode::GoalToleranceViolated,
                "not within the goal tolerance after the goal time tolerance", time, &v);
  }
}

void JointTrajectoryController::fill(JointTrajectoryControllerState& s, double time) const noexcept {
  const double sign = flavour_ == ControllerFlavour::Pr2 ? -1.0 : 1.0;
  s.stamp = time;
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    s.desired.positions[j] = desired_[j].position;
    s.desired.velocities[j] = desired_[j].velocity;
    s.desired.accelerations[j] = desired_[j].acceleration;
    s.actual.positions[j] = actual_[j].position;
    s.actual.velocities[j] = actual_[j].velocity;
    s.actual.accelerations[j] = actual_[j].acceleration;
    s.error.positions[j] = sign * error_[j].position;
    s.error.velocities[j] = sign * error_[j].velocity;
    s.error.accelerations[j] = sign * error_[j].acceleration;
  }
  const double from = active_goal_ != 0 ? goal_start_ : time;
  s.desired.time_from_start = s.actual.time_from_start = s.error.time_from_start = time - from;
}

void JointTrajectoryController::publish(double time) noexcept {
  if (state_period_ <= 0.0 || time >= last_state_publish_ + state_period_ - 1e-9) {
    if (state_.publish_from_rt([&](JointTrajectoryControllerState& s) { fill(s, time); })) last_state_publish_ = time;
  }
  if (active_goal_ != 0 && (monitor_period_ <= 0.0 || time >= last_feedback_publish_ + monitor_period_ - 1e-9)) {
    const std::uint64_t id = active_goal_;
    if (goal_->publish_feedback_from_rt([&](FollowJointTrajectoryFeedback& f) {
          f.goal_id = id;
          fill(f.state, time);
        })) {
      last_feedback_publish_ = time;
    }
  }
}

UpdateStatus JointTrajectoryController::update(double time, double period) {
  channel_->set_time_from_rt(time);
  std::uint64_t id = 0;
  while (channel_->next_cancel_from_rt(id)) {
    if (id == active_goal_) {
      finish_goal(GoalStatus::Preempted, TrajectoryResultCode::Successful, "canceled", time);
      hold_current(time);
    } else {
      canceled_[canceled_next_++ % canceled_.size()] = id;
    }
  }
  if (const TrajectoryRequest* r = channel_->take_from_rt()) take(*r, time);

  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const JointHandle& joint = joints_[j];
    desired_[j] = active_->sample(j, time);
    actual_[j].position = joint.position();
    actual_[j].velocity = joint.velocity();
    actual_[j].acceleration = have_previous_velocity_ && period > 0.0 ? (joint.velocity() - previous_velocity_[j]) / period : 0.0;
    previous_velocity_[j] = joint.velocity();
    error_[j].position = position_error(joint.info(), actual_[j].position, desired_[j].position);
    error_[j].velocity = desired_[j].velocity - actual_[j].velocity;
    error_[j].acceleration = desired_[j].acceleration - actual_[j].acceleration;
  }
  have_previous_velocity_ = true;

  check_goal(time);
  if (iface_ != HardwareInterface::Position) {
    for (std::size_t j = 0; j < joints_.size(); ++j) {
      const double command = pids_[j]->compute_command(error_[j].position, error_[j].velocity, period) +
                             velocity_ff_[j] * desired_[j].velocity;
      joints_[j].set_command(command);
    }
  } else {
    for (std::size_t j = 0; j < joints_.size(); ++j) joints_[j].set_command(desired_[j].position);
  }
  if (query_stale_) query_stale_ = !query_->publish_from_rt(*active_);
  publish(time);
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
