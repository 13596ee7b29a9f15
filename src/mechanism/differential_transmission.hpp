#pragma once
// Two actuators, two joints, a differential: ros_control's
// transmission_interface/DifferentialTransmission.
//
//   n_a1, n_a2  actuator reductions; n_j1, n_j2 joint reductions (nonzero; sign flips direction)
//   x_off1, x_off2  joint offsets (rad or m)
//
//   actuator -> joint:
//     tau_j1 = n_j1 (n_a1 tau_a1 + n_a2 tau_a2)              (N m or N)
//     tau_j2 = n_j2 (n_a1 tau_a1 - n_a2 tau_a2)
//     v_j1   = (v_a1 / n_a1 + v_a2 / n_a2) / (2 n_j1)        (rad/s or m/s)
//     v_j2   = (v_a1 / n_a1 - v_a2 / n_a2) / (2 n_j2)
//     x_j1   = (x_a1 / n_a1 + x_a2 / n_a2) / (2 n_j1) + x_off1   (rad or m)
//     x_j2   = (x_a1 / n_a1 - x_a2 / n_a2) / (2 n_j2) + x_off2
//   joint -> actuator:
//     tau_a1 = (tau_j1 / n_j1 + tau_j2 / n_j2) / (2 n_a1)    (N m)
//     tau_a2 = (tau_j1 / n_j1 - tau_j2 / n_j2) / (2 n_a2)
//     v_a1   = n_a1 (n_j1 v_j1 + n_j2 v_j2)                  (rad/s)
//     v_a2   = n_a2 (n_j1 v_j1 - n_j2 v_j2)
//     x_a1   = n_a1 (n_j1 (x_j1 - x_off1) + n_j2 (x_j2 - x_off2))   (rad)
//     x_a2   = n_a2 (n_j1 (x_j1 - x_off1) - n_j2 (x_j2 - x_off2))
//   power: with A_i = n_ai tau_ai, w_i = v_ai / n_ai,
//     tau_j1 v_j1 + tau_j2 v_j2 = ((A1 + A2)(w1 + w2) + (A1 - A2)(w1 - w2)) / 2 = A1 w1 + A2 w2.
// Source: ros_control transmission_interface DifferentialTransmission (class documentation and
// implementation; the documentation's joint-2 position and actuator-2 effort denominators have
// typos, the implementation's 2 n_j2 and 2 n_a2 are used).

#include <array>
#include <memory>

#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder;

class DifferentialTransmission final : public Transmission {
 public:
  // joints: {joint1, joint2}; actuators: {actuator1, actuator2}.
  DifferentialTransmission(std::string name, std::string type, std::array<int, 2> joints, std::array<int, 2> actuators,
                           std::array<double, 2> actuator_reduction, std::array<double, 2> joint_reduction,
                           std::array<double, 2> joint_offset = {0.0, 0.0});

  void actuator_to_joint_state(MechanismState& state) const override;
  void joint_to_actuator_state(MechanismState& state) const override;
  void joint_to_actuator_command(MechanismState& state) const override;
  void actuator_to_joint_command(MechanismState& state) const override;

  // The maps on plain numbers (positions include the offsets).
  std::array<double, 2> actuator_to_joint_position(std::array<double, 2> x_a) const;
  std::array<double, 2> actuator_to_joint_velocity(std::array<double, 2> v_a) const;
  std::array<double, 2> actuator_to_joint_effort(std::array<double, 2> tau_a) const;
  std::array<double, 2> joint_to_actuator_position(std::array<double, 2> x_j) const;
  std::array<double, 2> joint_to_actuator_velocity(std::array<double, 2> v_j) const;
  std::array<double, 2> joint_to_actuator_effort(std::array<double, 2> tau_j) const;

 private:
  std::array<double, 2> na_, nj_, off_;
};

std::unique_ptr<Transmission> build_differential_transmission(TransmissionBuilder& b);

}  // namespace mechsim::mechanism
