#include "mechanism/propagation.hpp"

namespace mechsim::mechanism {

void propagate_actuator_to_joint_position(const MechanismModel& model, MechanismState& state) {
  for (const auto& t : model.transmissions) t->actuator_to_joint_state(state);
}

void propagate_joint_to_actuator_position(const MechanismModel& model, MechanismState& state) {
  for (const auto& t : model.transmissions) t->joint_to_actuator_state(state);
}

void propagate_joint_to_actuator_effort(const MechanismModel& model, MechanismState& state) {
  for (const auto& t : model.transmissions) t->joint_to_actuator_command(state);
}

void propagate_actuator_to_joint_effort(const MechanismModel& model, MechanismState& state) {
  for (const auto& t : model.transmissions) t->actuator_to_joint_command(state);
}

}  // namespace mechsim::mechanism
