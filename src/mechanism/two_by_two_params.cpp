#include "mechanism/two_by_two_params.hpp"

#include <string>

#include "mechanism/transmission_builder.hpp"

namespace mechsim::mechanism {

namespace {

// The entries ordered by their <role> (prefix + "1", prefix + "2"), or in document order when
// none has a role.
template <typename Entry>
std::array<const Entry*, 2> by_role(TransmissionBuilder& b, const std::vector<Entry>& entries, const std::string& element,
                                    const std::string& prefix) {
  if (entries.size() != 2)
    b.fail("needs exactly 2 <" + element + "> entries, has " + std::to_string(entries.size()));
  std::array<const Entry*, 2> out{nullptr, nullptr};
  int with_role = 0;
  for (const Entry& e : entries) {
    const description::XmlNode* x = b.xml_child(element, e.name);
    const description::XmlNode* role = x ? x->child("role") : nullptr;
    if (!role) continue;
    ++with_role;
    int slot = -1;
    if (role->text == prefix + "1") slot = 0;
    if (role->text == prefix + "2") slot = 1;
    if (slot < 0)
      b.fail(element + " '" + e.name + "': <role>" + role->text + "</role> is neither " + prefix + "1 nor " + prefix + "2",
             e.name, role->line);
    if (out[slot]) b.fail("two " + element + "s have the role " + prefix + std::to_string(slot + 1), e.name, role->line);
    out[slot] = &e;
  }
  if (with_role == 0) return {&entries[0], &entries[1]};
  if (with_role != 2) b.fail("only one of the two " + element + "s has a <role>");
  return out;
}

}  // namespace

TwoByTwoParams read_two_by_two(TransmissionBuilder& b) {
  const description::Transmission& spec = b.spec();
  TwoByTwoParams p;
  const auto actuators = by_role(b, spec.actuators, "actuator", "actuator");
  const auto joints = by_role(b, spec.joints, "joint", "joint");
  for (int i = 0; i < 2; ++i) {
    const description::TransmissionActuator& a = *actuators[i];
    p.actuators[i] = b.actuator(a);
    p.actuator_reduction[i] = b.reduction(a.mechanical_reduction, 1.0, "mechanicalReduction of actuator '" + a.name + "'",
                                          a.name, b.line_of(a.name));
  }
  for (int i = 0; i < 2; ++i) {
    const description::TransmissionJoint& j = *joints[i];
    p.joints[i] = b.joint(j, JointRole::Actuated);
    p.joint_reduction[i] = b.reduction(j.mechanical_reduction, 1.0, "mechanicalReduction of joint '" + j.name + "'",
                                       j.name, b.line_of(j.name));
    if (const description::XmlNode* x = b.xml_child("joint", j.name))
      p.joint_offset[i] = b.number_child(*x, "offset", j.name).value_or(0.0);
  }
  return p;
}

}  // namespace mechsim::mechanism
