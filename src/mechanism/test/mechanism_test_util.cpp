#include "mechanism_test_util.hpp"

namespace mechsim::mechanism::test {

using description::JointType;

description::Joint make_joint(const std::string& name, JointType type, std::optional<description::JointLimits> limits,
                              std::optional<description::SafetyController> safety, int line) {
  description::Joint j;
  j.name = name;
  j.type = type;
  j.limits = limits;
  j.safety = safety;
  j.line = line;
  return j;
}

description::RobotModel make_robot(std::vector<description::Joint> joints) {
  description::RobotModel robot;
  robot.name = "test";
  robot.source = "test.urdf";
  robot.root_link = "link0";
  robot.links.push_back(description::Link{});
  robot.links.back().name = "link0";
  for (std::size_t i = 0; i < joints.size(); ++i) {
    joints[i].parent_link = "link" + std::to_string(i);
    joints[i].child_link = "link" + std::to_string(i + 1);
    description::Link l;
    l.name = joints[i].child_link;
    l.parent_joint = joints[i].name;
    robot.links.push_back(l);
  }
  robot.joints = std::move(joints);
  return robot;
}

description::XmlNode xml(const std::string& name, std::vector<std::pair<std::string, std::string>> attributes, int line,
                         std::string text) {
  description::XmlNode n;
  n.name = name;
  for (auto& [k, v] : attributes) n.attributes[k] = v;
  n.line = line;
  n.text = std::move(text);
  return n;
}

description::Transmission ros_simple(const std::string& name, const std::string& joint, const std::string& actuator,
                                     std::optional<double> reduction, const std::string& hw, int line) {
  description::Transmission t;
  t.name = name;
  t.type = "transmission_interface/SimpleTransmission";
  t.line = line;
  description::TransmissionJoint j;
  j.name = joint;
  if (!hw.empty()) j.hardware_interfaces.push_back(hw);
  t.joints.push_back(j);
  description::TransmissionActuator a;
  a.name = actuator;
  a.mechanical_reduction = reduction;
  t.actuators.push_back(a);
  t.xml = xml("transmission", {{"name", name}}, line);
  description::XmlNode jx = xml("joint", {{"name", joint}}, line + 2);
  t.xml.children.push_back(jx);
  t.xml.children.push_back(xml("actuator", {{"name", actuator}}, line + 5));
  return t;
}

description::Transmission pr2_simple(const std::string& name, const std::string& joint, const std::string& actuator,
                                     std::optional<double> reduction, int line) {
  description::Transmission t;
  t.name = name;
  t.type = "pr2_mechanism_model/SimpleTransmission";
  t.line = line;
  t.joints.push_back(description::TransmissionJoint{joint, "", {}, std::nullopt});
  t.actuators.push_back(description::TransmissionActuator{actuator, "", std::nullopt, {}});
  t.mechanical_reduction = reduction;
  t.xml = xml("transmission", {{"name", name}, {"type", t.type}}, line);
  t.xml.children.push_back(xml("actuator", {{"name", actuator}}, line + 1));
  t.xml.children.push_back(xml("joint", {{"name", joint}}, line + 2));
  return t;
}

double joint_power(const MechanismModel& model, const MechanismState& state, bool measured, JointRole role) {
  double p = 0.0;
  for (std::size_t i = 0; i < model.joints.size(); ++i) {
    if (model.joints[i].role != role) continue;
    const JointState& j = state.joints[i];
    p += (measured ? j.measured_effort : j.commanded_effort) * j.velocity;
  }
  return p;
}

double actuator_power(const MechanismState& state, bool measured) {
  double p = 0.0;
  for (const ActuatorState& a : state.actuators) p += (measured ? a.last_measured_effort : a.commanded_effort) * a.velocity;
  return p;
}

}  // namespace mechsim::mechanism::test

#include <algorithm>
#include <cmath>

#include "mechanism/propagation.hpp"

namespace mechsim::mechanism::test {

double joint_round_trip_error(const MechanismModel& model, MechanismState& state, double seed) {
  std::vector<JointState> before(state.joints.size());
  for (std::size_t i = 0; i < model.joints.size(); ++i) {
    if (model.joints[i].role != JointRole::Actuated) continue;
    const double k = seed + 0.37 * static_cast<double>(i);
    JointState& j = state.joints[i];
    j.position = 0.01 + 0.02 * std::sin(k);
    j.velocity = 0.5 * std::cos(1.3 * k);
    j.measured_effort = 3.0 * std::sin(2.1 * k);
    j.commanded_effort = -2.0 * std::cos(0.7 * k);
    j.commanded_position = 0.03 + 0.01 * std::cos(k);
    j.commanded_velocity = 0.2 * std::sin(0.9 * k);
    before[i] = j;
  }
  propagate_joint_to_actuator_position(model, state);
  propagate_joint_to_actuator_effort(model, state);
  for (std::size_t i = 0; i < model.joints.size(); ++i)
    if (model.joints[i].role == JointRole::Actuated) state.joints[i] = JointState{};
  propagate_actuator_to_joint_position(model, state);
  propagate_actuator_to_joint_effort(model, state);
  double err = 0.0;
  for (std::size_t i = 0; i < model.joints.size(); ++i) {
    if (model.joints[i].role != JointRole::Actuated) continue;
    const JointState& a = before[i];
    const JointState& b = state.joints[i];
    for (auto [x, y] : {std::pair{a.position, b.position}, {a.velocity, b.velocity},
                        {a.measured_effort, b.measured_effort}, {a.commanded_effort, b.commanded_effort},
                        {a.commanded_position, b.commanded_position}, {a.commanded_velocity, b.commanded_velocity}})
      err = std::max(err, std::abs(x - y));
  }
  return err;
}

double actuator_round_trip_error(const MechanismModel& model, MechanismState& state, double seed) {
  for (std::size_t i = 0; i < state.actuators.size(); ++i) {
    const double k = seed + 0.41 * static_cast<double>(i);
    ActuatorState& a = state.actuators[i];
    a.position = 3.0 + 2.0 * std::sin(k);
    a.velocity = 10.0 * std::cos(1.7 * k);
    a.last_measured_effort = 0.3 * std::sin(2.3 * k);
    a.commanded_effort = 0.2 * std::cos(0.3 * k);
    a.commanded_position = 4.0 + std::cos(k);
    a.commanded_velocity = 5.0 * std::sin(0.5 * k);
  }
  const std::vector<ActuatorState> before = state.actuators;
  propagate_actuator_to_joint_position(model, state);
  propagate_actuator_to_joint_effort(model, state);
  for (ActuatorState& a : state.actuators) a = ActuatorState{};
  propagate_joint_to_actuator_position(model, state);
  propagate_joint_to_actuator_effort(model, state);
  double err = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const ActuatorState& a = before[i];
    const ActuatorState& b = state.actuators[i];
    for (auto [x, y] : {std::pair{a.position, b.position}, {a.velocity, b.velocity},
                        {a.last_measured_effort, b.last_measured_effort}, {a.commanded_effort, b.commanded_effort},
                        {a.commanded_position, b.commanded_position}, {a.commanded_velocity, b.commanded_velocity}})
      err = std::max(err, std::abs(x - y));
  }
  return err;
}

}  // namespace mechsim::mechanism::test
