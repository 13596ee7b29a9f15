#include "mechanism/mechanism_model.hpp"

#include <algorithm>

namespace mechsim::mechanism {

bool JointInfo::has_interface(HardwareInterface hw) const {
  return std::find(interfaces.begin(), interfaces.end(), hw) != interfaces.end();
}

bool JointInfo::has_state_interface(const std::string& interface_name) const {
  if (!ros2_control) return interface_name == "position" || interface_name == "velocity" || interface_name == "effort";
  return std::find(state_interfaces.begin(), state_interfaces.end(), interface_name) != state_interfaces.end();
}

int MechanismModel::joint_index(const std::string& name) const {
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return static_cast<int>(i);
  return -1;
}

int MechanismModel::actuator_index(const std::string& name) const {
  for (std::size_t i = 0; i < actuators.size(); ++i)
    if (actuators[i].name == name) return static_cast<int>(i);
  return -1;
}

MechanismState make_state(const MechanismModel& model) {
  MechanismState state;
  state.joints.resize(model.joints.size());
  state.actuators.resize(model.actuators.size());
  return state;
}

}  // namespace mechsim::mechanism
