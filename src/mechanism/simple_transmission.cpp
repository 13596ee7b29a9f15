#include "mechanism/simple_transmission.hpp"

#include <algorithm>
#include <sstream>

#include "mechanism/hardware_interface.hpp"
#include "mechanism/mechanism_model.hpp"
#include "mechanism/transmission_builder.hpp"
#include "mechanism/transmission_factory.hpp"

namespace mechsim::mechanism {

namespace {
std::vector<int> joint_list(int joint, int simulated) {
  if (simulated >= 0) return {joint, simulated};
  return {joint};
}
}  // namespace

SimpleTransmission::SimpleTransmission(std::string name, std::string type, int joint, int actuator,
                                       double reduction, double offset, int simulated_joint,
                                       double simulated_reduction)
    : Transmission(std::move(name), std::move(type), joint_list(joint, simulated_joint), {actuator}),
      reduction_(reduction),
      offset_(offset),
      simulated_reduction_(simulated_reduction) {}

void SimpleTransmission::actuator_to_joint_state(MechanismState& state) const {
  const ActuatorState& a = state.actuators[actuators()[0]];
  JointState& j = state.joints[joints()[0]];
  j.position = a.position / reduction_ + offset_;
  j.velocity = a.velocity / reduction_;
  j.measured_effort = a.last_measured_effort * reduction_;
}

void SimpleTransmission::joint_to_actuator_state(MechanismState& state) const {
  const JointState& j = state.joints[joints()[0]];
  ActuatorState& a = state.actuators[actuators()[0]];
  a.position = (j.position - offset_) * reduction_;
  a.velocity = j.velocity * reduction_;
  a.last_measured_effort = j.measured_effort / reduction_;
}

void SimpleTransmission::joint_to_actuator_command(MechanismState& state) const {
  const JointState& j = state.joints[joints()[0]];
  ActuatorState& a = state.actuators[actuators()[0]];
  a.commanded_effort = j.commanded_effort / reduction_;
  a.commanded_position = (j.commanded_position - offset_) * reduction_;
  a.commanded_velocity = j.commanded_velocity * reduction_;
  a.command_mode = j.command_mode;
}

void SimpleTransmission::actuator_to_joint_command(MechanismState& state) const {
  const ActuatorState& a = state.actuators[actuators()[0]];
  JointState& j = state.joints[joints()[0]];
  j.commanded_effort = a.commanded_effort * reduction_;
  j.commanded_position = a.commanded_position / reduction_ + offset_;
  j.commanded_velocity = a.commanded_velocity / reduction_;
  if (has_simulated_joint()) {
    JointState& screw = state.joints[joints()[1]];
    screw.commanded_effort = a.commanded_effort * reduction_ / simulated_reduction_;
    screw.command_mode = HardwareInterface::Effort;
  }
}

namespace {

// ros_control puts the reduction on the actuator, the PR2 format at the top level. Gazebo's
// default ros_control plugin ignores the reduction, so a ros_control transmission without one
// gets 1; the PR2 loader requires it.
double reduction_of(const TransmissionBuilder& b, const description::TransmissionActuator& aentry) {
  const std::optional<double> fallback = b.ros_control_format() ? std::optional<double>(1.0) : std::nullopt;
  return b.reduction(aentry.mechanical_reduction ? aentry.mechanical_reduction : b.spec().mechanical_reduction,
                     fallback, "mechanicalReduction", aentry.name, b.line_of(aentry.name));
}

double offset_of(const TransmissionBuilder& b, const description::TransmissionJoint& jentry) {
  if (const description::XmlNode* jx = b.xml_child("joint", jentry.name))
    return b.number_child(*jx, "offset", jentry.name).value_or(0.0);
  return 0.0;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

bool add_to_driven_joint(TransmissionBuilder& b, const description::RobotModel& robot, const MechanismModel& model) {
  const description::Transmission& spec = b.spec();
  if (!is_simple_transmission_type(spec.type) || spec.joints.size() != 1 || spec.actuators.size() != 1) return false;
  const description::TransmissionJoint& jentry = spec.joints[0];
  const description::TransmissionActuator& aentry = spec.actuators[0];
  if (!jentry.role.empty() || !aentry.role.empty()) return false;
  const int index = model.joint_index(jentry.name);
  if (index < 0) return false;
  const JointInfo& info = model.joints[static_cast<std::size_t>(index)];
  if (info.role != JointRole::Actuated || info.transmission < 0) return false;
  const auto* first = dynamic_cast<const SimpleTransmission*>(model.transmissions[static_cast<std::size_t>(info.transmission)].get());
  if (first == nullptr || first->has_simulated_joint()) return false;  // "already driven" as usual

  int first_line = 0;
  for (const description::Transmission& t : robot.transmissions) {
    if (&t == &spec) break;
    const bool names_it = std::any_of(t.joints.begin(), t.joints.end(),
                                      [&](const description::TransmissionJoint& j) { return j.name == jentry.name; });
    if (names_it) {
      first_line = t.line;
      break;
    }
  }
  const std::string first_text = "transmission '" + first->name() + "'" +
                                 (first_line > 0 ? " (line " + std::to_string(first_line) + ")" : std::string());
  const double reduction = reduction_of(b, aentry);
  const double offset = offset_of(b, jentry);
  if (reduction != first->reduction() || offset != first->offset()) {
    b.fail("joint '" + jentry.name + "' is already driven by " + first_text + " with reduction " +
               number(first->reduction()) + " and offset " + number(first->offset()) + "; this one gives " +
               number(reduction) + " and " + number(offset) +
               ": two motors would drive one joint in conflicting ways (transmissions that add an interface to a "
               "joint must agree on reduction and offset)",
           jentry.name, b.line_of(jentry.name));
  }
  if (const int a = model.actuator_index(aentry.name); a >= 0 && model.actuators[static_cast<std::size_t>(a)].transmission != info.transmission) {
    b.fail("actuator '" + aentry.name + "' already belongs to transmission '" +
               model.transmissions[static_cast<std::size_t>(model.actuators[static_cast<std::size_t>(a)].transmission)]->name() +
               "', which drives another joint",
           aentry.name, b.line_of(aentry.name));
  }
  for (const std::string& text : aentry.hardware_interfaces)
    if (!parse_hardware_interface(text))
      b.fail("actuator '" + aentry.name + "': unknown hardware interface '" + text + "'", aentry.name, b.line_of(aentry.name));
  b.add_interfaces(index, jentry);
  return true;
}

std::unique_ptr<Transmission> build_simple_transmission(TransmissionBuilder& b) {
  const description::Transmission& spec = b.spec();
  const description::TransmissionJoint& jentry = b.joint_entry("");
  const description::TransmissionActuator& aentry = b.actuator_entry("");
  const int actuator = b.actuator(aentry);
  const int joint = b.joint(jentry, JointRole::Actuated);
  const double reduction = reduction_of(b, aentry);
  const double offset = offset_of(b, jentry);

  int simulated = -1;
  double simulated_reduction = 1.0;
  const auto sims = b.joint_entries("simulated_actuated");
  if (sims.size() > 1) b.fail("more than one simulated_actuated_joint", sims[1]->name, b.line_of(sims[1]->name));
  if (!sims.empty()) {
    const description::TransmissionJoint& s = *sims[0];
    simulated = b.joint(s, JointRole::SimulatedActuated);
    const description::XmlNode* sx = b.xml_child("simulated_actuated_joint", s.name);
    const double r = sx ? b.number_attribute(*sx, "simulated_reduction", std::nullopt, s.name)
                        : b.reduction(std::nullopt, std::nullopt, "simulated_reduction", s.name, b.line_of(s.name));
    simulated_reduction = b.reduction(r, std::nullopt, "simulated_reduction of '" + s.name + "'", s.name, b.line_of(s.name));
  }
  for (const description::TransmissionJoint& j : spec.joints)
    if (!j.role.empty() && j.role != "simulated_actuated")
      b.fail("joint '" + j.name + "' has role '" + j.role + "', which a SimpleTransmission does not have", j.name,
             b.line_of(j.name));
  return std::make_unique<SimpleTransmission>(spec.name, spec.type, joint, actuator, reduction, offset, simulated,
                                              simulated_reduction);
}

}  // namespace mechsim::mechanism
