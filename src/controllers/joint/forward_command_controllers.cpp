#include "controllers/joint/forward_command_controllers.hpp"

#include "control/controller_params.hpp"

namespace mechsim::control {

double process_value(const JointHandle& joint) noexcept {
  switch (joint.interface()) {
    case HardwareInterface::Position: return joint.position();
    case HardwareInterface::Velocity: return joint.velocity();
    case HardwareInterface::Effort: return joint.effort();
  }
  return 0.0;
}

namespace {

double start_value(const JointHandle& joint) noexcept {
  return joint.interface() == HardwareInterface::Position ? joint.position() : 0.0;
}

void fill_state(JointControllerState& s, const JointHandle& joint, double set_point, double time, double period) noexcept {
  s.stamp = time;
  s.set_point = set_point;
  s.process_value = process_value(joint);
  s.process_value_dot = joint.interface() == HardwareInterface::Position ? joint.velocity() : 0.0;
  s.error = set_point - s.process_value;
  s.time_step = period;
  s.command = set_point;
}

}  // namespace

bool JointCommandController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string joint = read_joint_name(params);
  joint_ = hardware.claim_joint(joint, iface_, join_param_path(params.path(), "joint"));
  state_.init(JointControllerState{});
  return true;
}

void JointCommandController::starting(double /*time*/) { command_.reset_from_rt(start_value(joint_)); }

UpdateStatus JointCommandController::update(double time, double period) {
  const double command = command_.read_from_rt();
  joint_.set_command(command);
  state_.publish_from_rt([&](JointControllerState& s) { fill_state(s, joint_, command, time, period); });
  return UpdateStatus::Ok();
}

bool JointGroupCommandController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  if (interface_from_params_) {
    const std::string path = join_param_path(params.path(), "interface_name");
    if (!params.has("interface_name")) {
      throw ControllerConfigError("parameter " + path + " not set (the joints' command interface: position, velocity or effort)");
    }
    const std::string name = params.get<std::string>("interface_name");
    if (name == "position") iface_ = HardwareInterface::Position;
    else if (name == "velocity") iface_ = HardwareInterface::Velocity;
    else if (name == "effort") iface_ = HardwareInterface::Effort;
    else throw ControllerConfigError("parameter " + path + ": interface '" + name + "' is none of position, velocity, effort");
  }
  const auto names = read_joint_names(params);
  const std::string path = join_param_path(params.path(), "joints");
  for (std::size_t i = 0; i < names.size(); ++i) {
    joints_.push_back(hardware.claim_joint(names[i], iface_, path + "[" + std::to_string(i) + "]"));
  }
  start_values_.assign(names.size(), 0.0);
  command_ = std::make_unique<ArrayCommandPort>("command", names.size());
  JointGroupControllerState prototype;
  prototype.joint_names = names;
  prototype.joints.resize(names.size());
  state_.init(prototype);
  return true;
}

void JointGroupCommandController::starting(double /*time*/) {
  for (std::size_t i = 0; i < joints_.size(); ++i) start_values_[i] = start_value(joints_[i]);
  command_->reset_from_rt(start_values_);
}

UpdateStatus JointGroupCommandController::update(double time, double period) {
  const std::vector<double>& commands = command_->read_from_rt();
  for (std::size_t i = 0; i < joints_.size(); ++i) joints_[i].set_command(commands[i]);
  state_.publish_from_rt([&](JointGroupControllerState& s) {
    s.stamp = time;
    for (std::size_t i = 0; i < joints_.size(); ++i) fill_state(s.joints[i], joints_[i], commands[i], time, period);
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
