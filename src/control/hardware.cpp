#include "control/hardware.hpp"

#include <algorithm>
#include <cmath>

namespace mechsim::control {

const char* interface_name(HardwareInterface iface) {
  switch (iface) {
    case HardwareInterface::Effort: return "hardware_interface::EffortJointInterface";
    case HardwareInterface::Position: return "hardware_interface::PositionJointInterface";
    case HardwareInterface::Velocity: return "hardware_interface::VelocityJointInterface";
  }
  return "?";
}

const char* interface_short_name(HardwareInterface iface) {
  switch (iface) {
    case HardwareInterface::Effort: return "effort";
    case HardwareInterface::Position: return "position";
    case HardwareInterface::Velocity: return "velocity";
  }
  return "?";
}

bool parse_interface_name(std::string_view text, HardwareInterface& out) {
  for (std::string_view prefix : {"hardware_interface::", "hardware_interface/"}) {
    if (text.substr(0, prefix.size()) == prefix) text.remove_prefix(prefix.size());
  }
  if (text == "EffortJointInterface") {
    out = HardwareInterface::Effort;
  } else if (text == "PositionJointInterface") {
    out = HardwareInterface::Position;
  } else if (text == "VelocityJointInterface") {
    out = HardwareInterface::Velocity;
  } else {
    return false;
  }
  return true;
}

void JointHandle::set_command(double value) noexcept {
  switch (iface_) {
    case HardwareInterface::Effort: state_->commanded_effort = value; break;
    case HardwareInterface::Position: state_->commanded_position = value; break;
    case HardwareInterface::Velocity: state_->commanded_velocity = value; break;
  }
  state_->command_mode = iface_;
}

double JointHandle::command() const noexcept {
  switch (iface_) {
    case HardwareInterface::Effort: return state_->commanded_effort;
    case HardwareInterface::Position: return state_->commanded_position;
    case HardwareInterface::Velocity: return state_->commanded_velocity;
  }
  return 0.0;
}

RobotHardware::RobotHardware(const mechanism::MechanismModel& model, mechanism::MechanismState& state,
                             HardwareAccess access)
    : model_(model), state_(state), access_(access) {
  if (state_.joints.size() != model_.joints.size()) {
    throw ControllerConfigError("mechanism state has " + std::to_string(state_.joints.size()) +
                                " joints but the model has " + std::to_string(model_.joints.size()));
  }
}

int RobotHardware::find_joint(std::string_view name) const {
  for (std::size_t i = 0; i < model_.joints.size(); ++i) {
    if (model_.joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

namespace {

std::string where(std::string_view param_path) {
  return param_path.empty() ? std::string() : " (parameter " + std::string(param_path) + ")";
}

std::string known_joints(const mechanism::MechanismModel& model) {
  std::string out;
  const std::size_t shown = std::min<std::size_t>(model.joints.size(), 12);
  for (std::size_t i = 0; i < shown; ++i) out += (i ? ", " : "") + model.joints[i].name;
  if (model.joints.size() > shown) out += ", ... (" + std::to_string(model.joints.size()) + " in all)";
  return out.empty() ? "none" : out;
}

}  // namespace

JointStateHandle RobotHardware::joint_state(const std::string& joint, std::string_view param_path) const {
  const int index = find_joint(joint);
  if (index < 0) {
    throw ControllerConfigError("unknown joint '" + joint + "'" + where(param_path) +
                                "; the robot's joints: " + known_joints(model_));
  }
  return joint_state(static_cast<std::size_t>(index));
}

JointStateHandle RobotHardware::joint_state(std::size_t index) const {
  return JointStateHandle(&model_.joints[index], &state_.joints[index]);
}

JointHandle RobotHardware::claim_joint(const std::string& joint, HardwareInterface iface, std::string_view param_path) {
  const int index = find_joint(joint);
  if (index < 0) {
    throw ControllerConfigError("unknown joint '" + joint + "'" + where(param_path) +
                                "; the robot's joints: " + known_joints(model_));
  }
  const mechanism::JointInfo& info = model_.joints[static_cast<std::size_t>(index)];
  if (info.role == mechanism::JointRole::Direct && access_ == HardwareAccess::RosControl) {
    const std::string owner = direct_owner_ ? direct_owner_(index) : std::string();
    throw ControllerConfigError("joint '" + joint + "'" + where(param_path) +
                                " has no transmission: gazebo_ros_control offers it to no controller (" +
                                (owner.empty() ? std::string("a Gazebo model plugin of the robot") : owner) + " drives it)");
  }
  // Model plugins command joints the way Gazebo's Joint API does, whatever the transmission says.
  const bool available = access_ == HardwareAccess::ModelPlugin ||
                       std::find(info.interfaces.begin(), info.interfaces.end(), iface) != info.interfaces.end();
  if (!available) {
    std::string offered;
    for (HardwareInterface i : info.interfaces) offered += (offered.empty() ? "" : ", ") + std::string(interface_name(i));
    throw ControllerConfigError("joint '" + joint + "'" + where(param_path) + " has no " + interface_name(iface) +
                                " (its transmission offers: " + (offered.empty() ? "none, it is passive" : offered) + ")");
  }
  auto claim = std::find_if(claims_.begin(), claims_.end(), [&](const ResourceClaim& c) { return c.interface == iface; });
  if (claim == claims_.end()) {
    claims_.push_back(ResourceClaim{iface, {}});
    claim = claims_.end() - 1;
  }
  if (std::find(claim->joints.begin(), claim->joints.end(), joint) == claim->joints.end()) claim->joints.push_back(joint);
  return JointHandle(&info, &state_.joints[static_cast<std::size_t>(index)], iface);
}

BaseHandle RobotHardware::claim_base(std::string_view param_path) {
  if (access_ != HardwareAccess::ModelPlugin) {
    throw ControllerConfigError("only a Gazebo model plugin may move the robot's base" + where(param_path));
  }
  if (!state_.base.floating) {
    throw ControllerConfigError("the robot is fixed to the world: it has no floating base to move" + where(param_path));
  }
  claims_base_ = true;
  return BaseHandle(&state_.base, &state_.base_command);
}

namespace {

template <class Data>
std::string sensor_names(const std::vector<Data>& sensors) {
  std::string out;
  for (const Data& d : sensors) out += (out.empty() ? "" : ", ") + d.name;
  return out.empty() ? "none" : out;
}

}  // namespace

void RobotHardware::use_sensor(const char* interface, const std::string& name) {
  auto use = std::find_if(sensor_uses_.begin(), sensor_uses_.end(), [&](const SensorUse& u) { return u.interface == interface; });
  if (use == sensor_uses_.end()) {
    sensor_uses_.push_back(SensorUse{interface, {}});
    use = sensor_uses_.end() - 1;
  }
  if (std::find(use->sensors.begin(), use->sensors.end(), name) == use->sensors.end()) use->sensors.push_back(name);
}

constexpr const char* kImuInterface = "hardware_interface::ImuSensorInterface";
constexpr const char* kForceTorqueInterface = "hardware_interface::ForceTorqueSensorInterface";

ImuSensorHandle RobotHardware::imu_sensor(const std::string& name, std::string_view param_path) {
  if (sensors_ != nullptr) {
    const std::vector<ImuSensorData>& imus = sensors_->imus();
    for (std::size_t i = 0; i < imus.size(); ++i) {
      if (imus[i].name != name) continue;
      sensors_->mark_imu_used(i);
      use_sensor(kImuInterface, name);
      return ImuSensorHandle(&imus[i]);
    }
  }
  throw ControllerConfigError("unknown IMU '" + name + "'" + where(param_path) + "; the robot's IMUs: " +
                              (sensors_ ? sensor_names(sensors_->imus()) : std::string("none")));
}

std::vector<std::string> RobotHardware::imu_sensor_names() const {
  std::vector<std::string> out;
  if (sensors_ != nullptr) {
    for (const ImuSensorData& d : sensors_->imus()) out.push_back(d.name);
  }
  return out;
}

std::vector<ImuSensorHandle> RobotHardware::imu_sensors() {
  std::vector<ImuSensorHandle> out;
  if (sensors_ == nullptr) return out;
  for (std::size_t i = 0; i < sensors_->imus().size(); ++i) {
    sensors_->mark_imu_used(i);
    use_sensor(kImuInterface, sensors_->imus()[i].name);
    out.emplace_back(&sensors_->imus()[i]);
  }
  return out;
}

ForceTorqueSensorHandle RobotHardware::force_torque_sensor(const std::string& name, std::string_view param_path) {
  if (sensors_ != nullptr) {
    const std::vector<ForceTorqueSensorData>& fts = sensors_->force_torque();
    for (std::size_t i = 0; i < fts.size(); ++i) {
      if (fts[i].name != name) continue;
      sensors_->mark_force_torque_used(i);
      use_sensor(kForceTorqueInterface, name);
      return ForceTorqueSensorHandle(&fts[i]);
    }
  }
  throw ControllerConfigError("unknown force-torque sensor '" + name + "'" + where(param_path) +
                              "; the robot's force-torque sensors: " +
                              (sensors_ ? sensor_names(sensors_->force_torque()) : std::string("none")));
}

std::vector<ForceTorqueSensorHandle> RobotHardware::force_torque_sensors() {
  std::vector<ForceTorqueSensorHandle> out;
  if (sensors_ == nullptr) return out;
  for (std::size_t i = 0; i < sensors_->force_torque().size(); ++i) {
    sensors_->mark_force_torque_used(i);
    use_sensor(kForceTorqueInterface, sensors_->force_torque()[i].name);
    out.emplace_back(&sensors_->force_torque()[i]);
  }
  return out;
}

double yaw_of(const std::array<double, 4>& q) noexcept {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  return std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
}

}  // namespace mechsim::control
