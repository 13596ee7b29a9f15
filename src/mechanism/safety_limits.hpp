#pragma once
// Safety limits on joint commands, per joint. enforce_safety_limits (mechanism/propagation.hpp)
// applies them to every actuated joint of a mechanism. Real-time safe.
//
// Effort (the PR2's JointState::enforceLimits law; the joint is taken as calibrated):
//   no <limit>:                       no bound
//   <limit> without <safety_controller>: -effort <= tau <= effort
//   <limit> and <safety_controller k_position k_velocity soft_lower_limit soft_upper_limit>:
//     velocity bounds (rad/s or m/s), revolute and prismatic joints only
//       v_high = clamp(-k_position * (q - soft_upper_limit), -velocity, velocity)
//       v_low  = clamp(-k_position * (q - soft_lower_limit), -velocity, velocity)
//     continuous joints: v_high = velocity, v_low = -velocity (no position bound)
//     effort bounds (N m or N)
//       tau_high = clamp(-k_velocity * (v - v_high), -effort, effort)
//       tau_low  = clamp(-k_velocity * (v - v_low),  -effort, effort)
//   (Source: pr2_mechanism_model JointState::getLimits, PR2/pr2_mechanism.)
//
// Position commands (ros_control joint_limits_interface, saturation):
//   into [lower, upper] (intersected with [soft_lower_limit, soft_upper_limit] when the joint has
//   a safety controller); no position bound for continuous joints; and, when the velocity limit is
//   positive, within velocity * period of the previous tick's position command (or of the measured
//   position on the first position-commanded tick). The position limits win over reachability.
// Velocity commands: into [-velocity, velocity] when the velocity limit is positive.
// ros2_control joints (JointInfo::command_min/max, a <command_interface>'s min and max): the
// command of the joint's current mode is clamped into [min, max] as well (position: after the
// limits above).
// Non-finite commands: effort and velocity become 0, a position command becomes the previous
// position command (or the measured position); each replacement is counted.

#include <cstdint>

#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

struct EffortBounds {
  double low, high;  // N m or N; +-infinity when unbounded
};

// The effort bounds of the joint in its current state (position, velocity).
EffortBounds effort_bounds(const JointInfo& joint, const JointState& state);

// A position command clamped as above. `reference` is the previous position command or the
// measured position (rad or m); period in s.
double limit_position_command(const JointInfo& joint, double command, double reference, double period);

// A velocity command clamped to the velocity limit (rad/s or m/s).
double limit_velocity_command(const JointInfo& joint, double command);

// All of the above on one joint's commands; returns how many non-finite values it replaced.
int enforce_joint_limits(const JointInfo& joint, JointState& state, double period);

}  // namespace mechsim::mechanism
