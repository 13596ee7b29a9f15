#pragma once
// The four propagations of the PR2 mechanism model, over every transmission of a mechanism.
// Real-time safe: no allocation, no locks, no exceptions.
//
//   sim side (physics -> encoders):     propagate_joint_to_actuator_position (joint -> actuator)
//   manager, before controllers:        propagate_actuator_to_joint_position (actuator -> joint)
//   manager, after controllers+limits:  propagate_joint_to_actuator_effort   (joint -> actuator)
//   sim side (motors -> physics):       propagate_actuator_to_joint_effort   (actuator -> joint)
//
// Position/velocity commands (position and velocity hardware interfaces) travel with the
// effort propagations: commanded_position/commanded_velocity/command_mode go joint -> actuator
// in propagate_joint_to_actuator_effort and back in propagate_actuator_to_joint_effort, which
// overwrites JointState::commanded_* with what the physics must apply.

#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

// Actuator position, velocity, last_measured_effort -> joint position, velocity, measured_effort.
void propagate_actuator_to_joint_position(const MechanismModel& model, MechanismState& state);
// Joint position, velocity, measured_effort -> actuator position, velocity, last_measured_effort.
void propagate_joint_to_actuator_position(const MechanismModel& model, MechanismState& state);
// Joint commands -> actuator commands.
void propagate_joint_to_actuator_effort(const MechanismModel& model, MechanismState& state);
// Actuator commands -> joint commands (what the physics applies).
void propagate_actuator_to_joint_effort(const MechanismModel& model, MechanismState& state);

// Clamps each actuated joint's commanded effort to its effort limit and, where the joint has a
// <safety_controller>, to the PR2's position- and velocity-dependent bounds. Position and
// velocity commands are clamped ros_control-style (position into the soft or hard limits and
// within one period of travel at the velocity limit, velocity to the velocity limit). Non-finite
// commands are replaced (effort and velocity by 0, position by the last good one) and counted in
// state.rejected_commands. The laws are in mechanism/safety_limits.hpp. `period` in s.
inline constexpr double kDefaultPeriod = 0.001;  // s, the 1 kHz tick
void enforce_safety_limits(const MechanismModel& model, MechanismState& state, double period);
void enforce_safety_limits(const MechanismModel& model, MechanismState& state);  // kDefaultPeriod

}  // namespace mechsim::mechanism
