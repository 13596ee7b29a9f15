#include "description/robot_model.hpp"

#include "description/ros2_control.hpp"
#include "description/sensor_spec.hpp"

namespace mechsim::description {

RobotModel::RobotModel() = default;
RobotModel::~RobotModel() = default;
RobotModel::RobotModel(const RobotModel&) = default;
RobotModel::RobotModel(RobotModel&&) noexcept = default;
RobotModel& RobotModel::operator=(const RobotModel&) = default;
RobotModel& RobotModel::operator=(RobotModel&&) noexcept = default;

const XmlNode* XmlNode::child(const std::string& child_name) const {
  for (const XmlNode& c : children)
    if (c.name == child_name) return &c;
  return nullptr;
}

std::vector<const XmlNode*> XmlNode::children_named(const std::string& child_name) const {
  std::vector<const XmlNode*> out;
  for (const XmlNode& c : children)
    if (c.name == child_name) out.push_back(&c);
  return out;
}

std::optional<std::string> XmlNode::attribute(const std::string& key) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) return std::nullopt;
  return it->second;
}

const Link* RobotModel::link(const std::string& link_name) const {
  for (const Link& l : links)
    if (l.name == link_name) return &l;
  return nullptr;
}

const Joint* RobotModel::joint(const std::string& joint_name) const {
  for (const Joint& j : joints)
    if (j.name == joint_name) return &j;
  return nullptr;
}

std::size_t RobotModel::dof() const {
  std::size_t n = 0;
  for (const Joint& j : joints) {
    if (j.mimic) continue;
    switch (j.type) {
      case JointType::Revolute:
      case JointType::Continuous:
      case JointType::Prismatic: ++n; break;
      case JointType::Planar: n += 3; break;
      case JointType::Floating: n += 6; break;
      case JointType::Fixed: break;
    }
  }
  return n;
}

double RobotModel::total_mass() const {
  double m = 0.0;
  for (const Link& l : links)
    if (l.inertial) m += l.inertial->mass;
  return m;
}

}  // namespace mechsim::description
