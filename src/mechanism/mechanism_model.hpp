#pragma once
// The mechanism of one robot: joints, actuators and the transmissions between them, built once
// from a description::RobotModel (MechanismModel, immutable) plus the per-instance state
// (MechanismState). Hot-path functions take (const MechanismModel&, MechanismState&) and neither
// allocate nor throw. build_mechanism (mechanism/build_mechanism.hpp) makes a MechanismModel.

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "mechanism/base_state.hpp"
#include "mechanism/joint_state.hpp"
#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

struct JointInfo {
  std::string name;
  description::JointType type = description::JointType::Revolute;
  bool continuous = false;  // continuous joints have no position limits and wrap for PID errors
  std::optional<description::JointLimits> limits;
  std::optional<description::SafetyController> safety;
  std::optional<description::Mimic> mimic;
  // Hardware interfaces the transmissions make available for this joint (Effort if the
  // transmission names none, as the PR2 format does). Empty for passive and simulated joints,
  // which no controller may command.
  std::vector<HardwareInterface> interfaces;
  // What the joint is to its transmission. The physics applies commanded efforts to Actuated
  // joints; Passive joints (PR2 gripper fingers) follow the transmission; SimulatedActuated joints
  // (PR2 Gazebo screw joints) carry the PR2 screw torque for a backend that models the screw.
  JointRole role = JointRole::Actuated;
  int transmission = -1;  // index into MechanismModel::transmissions
  int line = 0;           // the URDF <joint> element's line

  // A joint of a <ros2_control> tag (mechanism/ros2_control_joints.hpp). Its `interfaces` are the
  // tag's command interfaces; `state_interfaces` the state interfaces it lists ("position",
  // "velocity", "effort": what ros2_control's broadcasters and controllers may read). ROS 1
  // joints leave them empty: all three are readable.
  bool ros2_control = false;
  std::vector<std::string> state_interfaces;
  // Per command interface (index: HardwareInterface's value), the <command_interface>'s
  // <param name="min"> and "max" (rad, m, rad/s, m/s, N m, N): the safety limits clamp that mode's
  // command into them (mechanism/safety_limits.hpp). +-infinity when not given.
  std::array<double, 3> command_min{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity()};
  std::array<double, 3> command_max{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::infinity()};
  // gazebo_ros2_control's <hold_joints> (default true) on a joint with command interfaces: while
  // no running controller claims it, the controller manager holds it where it was when it
  // became unclaimed (a position command: the plugin's SetVelocity(0) every step holds it as
  // hard), instead of letting it fall.
  bool hold_when_unclaimed = false;

  bool has_interface(HardwareInterface hw) const;
  // Whether ros2_control's state interface `name` is there (every one of position, velocity and
  // effort for a ROS 1 joint).
  bool has_state_interface(const std::string& interface_name) const;
};

struct ActuatorInfo {
  std::string name;
  int transmission = -1;  // index into MechanismModel::transmissions
};

struct MechanismModel {
  std::string source;                  // the description's file, for messages
  // Joints driven by a transmission (+ passive ones), then the Direct joints of model plugins.
  std::vector<JointInfo> joints;
  std::vector<ActuatorInfo> actuators;
  std::vector<std::unique_ptr<const Transmission>> transmissions;

  int joint_index(const std::string& name) const;     // -1 when absent
  int actuator_index(const std::string& name) const;  // -1 when absent
};

struct MechanismState {
  std::vector<JointState> joints;        // indexed like MechanismModel::joints
  std::vector<ActuatorState> actuators;  // indexed like MechanismModel::actuators
  // Non-finite commands (NaN, inf) that enforce_safety_limits replaced since the state was made.
  std::uint64_t rejected_commands = 0;
  // The floating base (a physics port: mechanism/base_state.hpp).
  BaseState base;
  BaseVelocityCommand base_command;
};

// A state sized for `model`, everything at rest and zero.
MechanismState make_state(const MechanismModel& model);

// Whether a physics backend should apply this joint's commands (commanded_effort, or the
// position/velocity servo of its command_mode) after propagate_actuator_to_joint_effort. Passive
// joints carry the finger commands of the PR2 gripper (a backend that moves the fingers instead
// of the gap joint uses those and not the gap's); simulated joints carry the PR2 Gazebo screw
// torque and are for a backend that models the screw. Direct joints take their model plugin's.
inline bool physics_applies_command(const JointInfo& joint) {
  return joint.role == JointRole::Actuated || joint.role == JointRole::Direct;
}

}  // namespace mechsim::mechanism
