#pragma once
// The PR2 wrist: two motors (right, left) drive the flex and roll joints through a bevel-gear
// differential: pr2_mechanism_model/WristTransmission.
//
//   n_r, n_l  actuator reductions (<rightActuator>/<leftActuator mechanicalReduction>)
//   n_f, n_o  joint reductions (<flexJoint>/<rollJoint mechanicalReduction>; the PR2 uses
//             n_f = -1, n_o = 1 and n_r = n_l = 624/35 * 54/16)
//
//   actuator -> joint (x: rad, v: rad/s, tau: N m):
//     x_flex = ( x_r / n_r - x_l / n_l) / (2 n_f)
//     x_roll = (-x_r / n_r - x_l / n_l) / (2 n_o)          (same for velocities)
//     tau_flex = n_f ( n_r tau_r - n_l tau_l)
//     tau_roll = n_o (-n_r tau_r - n_l tau_l)
//   joint -> actuator:
//     x_r = n_r ( n_f x_flex - n_o x_roll)
//     x_l = n_l (-n_f x_flex - n_o x_roll)                  (same for velocities)
//     tau_r = ( tau_flex / n_f - tau_roll / n_o) / (2 n_r)
//     tau_l = (-tau_flex / n_f - tau_roll / n_o) / (2 n_l)
//   power: with A = n_r tau_r, B = n_l tau_l, u = v_r / n_r, w = v_l / n_l,
//     tau_flex v_flex + tau_roll v_roll = ((A - B)(u - w) + (A + B)(u + w)) / 2 = A u + B w.
// The PR2 adds the calibration reference positions to x_flex and x_roll; a simulated PR2 starts
// calibrated with references 0, which is what this does.
// Source: pr2_mechanism_model WristTransmission (PR2/pr2_mechanism), the parameters of
// pr2_description/urdf/forearm_v0/forearm.transmission.xacro.

#include <array>
#include <memory>

#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder;

class Pr2WristTransmission final : public Transmission {
 public:
  // joints: {flex, roll}; actuators: {right, left}.
  Pr2WristTransmission(std::string name, std::string type, std::array<int, 2> joints, std::array<int, 2> actuators,
                       std::array<double, 2> actuator_reduction, std::array<double, 2> joint_reduction);

  void actuator_to_joint_state(MechanismState& state) const override;
  void joint_to_actuator_state(MechanismState& state) const override;
  void joint_to_actuator_command(MechanismState& state) const override;
  void actuator_to_joint_command(MechanismState& state) const override;

  std::array<double, 2> actuator_to_joint_position(std::array<double, 2> x_a) const;
  std::array<double, 2> actuator_to_joint_velocity(std::array<double, 2> v_a) const;
  std::array<double, 2> actuator_to_joint_effort(std::array<double, 2> tau_a) const;
  std::array<double, 2> joint_to_actuator_position(std::array<double, 2> x_j) const;
  std::array<double, 2> joint_to_actuator_velocity(std::array<double, 2> v_j) const;
  std::array<double, 2> joint_to_actuator_effort(std::array<double, 2> tau_j) const;

 private:
  std::array<double, 2> na_, nj_;
};

std::unique_ptr<Transmission> build_pr2_wrist_transmission(TransmissionBuilder& b);

}  // namespace mechsim::mechanism
