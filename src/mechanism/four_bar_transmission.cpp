#include "mechanism/four_bar_transmission.hpp"

#include "mechanism/pair_propagation.hpp"
#include "mechanism/transmission_builder.hpp"
#include "mechanism/two_by_two_params.hpp"

namespace mechsim::mechanism {

using pair::Pair;

FourBarLinkageTransmission::FourBarLinkageTransmission(std::string name, std::string type, std::array<int, 2> joints,
                                                       std::array<int, 2> actuators, Pair actuator_reduction,
                                                       Pair joint_reduction, Pair joint_offset)
    : Transmission(std::move(name), std::move(type), {joints[0], joints[1]}, {actuators[0], actuators[1]}),
      na_(actuator_reduction),
      nj_(joint_reduction),
      off_(joint_offset) {}

Pair FourBarLinkageTransmission::actuator_to_joint_velocity(Pair v) const {
  const double v1 = v[0] / (nj_[0] * na_[0]);
  return {v1, (v[1] / na_[1] - v1) / nj_[1]};
}

Pair FourBarLinkageTransmission::actuator_to_joint_position(Pair x) const {
  const Pair q = actuator_to_joint_velocity(x);
  return {q[0] + off_[0], q[1] + off_[1]};
}

Pair FourBarLinkageTransmission::actuator_to_joint_effort(Pair tau) const {
  return {nj_[0] * na_[0] * tau[0] + na_[1] * tau[1], nj_[1] * na_[1] * tau[1]};
}

Pair FourBarLinkageTransmission::joint_to_actuator_velocity(Pair v) const {
  return {nj_[0] * na_[0] * v[0], na_[1] * (v[0] + nj_[1] * v[1])};
}

Pair FourBarLinkageTransmission::joint_to_actuator_position(Pair x) const {
  return joint_to_actuator_velocity({x[0] - off_[0], x[1] - off_[1]});
}

Pair FourBarLinkageTransmission::joint_to_actuator_effort(Pair tau) const {
  return {(tau[0] - tau[1] / nj_[1]) / (nj_[0] * na_[0]), tau[1] / (nj_[1] * na_[1])};
}

void FourBarLinkageTransmission::actuator_to_joint_state(MechanismState& s) const {
  pair::actuator_to_joint_state(*this, s);
}
void FourBarLinkageTransmission::joint_to_actuator_state(MechanismState& s) const {
  pair::joint_to_actuator_state(*this, s);
}
void FourBarLinkageTransmission::joint_to_actuator_command(MechanismState& s) const {
  pair::joint_to_actuator_command(*this, s, common_mode(s, joints()));
}
void FourBarLinkageTransmission::actuator_to_joint_command(MechanismState& s) const {
  pair::actuator_to_joint_command(*this, s);
}

std::unique_ptr<Transmission> build_four_bar_transmission(TransmissionBuilder& b) {
  const TwoByTwoParams p = read_two_by_two(b);
  return std::make_unique<FourBarLinkageTransmission>(b.spec().name, b.spec().type, p.joints, p.actuators,
                                                      p.actuator_reduction, p.joint_reduction, p.joint_offset);
}

}  // namespace mechsim::mechanism
