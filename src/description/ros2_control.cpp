#include "description/ros2_control.hpp"

#include <array>
#include <string_view>

namespace mechsim::description {

bool is_gazebo_system_plugin(const std::string& plugin) {
  return plugin == kGazeboSystem || plugin == kGazeboSimSystem || plugin == kIgnitionSystem;
}

namespace {

const Ros2ControlInterface* find_interface(const std::vector<Ros2ControlInterface>& list, const std::string& name) {
  for (const Ros2ControlInterface& i : list)
    if (i.name == name) return &i;
  return nullptr;
}

bool one_of(const std::string& name, std::initializer_list<std::string_view> names) {
  for (std::string_view n : names)
    if (name == n) return true;
  return false;
}

}  // namespace

const Ros2ControlInterface* Ros2ControlComponent::command_interface(const std::string& interface_name) const {
  return find_interface(command_interfaces, interface_name);
}

const Ros2ControlInterface* Ros2ControlComponent::state_interface(const std::string& interface_name) const {
  return find_interface(state_interfaces, interface_name);
}

std::vector<Ros2ControlJointRef> ros2_control_joints(const RobotModel& robot) {
  std::vector<Ros2ControlJointRef> out;
  for (const Ros2ControlHardware& h : robot.ros2_control)
    for (const Ros2ControlComponent& j : h.joints) out.push_back({&h, &j});
  return out;
}

const Ros2ControlComponent* find_ros2_control_joint(const RobotModel& robot, const std::string& joint) {
  for (const Ros2ControlHardware& h : robot.ros2_control)
    for (const Ros2ControlComponent& j : h.joints)
      if (j.name == joint) return &j;
  return nullptr;
}

const Ros2ControlComponent* find_ros2_control_sensor(const RobotModel& robot, const std::string& sensor) {
  for (const Ros2ControlHardware& h : robot.ros2_control)
    for (const Ros2ControlComponent& s : h.sensors)
      if (s.name == sensor) return &s;
  return nullptr;
}

std::optional<Ros2ControlMimic> ros2_control_mimic(const RobotModel& robot, const Ros2ControlComponent& joint) {
  // Humble's gazebo_ros2_control: the parameters say it, whatever the URDF says.
  if (auto it = joint.parameters.find("mimic"); it != joint.parameters.end()) {
    Ros2ControlMimic m;
    m.joint = joint.name;
    m.leader = it->second;
    m.from_param = true;
    if (auto mult = joint.parameters.find("multiplier"); mult != joint.parameters.end()) {
      // The reader has checked that it is a number.
      m.multiplier = std::stod(mult->second);
    }
    return m;
  }
  // Jazzy's parser: a URDF <mimic> makes it a mimic joint unless mimic="false".
  if (joint.mimic_attribute == false) return std::nullopt;
  const Joint* urdf = robot.joint(joint.name);
  if (urdf == nullptr || !urdf->mimic) return std::nullopt;
  Ros2ControlMimic m;
  m.joint = joint.name;
  m.leader = urdf->mimic->joint;
  m.multiplier = urdf->mimic->multiplier;
  m.offset = urdf->mimic->offset;
  return m;
}

std::map<std::string, double> ros2_control_initial_positions(const RobotModel& robot) {
  std::map<std::string, double> out;
  for (const Ros2ControlJointRef& ref : ros2_control_joints(robot)) {
    if (const Ros2ControlInterface* p = ref.joint->state_interface("position"); p != nullptr && p->initial_value) {
      out[ref.joint->name] = *p->initial_value;
    }
  }
  return out;
}

bool is_joint_interface(const std::string& name) { return one_of(name, {"position", "velocity", "effort"}); }

bool is_imu_interface(const std::string& name) {
  return one_of(name, {"orientation.x", "orientation.y", "orientation.z", "orientation.w", "angular_velocity.x",
                       "angular_velocity.y", "angular_velocity.z", "linear_acceleration.x", "linear_acceleration.y",
                       "linear_acceleration.z"});
}

bool is_force_torque_interface(const std::string& name) {
  return one_of(name, {"force.x", "force.y", "force.z", "torque.x", "torque.y", "torque.z"});
}

}  // namespace mechsim::description
