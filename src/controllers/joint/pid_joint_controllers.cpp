#include "controllers/joint/pid_joint_controllers.hpp"

#include "control/angles.hpp"
#include "control/controller_params.hpp"

namespace mechsim::control {

void fill_joint_controller_state(JointControllerState& s, double time, double period, double set_point, double value,
                                 double value_dot, double error, double command, const PidGains& gains) noexcept {
  s.stamp = time;
  s.set_point = set_point;
  s.process_value = value;
  s.process_value_dot = value_dot;
  s.error = error;
  s.time_step = period;
  s.command = command;
  s.gains = gains;
}

// ---------------------------------------------------------------- single joint

bool SingleJointPidController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string joint = read_joint_name(params);
  joint_ = hardware.claim_joint(joint, HardwareInterface::Effort, join_param_path(params.path(), "joint"));
  pid_.init(params, "pid");
  state_.init(JointControllerState{});
  return true;
}

void SingleJointPidController::drive(double time, double period, double set_point, double value, double value_dot,
                                     double error) noexcept {
  const double effort = pid_.compute_command(error, period);
  joint_.set_command(effort);
  const double reported_error = flavour_ == ControllerFlavour::Pr2 ? -error : error;
  state_.publish_from_rt([&](JointControllerState& s) {
    fill_joint_controller_state(s, time, period, set_point, value, value_dot, reported_error, effort, pid_.rt_gains());
  });
}

// ---------------------------------------------------------------- position

double JointPositionPidController::limit(double command) const noexcept {
  return flavour_ == ControllerFlavour::RosControl ? enforce_position_limits(joint_.info(), command) : command;
}

void JointPositionPidController::starting(double /*time*/) {
  command_.reset_from_rt(limit(joint_.position()));
  pid_.reset();
}

UpdateStatus JointPositionPidController::update(double time, double period) {
  const double set_point = limit(command_.read_from_rt());
  const double position = joint_.position();
  drive(time, period, set_point, position, joint_.velocity(), position_error(joint_.info(), position, set_point));
  return UpdateStatus::Ok();
}

// ---------------------------------------------------------------- velocity

void JointVelocityPidController::starting(double /*time*/) {
  command_.reset_from_rt(0.0);
  pid_.reset();
}

UpdateStatus JointVelocityPidController::update(double time, double period) {
  const double set_point = command_.read_from_rt();
  const double velocity = joint_.velocity();
  drive(time, period, set_point, velocity, 0.0, set_point - velocity);
  return UpdateStatus::Ok();
}

// ---------------------------------------------------------------- group position

bool JointGroupPositionPidController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const auto names = read_joint_names(params);
  const std::string path = join_param_path(params.path(), "joints");
  for (std::size_t i = 0; i < names.size(); ++i) {
    joints_.push_back(hardware.claim_joint(names[i], HardwareInterface::Effort, path + "[" + std::to_string(i) + "]"));
    pids_.push_back(std::make_unique<Pid>());
    pids_.back()->init(params, names[i] + "/pid");
    gains_.push_back(std::make_unique<PidGainsPort>("gains/" + names[i], pids_.back().get()));
  }
  scratch_.assign(names.size(), 0.0);
  command_ = std::make_unique<ArrayCommandPort>("command", names.size());
  JointGroupControllerState prototype;
  prototype.joint_names = names;
  prototype.joints.resize(names.size());
  state_.init(prototype);
  return true;
}

std::vector<Port*> JointGroupPositionPidController::ports() {
  std::vector<Port*> out{command_.get(), &state_};
  for (auto& g : gains_) out.push_back(g.get());
  return out;
}

void JointGroupPositionPidController::starting(double /*time*/) {
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    scratch_[i] = enforce_position_limits(joints_[i].info(), joints_[i].position());
    pids_[i]->reset();
  }
  command_->reset_from_rt(scratch_);
}

UpdateStatus JointGroupPositionPidController::update(double time, double period) {
  const std::vector<double>& commands = command_->read_from_rt();
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const double set_point = enforce_position_limits(joints_[i].info(), commands[i]);
    const double error = position_error(joints_[i].info(), joints_[i].position(), set_point);
    scratch_[i] = pids_[i]->compute_command(error, period);
    joints_[i].set_command(scratch_[i]);
  }
  state_.publish_from_rt([&](JointGroupControllerState& s) {
    s.stamp = time;
    for (std::size_t i = 0; i < joints_.size(); ++i) {
      const double set_point = enforce_position_limits(joints_[i].info(), commands[i]);
      const double position = joints_[i].position();
      fill_joint_controller_state(s.joints[i], time, period, set_point, position, joints_[i].velocity(),
                 position_error(joints_[i].info(), position, set_point), scratch_[i], pids_[i]->rt_gains());
    }
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
