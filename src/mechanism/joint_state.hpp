#pragma once
// Per-instance mutable state of joints and actuators (the "data" half of the model/data split).

#include <cstdint>
#include <limits>

namespace mechsim::mechanism {

// How a joint is commanded this tick; chosen by the controller that claims the joint.
enum class HardwareInterface : std::uint8_t { Effort, Position, Velocity };

struct JointState {
  // Measured, propagated forward from the actuators by the transmissions.
  double position = 0.0;         // rad or m
  double velocity = 0.0;         // rad/s or m/s
  double measured_effort = 0.0;  // N m or N
  // Commands written by controllers. Which one is used depends on `command_mode`.
  double commanded_effort = 0.0;    // N m or N (after safety limits)
  double commanded_position = 0.0;  // rad or m
  double commanded_velocity = 0.0;  // rad/s or m/s
  HardwareInterface command_mode = HardwareInterface::Effort;
  // The position command let through by the previous tick's safety limits, the origin of the
  // one-period reachability bound (ros_control's joint-limits semantics). NaN when the joint
  // was not position-commanded on the previous tick.
  double last_position_command = std::numeric_limits<double>::quiet_NaN();  // rad or m
  // N m or N: bound of the physics' effort for this joint in every command mode (a Gazebo model
  // plugin's wheelTorque / maxEffort, as Gazebo's joint "fmax"); 0 keeps the joint's own
  // (its URDF effort limit).
  double effort_limit = 0.0;
};

struct ActuatorState {
  // What the encoders report (joint state propagated backwards by the transmissions).
  double position = 0.0;          // rad (motor side)
  double velocity = 0.0;          // rad/s
  double last_measured_effort = 0.0;  // N m
  // Commands, propagated forward from the joints by the transmissions.
  double commanded_effort = 0.0;    // N m
  double commanded_position = 0.0;  // rad (position interfaces)
  double commanded_velocity = 0.0;  // rad/s (velocity interfaces)
  HardwareInterface command_mode = HardwareInterface::Effort;
};

}  // namespace mechsim::mechanism
