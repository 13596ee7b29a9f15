#include "mechanism/ros2_control_joints.hpp"

#include <algorithm>

#include "description/ros2_control.hpp"
#include "description/ros2_control_plugin.hpp"
#include "mechanism/mechanism_error.hpp"
#include "mechanism/simple_transmission.hpp"
#include "mechanism/transmission_builder.hpp"

namespace mechsim::mechanism {

namespace {

std::optional<HardwareInterface> simulated_command(const std::string& name) {
  if (name == "position") return HardwareInterface::Position;
  if (name == "velocity") return HardwareInterface::Velocity;
  if (name == "effort") return HardwareInterface::Effort;
  return std::nullopt;
}

}  // namespace

void add_ros2_control_joints(MechanismModel& model, const description::RobotModel& robot) {
  if (robot.ros2_control.empty()) return;
  const std::optional<description::Ros2ControlPlugin> plugin = description::find_ros2_control_plugin(robot);
  const bool hold = plugin ? plugin->hold_joints : true;
  for (const description::Ros2ControlJointRef& ref : description::ros2_control_joints(robot)) {
    const description::Ros2ControlComponent& rc = *ref.joint;
    const std::string tag = "<ros2_control name=\"" + ref.hardware->name + "\">";
    const description::Joint* urdf = robot.joint(rc.name);
    if (urdf == nullptr) {
      throw MechanismError(where(model.source, rc.line) + tag + ": joint '" + rc.name + "' is not in the robot", "", rc.name,
                           rc.line);
    }
    if (urdf->type != description::JointType::Revolute && urdf->type != description::JointType::Continuous &&
        urdf->type != description::JointType::Prismatic) {
      throw MechanismError(where(model.source, rc.line) + tag + ": joint '" + rc.name +
                               "' is not revolute, continuous or prismatic", "", rc.name, rc.line);
    }
    int index = model.joint_index(rc.name);
    const bool created = index < 0;
    if (created) {
      // Gazebo's systems write the joint's own commands: reduction 1, no offset.
      const std::string name = rc.name + "_ros2_control";
      const int transmission = static_cast<int>(model.transmissions.size());
      JointInfo info;
      info.name = rc.name;
      info.type = urdf->type;
      info.continuous = urdf->type == description::JointType::Continuous;
      info.limits = urdf->limits;
      info.safety = urdf->safety;
      info.mimic = urdf->mimic;
      info.transmission = transmission;
      info.line = urdf->line;
      model.joints.push_back(std::move(info));
      index = static_cast<int>(model.joints.size()) - 1;
      model.actuators.push_back(ActuatorInfo{name, transmission});
      const int actuator = static_cast<int>(model.actuators.size()) - 1;
      model.transmissions.push_back(
          std::make_unique<SimpleTransmission>(name, "transmission_interface/SimpleTransmission", index, actuator, 1.0));
    }
    JointInfo& info = model.joints[static_cast<std::size_t>(index)];
    info.ros2_control = true;
    info.mimic = urdf->mimic;  // Humble's <param name="mimic"> has been folded into it
    info.interfaces.clear();
    const bool mimic = description::ros2_control_mimic(robot, rc).has_value();
    if (!mimic) {
      for (const description::Ros2ControlInterface& ci : rc.command_interfaces) {
        const std::optional<HardwareInterface> hw = simulated_command(ci.name);
        if (!hw) continue;
        if (std::find(info.interfaces.begin(), info.interfaces.end(), *hw) == info.interfaces.end()) {
          info.interfaces.push_back(*hw);
        }
        const auto slot = static_cast<std::size_t>(*hw);
        if (ci.min) info.command_min[slot] = *ci.min;
        if (ci.max) info.command_max[slot] = *ci.max;
      }
    }
    info.state_interfaces.clear();
    for (const description::Ros2ControlInterface& si : rc.state_interfaces) {
      if (description::is_joint_interface(si.name) &&
          std::find(info.state_interfaces.begin(), info.state_interfaces.end(), si.name) == info.state_interfaces.end()) {
        info.state_interfaces.push_back(si.name);
      }
    }
    // A ros2_control joint of its own is actuated when it has a command interface Gazebo
    // simulates; a transmission's joint keeps the role its transmission gives it.
    if (created) info.role = info.interfaces.empty() ? JointRole::Passive : JointRole::Actuated;
    info.hold_when_unclaimed = hold && !info.interfaces.empty();
  }
}

}  // namespace mechsim::mechanism
