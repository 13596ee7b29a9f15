#include "mechanism/pr2_wrist_transmission.hpp"

#include "mechanism/pair_propagation.hpp"
#include "mechanism/transmission_builder.hpp"

namespace mechsim::mechanism {

using pair::Pair;

Pr2WristTransmission::Pr2WristTransmission(std::string name, std::string type, std::array<int, 2> joints,
                                           std::array<int, 2> actuators, Pair actuator_reduction, Pair joint_reduction)
    : Transmission(std::move(name), std::move(type), {joints[0], joints[1]}, {actuators[0], actuators[1]}),
      na_(actuator_reduction),
      nj_(joint_reduction) {}

Pair Pr2WristTransmission::actuator_to_joint_velocity(Pair v) const {
  const double u = v[0] / na_[0], w = v[1] / na_[1];
  return {(u - w) / (2.0 * nj_[0]), (-u - w) / (2.0 * nj_[1])};
}

Pair Pr2WristTransmission::actuator_to_joint_position(Pair x) const { return actuator_to_joint_velocity(x); }

Pair Pr2WristTransmission::actuator_to_joint_effort(Pair tau) const {
  const double A = na_[0] * tau[0], B = na_[1] * tau[1];
  return {nj_[0] * (A - B), nj_[1] * (-A - B)};
}

Pair Pr2WristTransmission::joint_to_actuator_velocity(Pair v) const {
  const double f = nj_[0] * v[0], r = nj_[1] * v[1];
  return {na_[0] * (f - r), na_[1] * (-f - r)};
}

Pair Pr2WristTransmission::joint_to_actuator_position(Pair x) const { return joint_to_actuator_velocity(x); }

Pair Pr2WristTransmission::joint_to_actuator_effort(Pair tau) const {
  const double f = tau[0] / nj_[0], r = tau[1] / nj_[1];
  return {(f - r) / (2.0 * na_[0]), (-f - r) / (2.0 * na_[1])};
}

void Pr2WristTransmission::actuator_to_joint_state(MechanismState& s) const { pair::actuator_to_joint_state(*this, s); }
void Pr2WristTransmission::joint_to_actuator_state(MechanismState& s) const { pair::joint_to_actuator_state(*this, s); }
void Pr2WristTransmission::joint_to_actuator_command(MechanismState& s) const {
  pair::joint_to_actuator_command(*this, s, common_mode(s, joints()));
}
void Pr2WristTransmission::actuator_to_joint_command(MechanismState& s) const {
  pair::actuator_to_joint_command(*this, s);
}

std::unique_ptr<Transmission> build_pr2_wrist_transmission(TransmissionBuilder& b) {
  const description::Transmission& spec = b.spec();
  const description::TransmissionActuator& right = b.actuator_entry("right");
  const description::TransmissionActuator& left = b.actuator_entry("left");
  const description::TransmissionJoint& flex = b.joint_entry("flex");
  const description::TransmissionJoint& roll = b.joint_entry("roll");
  for (const description::TransmissionJoint& j : spec.joints)
    if (j.role != "flex" && j.role != "roll")
      b.fail("joint '" + j.name + "' is neither the <flexJoint> nor the <rollJoint>", j.name, b.line_of(j.name));
  for (const description::TransmissionActuator& a : spec.actuators)
    if (a.role != "right" && a.role != "left")
      b.fail("actuator '" + a.name + "' is neither the <rightActuator> nor the <leftActuator>", a.name,
             b.line_of(a.name));
  const std::array<int, 2> actuators{b.actuator(right), b.actuator(left)};
  const std::array<int, 2> joints{b.joint(flex, JointRole::Actuated), b.joint(roll, JointRole::Actuated)};
  const Pair na{b.reduction(right.mechanical_reduction, std::nullopt, "mechanicalReduction of the rightActuator",
                            right.name, b.line_of(right.name)),
                b.reduction(left.mechanical_reduction, std::nullopt, "mechanicalReduction of the leftActuator",
                            left.name, b.line_of(left.name))};
  const Pair nj{b.reduction(flex.mechanical_reduction, std::nullopt, "mechanicalReduction of the flexJoint",
                            flex.name, b.line_of(flex.name)),
                b.reduction(roll.mechanical_reduction, std::nullopt, "mechanicalReduction of the rollJoint",
                            roll.name, b.line_of(roll.name))};
  return std::make_unique<Pr2WristTransmission>(spec.name, spec.type, joints, actuators, na, nj);
}

}  // namespace mechsim::mechanism
