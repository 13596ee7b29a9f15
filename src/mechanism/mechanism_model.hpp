#pragma once
// The mechanism of one robot: joints, actuators and the transmissions between them, built once
// from a description::RobotModel (MechanismModel, immutable) plus the per-instance state
// (MechanismState). Hot-path functions take (const MechanismModel&, MechanismState&) and neither
// allocate nor throw.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "mechanism/joint_state.hpp"

namespace mechsim::mechanism {

class Transmission;  // mechanism/transmission.hpp

struct JointInfo {
  std::string name;
  description::JointType type = description::JointType::Revolute;
  bool continuous = false;  // continuous joints have no position limits and wrap for PID errors
  std::optional<description::JointLimits> limits;
  std::optional<description::SafetyController> safety;
  std::optional<description::Mimic> mimic;
  // Hardware interfaces the transmissions make available for this joint (Effort if the
  // transmission names none, as the PR2 format does).
  std::vector<HardwareInterface> interfaces;
};

struct ActuatorInfo {
  std::string name;
};

struct MechanismModel {
  std::vector<JointInfo> joints;       // only joints driven by a transmission (+ passive ones)
  std::vector<ActuatorInfo> actuators;
  std::vector<std::unique_ptr<const Transmission>> transmissions;

  int joint_index(const std::string& name) const;     // -1 when absent
  int actuator_index(const std::string& name) const;  // -1 when absent
};

struct MechanismState {
  std::vector<JointState> joints;        // indexed like MechanismModel::joints
  std::vector<ActuatorState> actuators;  // indexed like MechanismModel::actuators
};

}  // namespace mechsim::mechanism
