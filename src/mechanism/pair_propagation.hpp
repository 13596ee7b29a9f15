#pragma once
// The four propagations of a two-actuator, two-joint transmission, written once over its six
// maps on plain numbers (actuator_to_joint_{position,velocity,effort} and the joint_to_actuator
// ones; positions include offsets). Used by the Differential, FourBarLinkage and PR2 wrist
// transmissions. Real-time safe.

#include <array>

#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism::pair {

using Pair = std::array<double, 2>;

template <typename T>
void actuator_to_joint_state(const T& t, MechanismState& s) {
  const auto J = t.joints();
  const auto A = t.actuators();
  const ActuatorState& a0 = s.actuators[A[0]];
  const ActuatorState& a1 = s.actuators[A[1]];
  const Pair x = t.actuator_to_joint_position({a0.position, a1.position});
  const Pair v = t.actuator_to_joint_velocity({a0.velocity, a1.velocity});
  const Pair f = t.actuator_to_joint_effort({a0.last_measured_effort, a1.last_measured_effort});
  for (int i = 0; i < 2; ++i) {
    JointState& j = s.joints[J[i]];
    j.position = x[i];
    j.velocity = v[i];
    j.measured_effort = f[i];
  }
}

template <typename T>
void joint_to_actuator_state(const T& t, MechanismState& s) {
  const auto J = t.joints();
  const auto A = t.actuators();
  const JointState& j0 = s.joints[J[0]];
  const JointState& j1 = s.joints[J[1]];
  const Pair x = t.joint_to_actuator_position({j0.position, j1.position});
  const Pair v = t.joint_to_actuator_velocity({j0.velocity, j1.velocity});
  const Pair f = t.joint_to_actuator_effort({j0.measured_effort, j1.measured_effort});
  for (int i = 0; i < 2; ++i) {
    ActuatorState& a = s.actuators[A[i]];
    a.position = x[i];
    a.velocity = v[i];
    a.last_measured_effort = f[i];
  }
}

template <typename T>
void joint_to_actuator_command(const T& t, MechanismState& s, HardwareInterface mode) {
  const auto J = t.joints();
  const auto A = t.actuators();
  const JointState& j0 = s.joints[J[0]];
  const JointState& j1 = s.joints[J[1]];
  const Pair x = t.joint_to_actuator_position({j0.commanded_position, j1.commanded_position});
  const Pair v = t.joint_to_actuator_velocity({j0.commanded_velocity, j1.commanded_velocity});
  const Pair f = t.joint_to_actuator_effort({j0.commanded_effort, j1.commanded_effort});
  for (int i = 0; i < 2; ++i) {
    ActuatorState& a = s.actuators[A[i]];
    a.commanded_position = x[i];
    a.commanded_velocity = v[i];
    a.commanded_effort = f[i];
    a.command_mode = mode;
  }
}

template <typename T>
void actuator_to_joint_command(const T& t, MechanismState& s) {
  const auto J = t.joints();
  const auto A = t.actuators();
  const ActuatorState& a0 = s.actuators[A[0]];
  const ActuatorState& a1 = s.actuators[A[1]];
  const Pair x = t.actuator_to_joint_position({a0.commanded_position, a1.commanded_position});
  const Pair v = t.actuator_to_joint_velocity({a0.commanded_velocity, a1.commanded_velocity});
  const Pair f = t.actuator_to_joint_effort({a0.commanded_effort, a1.commanded_effort});
  for (int i = 0; i < 2; ++i) {
    JointState& j = s.joints[J[i]];
    j.commanded_position = x[i];
    j.commanded_velocity = v[i];
    j.commanded_effort = f[i];
  }
}

}  // namespace mechsim::mechanism::pair
