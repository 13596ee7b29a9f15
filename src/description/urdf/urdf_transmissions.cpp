// <transmission> elements, which urdfdom ignores. Two formats occur in real descriptions:
//  - ros_control: <type> element; <joint name> with <hardwareInterface> children; <actuator name>
//    with <mechanicalReduction> and <hardwareInterface> children;
//  - PR2 (pr2_mechanism_model): name/type attributes; <actuator name>, <joint name> and a
//    top-level <mechanicalReduction>; the wrist's rightActuator/leftActuator and
//    flexJoint/rollJoint with mechanicalReduction attributes; the gripper's <gap_joint> (with its
//    screw/linkage parameters), <passive_joint> and <simulated_actuated_joint> entries;
//    <compensator> parameters. The whole element is kept in Transmission::xml.
#include <string>

#include "description/urdf/urdf_reading.hpp"

namespace mechsim::description::detail {

namespace {

using tinyxml2::XMLElement;

std::vector<std::string> hardware_interfaces(const XMLElement& e) {
  std::vector<std::string> out;
  for (const XMLElement* h = e.FirstChildElement("hardwareInterface"); h;
       h = h->NextSiblingElement("hardwareInterface")) {
    const char* t = h->GetText();
    if (t != nullptr) out.push_back(to_xml_node(*h).text);
  }
  return out;
}

std::optional<double> child_reduction(const XMLElement& e, Problems& p, const std::string& what) {
  if (const XMLElement* r = e.FirstChildElement("mechanicalReduction")) return p.number_text(*r, what);
  return std::nullopt;
}

// Numeric attributes of PR2 parameter elements (<gap_joint>, <compensator>, ...): every
// attribute but the names must be a finite number.
void check_numeric_attributes(const XMLElement& e, Problems& p, const std::string& what) {
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    const std::string key = a->Name();
    if (key == "name" || key == "passive_actuated_joint") continue;
    p.number_attribute(e, a->Name(), what, true);
  }
}

void read_one(const XMLElement& e, Problems& p, RobotModel& model) {
  Transmission t;
  t.line = e.GetLineNum();
  t.xml = to_xml_node(e);
  if (const char* name = e.Attribute("name")) {
    t.name = name;
  } else {
    p.error(t.line, "<transmission> has no 'name' attribute");
  }
  const std::string what = "transmission '" + t.name + "'";
  if (const char* type = e.Attribute("type")) t.type = type;
  if (const XMLElement* type = e.FirstChildElement("type")) t.type = to_xml_node(*type).text;
  if (t.type.empty()) p.error(t.line, what + ": no type (neither a 'type' attribute nor a <type> element)");

  auto add_joint = [&](const XMLElement& c, const std::string& role, std::optional<double> reduction) {
    auto name = p.text_attribute(c, "name", what, true);
    if (!name) return;
    TransmissionJoint j;
    j.name = *name;
    j.role = role;
    j.hardware_interfaces = hardware_interfaces(c);
    j.mechanical_reduction = reduction;
    t.joints.push_back(std::move(j));
  };
  auto add_actuator = [&](const XMLElement& c, const std::string& role, std::optional<double> reduction) {
    auto name = p.text_attribute(c, "name", what, true);
    if (!name) return;
    TransmissionActuator a;
    a.name = *name;
    a.role = role;
    a.hardware_interfaces = hardware_interfaces(c);
    a.mechanical_reduction = reduction;
    t.actuators.push_back(std::move(a));
  };

  for (const XMLElement* c = e.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag == "joint") {
      add_joint(*c, "", child_reduction(*c, p, what));
    } else if (tag == "actuator") {
      add_actuator(*c, "", child_reduction(*c, p, what));
    } else if (tag == "mechanicalReduction") {
      t.mechanical_reduction = p.number_text(*c, what);
    } else if (tag == "rightActuator" || tag == "leftActuator") {
      add_actuator(*c, tag == "rightActuator" ? "right" : "left",
                   p.number_attribute(*c, "mechanicalReduction", what, true));
    } else if (tag == "flexJoint" || tag == "rollJoint") {
      add_joint(*c, tag == "flexJoint" ? "flex" : "roll",
                p.number_attribute(*c, "mechanicalReduction", what, true));
    } else if (tag == "gap_joint") {
      check_numeric_attributes(*c, p, what);
      add_joint(*c, "gap", p.number_attribute(*c, "mechanical_reduction", what, false));
    } else if (tag == "passive_joint") {
      add_joint(*c, "passive", std::nullopt);
    } else if (tag == "simulated_actuated_joint") {
      check_numeric_attributes(*c, p, what);
      add_joint(*c, "simulated_actuated", std::nullopt);
    } else if (tag == "compensator") {
      check_numeric_attributes(*c, p, what);
    }
  }
  if (t.joints.empty()) p.error(t.line, what + ": names no joint");
  if (t.actuators.empty()) p.error(t.line, what + ": names no actuator");
  model.transmissions.push_back(std::move(t));
}

}  // namespace

void read_transmissions(const XMLElement& robot, Problems& p, RobotModel& model) {
  for (const XMLElement* e = robot.FirstChildElement("transmission"); e != nullptr;
       e = e->NextSiblingElement("transmission")) {
    read_one(*e, p, model);
  }
}

}  // namespace mechsim::description::detail
