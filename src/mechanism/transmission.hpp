#pragma once
// The abstract transmission: maps actuator space (motor angle, velocity, torque) to joint space
// (joint position, velocity, effort) and back, preserving power. A transmission is built once
// with the indices of its joints and actuators in the MechanismModel (resolved from the names in
// the URDF) and then reads and writes a MechanismState through them. Every propagation function
// is real-time safe: no allocation, no locks, no exceptions.

#include <span>
#include <string>
#include <vector>

#include "mechanism/joint_state.hpp"

namespace mechsim::mechanism {

struct MechanismState;  // mechanism/mechanism_model.hpp

// How a mechanism joint takes part in its transmission.
enum class JointRole : std::uint8_t {
  Actuated,           // driven by the transmission; controllers command it
  Passive,            // moved by the transmission (PR2 gripper fingers), never commanded
  SimulatedActuated,  // PR2 simulated_actuated_joint (Gazebo screw joint); the physics may ignore it
  Direct,             // no transmission: a Gazebo model plugin drives or reads it (mechanism/direct_joints.hpp)
};

class Transmission {
 public:
  Transmission(std::string name, std::string type, std::vector<int> joints, std::vector<int> actuators);
  virtual ~Transmission() = default;
  Transmission(const Transmission&) = delete;
  Transmission& operator=(const Transmission&) = delete;

  const std::string& name() const { return name_; }
  const std::string& type() const { return type_; }  // as written in the URDF
  // Indices into MechanismModel::joints / ::actuators, in the transmission's own order
  // (documented by each subclass).
  std::span<const int> joints() const { return joints_; }
  std::span<const int> actuators() const { return actuators_; }

  // Actuator position, velocity, last_measured_effort -> joint position, velocity, measured_effort.
  virtual void actuator_to_joint_state(MechanismState& state) const = 0;
  // Joint position, velocity, measured_effort -> actuator position, velocity, last_measured_effort.
  virtual void joint_to_actuator_state(MechanismState& state) const = 0;
  // Joint commanded_effort/position/velocity and command_mode -> actuator commands.
  virtual void joint_to_actuator_command(MechanismState& state) const = 0;
  // Actuator commands -> joint commanded_effort/position/velocity (what the physics applies).
  virtual void actuator_to_joint_command(MechanismState& state) const = 0;

 protected:
  // The command mode the actuators take: the joints' common mode, or Effort when the actuated
  // joints of one coupled transmission are commanded in different modes (each joint still gets
  // its own command back from actuator_to_joint_command, as every quantity is mapped).
  HardwareInterface common_mode(const MechanismState& state, std::span<const int> actuated) const;

 private:
  std::string name_;
  std::string type_;
  std::vector<int> joints_;
  std::vector<int> actuators_;
};

}  // namespace mechsim::mechanism
