#include "mechanism/differential_transmission.hpp"

#include "mechanism/pair_propagation.hpp"
#include "mechanism/transmission_builder.hpp"
#include "mechanism/two_by_two_params.hpp"

namespace mechsim::mechanism {

using pair::Pair;

DifferentialTransmission::DifferentialTransmission(std::string name, std::string type, std::array<int, 2> joints,
                                                   std::array<int, 2> actuators, Pair actuator_reduction,
                                                   Pair joint_reduction, Pair joint_offset)
    : Transmission(std::move(name), std::move(type), {joints[0], joints[1]}, {actuators[0], actuators[1]}),
      na_(actuator_reduction),
      nj_(joint_reduction),
      off_(joint_offset) {}

Pair DifferentialTransmission::actuator_to_joint_position(Pair x) const {
  const double w1 = x[0] / na_[0], w2 = x[1] / na_[1];
  return {(w1 + w2) / (2.0 * nj_[0]) + off_[0], (w1 - w2) / (2.0 * nj_[1]) + off_[1]};
}

Pair DifferentialTransmission::actuator_to_joint_velocity(Pair v) const {
  const double w1 = v[0] / na_[0], w2 = v[1] / na_[1];
  return {(w1 + w2) / (2.0 * nj_[0]), (w1 - w2) / (2.0 * nj_[1])};
}

Pair DifferentialTransmission::actuator_to_joint_effort(Pair tau) const {
  const double a1 = na_[0] * tau[0], a2 = na_[1] * tau[1];
  return {nj_[0] * (a1 + a2), nj_[1] * (a1 - a2)};
}

Pair DifferentialTransmission::joint_to_actuator_position(Pair x) const {
  const double q1 = nj_[0] * (x[0] - off_[0]), q2 = nj_[1] * (x[1] - off_[1]);
  return {na_[0] * (q1 + q2), na_[1] * (q1 - q2)};
}

Pair DifferentialTransmission::joint_to_actuator_velocity(Pair v) const {
  const double q1 = nj_[0] * v[0], q2 = nj_[1] * v[1];
  return {na_[0] * (q1 + q2), na_[1] * (q1 - q2)};
}

Pair DifferentialTransmission::joint_to_actuator_effort(Pair tau) const {
  const double t1 = tau[0] / nj_[0], t2 = tau[1] / nj_[1];
  return {(t1 + t2) / (2.0 * na_[0]), (t1 - t2) / (2.0 * na_[1])};
}

void DifferentialTransmission::actuator_to_joint_state(MechanismState& s) const { pair::actuator_to_joint_state(*this, s); }
void DifferentialTransmission::joint_to_actuator_state(MechanismState& s) const { pair::joint_to_actuator_state(*this, s); }
void DifferentialTransmission::joint_to_actuator_command(MechanismState& s) const {
  pair::joint_to_actuator_command(*this, s, common_mode(s, joints()));
}
void DifferentialTransmission::actuator_to_joint_command(MechanismState& s) const {
  pair::actuator_to_joint_command(*this, s);
}

std::unique_ptr<Transmission> build_differential_transmission(TransmissionBuilder& b) {
  const TwoByTwoParams p = read_two_by_two(b);
  return std::make_unique<DifferentialTransmission>(b.spec().name, b.spec().type, p.joints, p.actuators,
                                                    p.actuator_reduction, p.joint_reduction, p.joint_offset);
}

}  // namespace mechsim::mechanism
