#include "mechanism/transmission_builder.hpp"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "mechanism/hardware_interface.hpp"

namespace mechsim::mechanism {

using description::JointType;

std::string where(const std::string& source, int line) {
  const std::string file = source.empty() ? std::string("<robot>") : source;
  return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

namespace {

std::optional<double> parse_finite(const std::string& text) {
  const char* begin = text.c_str();
  while (*begin == ' ' || *begin == '\t' || *begin == '\n' || *begin == '\r') ++begin;
  if (*begin == '\0') return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r') ++end;
  if (*end != '\0' || end == begin || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

// The shortest text that reads back as `v` ("0", "1e+300", "nan").
std::string number_text(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

const char* joint_type_name(JointType t) {
  switch (t) {
    case JointType::Revolute: return "revolute";
    case JointType::Continuous: return "continuous";
    case JointType::Prismatic: return "prismatic";
    case JointType::Fixed: return "fixed";
    case JointType::Floating: return "floating";
    case JointType::Planar: return "planar";
  }
  return "?";
}

}  // namespace

TransmissionBuilder::TransmissionBuilder(const description::RobotModel& robot, MechanismModel& model,
                                         const description::Transmission& spec, int index)
    : robot_(robot), model_(model), spec_(spec), index_(index) {}

bool TransmissionBuilder::ros_control_format() const {
  return spec_.type.rfind("transmission_interface/", 0) == 0;
}

void TransmissionBuilder::fail(const std::string& what, const std::string& element, int line) const {
  const int at = line > 0 ? line : spec_.line;
  throw MechanismError(where(robot_.source, at) + "transmission '" + spec_.name + "' (" + spec_.type + "): " + what,
                       spec_.name, element, at);
}

const description::XmlNode* TransmissionBuilder::xml_child(const std::string& element, const std::string& name) const {
  for (const description::XmlNode& c : spec_.xml.children) {
    if (c.name != element) continue;
    if (name.empty()) return &c;
    const auto n = c.attribute("name");
    if (n && *n == name) return &c;
  }
  return nullptr;
}

int TransmissionBuilder::line_of(const std::string& name) const {
  for (const description::XmlNode& c : spec_.xml.children) {
    const auto n = c.attribute("name");
    if (n && *n == name && c.line > 0) return c.line;
  }
  return spec_.line;
}

int TransmissionBuilder::joint(const std::string& name, JointRole role, int line) {
  if (name.empty()) fail("a joint entry has no name", "", line);
  const description::Joint* urdf_joint = robot_.joint(name);
  if (!urdf_joint) fail("joint '" + name + "' is not in the robot", name, line);
  switch (urdf_joint->type) {
    case JointType::Revolute:
    case JointType::Continuous:
    case JointType::Prismatic: break;
    default:
      fail("joint '" + name + "' is " + joint_type_name(urdf_joint->type) +
               "; a transmission drives revolute, continuous and prismatic joints only",
           name, line);
  }
  if (int existing = model_.joint_index(name); existing >= 0) {
    const int other = model_.joints[existing].transmission;
    const std::string other_name = other >= 0 && other < static_cast<int>(model_.transmissions.size())
                                       ? model_.transmissions[other]->name()
                                       : spec_.name;
    fail("joint '" + name + "' is already driven by transmission '" + other_name + "'", name, line);
  }
  JointInfo info;
  info.name = name;
  info.type = urdf_joint->type;
  info.continuous = urdf_joint->type == JointType::Continuous;
  info.limits = urdf_joint->limits;
  info.safety = urdf_joint->safety;
  info.mimic = urdf_joint->mimic;
  info.role = role;
  info.transmission = index_;
  info.line = urdf_joint->line;
  model_.joints.push_back(std::move(info));
  return static_cast<int>(model_.joints.size()) - 1;
}

int TransmissionBuilder::joint(const description::TransmissionJoint& entry, JointRole role) {
  const int index = joint(entry.name, role, line_of(entry.name));
  if (role == JointRole::Actuated) add_interfaces(index, entry);
  return index;
}

void TransmissionBuilder::add_interfaces(int index, const description::TransmissionJoint& entry) {
  const int line = line_of(entry.name);
  // gazebo_ros_control reads the interfaces of the <actuator> when the <joint> names none (with a
  // deprecation warning, which description validation gives).
  const std::vector<std::string>* names = &entry.hardware_interfaces;
  if (names->empty() && spec_.actuators.size() == 1) names = &spec_.actuators[0].hardware_interfaces;
  std::vector<HardwareInterface>& interfaces = model_.joints[static_cast<std::size_t>(index)].interfaces;
  for (const std::string& text : *names) {
    const auto parsed = parse_hardware_interface(text);
    if (!parsed)
      fail("joint '" + entry.name + "': unknown hardware interface '" + text +
               "' (expected EffortJointInterface, PositionJointInterface, VelocityJointInterface or "
               "JointStateInterface, with or without the hardware_interface/ prefix)",
           entry.name, line);
    const auto hw = command_interface(*parsed);
    if (hw && std::find(interfaces.begin(), interfaces.end(), *hw) == interfaces.end()) interfaces.push_back(*hw);
  }
  if (names->empty()) {
    if (ros_control_format())
      fail("joint '" + entry.name + "' names no <hardwareInterface> (neither in its <joint> nor in its <actuator>)",
           entry.name, line);
    if (std::find(interfaces.begin(), interfaces.end(), HardwareInterface::Effort) == interfaces.end())
      interfaces.push_back(HardwareInterface::Effort);
  }
}

int TransmissionBuilder::actuator(const description::TransmissionActuator& entry) {
  const int line = line_of(entry.name);
  if (entry.name.empty()) fail("an actuator entry has no name", "", line);
  if (int existing = model_.actuator_index(entry.name); existing >= 0) {
    const int other = model_.actuators[existing].transmission;
    const std::string other_name = other >= 0 && other < static_cast<int>(model_.transmissions.size())
                                       ? model_.transmissions[other]->name()
                                       : spec_.name;
    fail("actuator '" + entry.name + "' already belongs to transmission '" + other_name + "'", entry.name, line);
  }
  for (const std::string& text : entry.hardware_interfaces)
    if (!parse_hardware_interface(text))
      fail("actuator '" + entry.name + "': unknown hardware interface '" + text + "'", entry.name, line);
  model_.actuators.push_back(ActuatorInfo{entry.name, index_});
  return static_cast<int>(model_.actuators.size()) - 1;
}

const description::TransmissionJoint& TransmissionBuilder::joint_entry(const std::string& role) const {
  const auto found = joint_entries(role);
  if (found.empty()) fail(role.empty() ? std::string("no <joint>") : "no " + role + " joint");
  if (found.size() > 1)
    fail(role.empty() ? std::string("more than one <joint>") : "more than one " + role + " joint",
         found[1]->name, line_of(found[1]->name));
  return *found[0];
}

std::vector<const description::TransmissionJoint*> TransmissionBuilder::joint_entries(const std::string& role) const {
  std::vector<const description::TransmissionJoint*> out;
  for (const description::TransmissionJoint& j : spec_.joints)
    if (j.role == role) out.push_back(&j);
  return out;
}

const description::TransmissionActuator& TransmissionBuilder::actuator_entry(const std::string& role) const {
  const description::TransmissionActuator* found = nullptr;
  for (const description::TransmissionActuator& a : spec_.actuators) {
    if (a.role != role) continue;
    if (found)
      fail(role.empty() ? std::string("more than one <actuator>") : "more than one " + role + " actuator", a.name,
           line_of(a.name));
    found = &a;
  }
  if (!found) fail(role.empty() ? std::string("no <actuator>") : "no " + role + " actuator");
  return *found;
}

double TransmissionBuilder::reduction(std::optional<double> value, std::optional<double> fallback,
                                      const std::string& what, const std::string& element, int line) const {
  if (!value) value = fallback;
  if (!value) fail(what + " is missing", element, line);
  if (!std::isfinite(*value) || *value == 0.0)
    fail(what + " is " + number_text(*value) + "; it must be finite and nonzero", element, line);
  return *value;
}

double TransmissionBuilder::number_attribute(const description::XmlNode& node, const std::string& attribute,
                                             std::optional<double> fallback, const std::string& element) const {
  const auto text = node.attribute(attribute);
  if (!text) {
    if (fallback) return *fallback;
    fail("<" + node.name + "> has no " + attribute + " attribute", element, node.line);
  }
  const auto value = parse_finite(*text);
  if (!value) fail("<" + node.name + "> " + attribute + "=\"" + *text + "\" is not a finite number", element, node.line);
  return *value;
}

std::optional<double> TransmissionBuilder::number_child(const description::XmlNode& node, const std::string& child,
                                                        const std::string& element) const {
  const description::XmlNode* c = node.child(child);
  if (!c) return std::nullopt;
  const auto value = parse_finite(c->text);
  if (!value) fail("<" + child + ">" + c->text + "</" + child + "> is not a finite number", element, c->line);
  return value;
}

}  // namespace mechsim::mechanism
