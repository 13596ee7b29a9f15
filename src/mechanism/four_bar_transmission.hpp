#pragma once
// Two actuators, two joints; joint 1 depends on actuator 1 only, joint 2 on both: ros_control's
// transmission_interface/FourBarLinkageTransmission.
//
//   n_a1, n_a2  actuator reductions; n_j1, n_j2 joint reductions (nonzero); x_off1, x_off2 offsets
//
//   actuator -> joint:
//     x_j1 = x_a1 / (n_j1 n_a1) + x_off1                                  (rad or m)
//     x_j2 = (x_a2 / n_a2 - x_a1 / (n_j1 n_a1)) / n_j2 + x_off2
//     v_j1 = v_a1 / (n_j1 n_a1)                                           (rad/s or m/s)
//     v_j2 = (v_a2 / n_a2 - v_a1 / (n_j1 n_a1)) / n_j2
//     tau_j1 = n_j1 n_a1 tau_a1 + n_a2 tau_a2                             (N m or N)
//     tau_j2 = n_j2 n_a2 tau_a2
//   joint -> actuator:
//     x_a1 = n_j1 n_a1 (x_j1 - x_off1)                                    (rad)
//     x_a2 = n_a2 ((x_j1 - x_off1) + n_j2 (x_j2 - x_off2))
//     v_a1 = n_j1 n_a1 v_j1 ;  v_a2 = n_a2 (v_j1 + n_j2 v_j2)             (rad/s)
//     tau_a1 = (tau_j1 - tau_j2 / n_j2) / (n_j1 n_a1)                     (N m)
//     tau_a2 = tau_j2 / (n_j2 n_a2)
//   power: tau_j1 v_j1 + tau_j2 v_j2 = tau_a1 v_a1 + tau_a2 v_a2.
// Sources: the positions and velocities are ros_control's (FourBarLinkageTransmission class
// documentation). ros_control's effort maps (tau_j2 = n_j2 (n_a2 tau_a2 - n_j1 n_a1 tau_a1), ...)
// do not preserve power (ros_control issue #523, ros2_control issue #1746); the efforts here
// are the power-consistent ones (J^-T of the velocity map) that ros2_control adopted in PR #1837.

#include <array>
#include <memory>

#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder;

class FourBarLinkageTransmission final : public Transmission {
 public:
  // joints: {joint1, joint2}; actuators: {actuator1, actuator2}.
  FourBarLinkageTransmission(std::string name, std::string type, std::array<int, 2> joints,
                             std::array<int, 2> actuators, std::array<double, 2> actuator_reduction,
                             std::array<double, 2> joint_reduction, std::array<double, 2> joint_offset = {0.0, 0.0});

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
  std::array<double, 2> na_, nj_, off_;
};

std::unique_ptr<Transmission> build_four_bar_transmission(TransmissionBuilder& b);

}  // namespace mechsim::mechanism
