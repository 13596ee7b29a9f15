// The tinyxml2 pass before urdfdom: urdfdom logs a vague message and returns null on most bad
// input, so everything it would reject is checked here first, with the element's line.
#include <array>
#include <string>

#include "description/urdf/urdf_reading.hpp"

namespace mechsim::description::detail {

namespace {

using tinyxml2::XMLElement;

std::string quoted(const char* kind, const char* name) {
  return std::string(kind) + " '" + (name != nullptr ? name : "") + "'";
}

void check_origin(const XMLElement& parent, Problems& p, const std::string& what) {
  if (const XMLElement* o = parent.FirstChildElement("origin")) {
    p.numbers_attribute(*o, "xyz", 3, what, false);
    p.numbers_attribute(*o, "rpy", 3, what, false);
  }
}

void check_geometry(const XMLElement& owner, Problems& p, const std::string& what) {
  const XMLElement* g = owner.FirstChildElement("geometry");
  if (g == nullptr) {
    p.error(owner.GetLineNum(), what + ": <" + owner.Name() + "> has no <geometry>");
    return;
  }
  const XMLElement* shape = g->FirstChildElement();
  if (shape == nullptr) {
    p.error(g->GetLineNum(), what + ": <geometry> holds no shape (box, cylinder, sphere or mesh)");
    return;
  }
  const std::string type = shape->Name();
  if (type == "box") {
    p.numbers_attribute(*shape, "size", 3, what, true);
  } else if (type == "cylinder") {
    p.number_attribute(*shape, "radius", what, true);
    p.number_attribute(*shape, "length", what, true);
  } else if (type == "sphere") {
    p.number_attribute(*shape, "radius", what, true);
  } else if (type == "mesh") {
    p.text_attribute(*shape, "filename", what, true);
    p.numbers_attribute(*shape, "scale", 3, what, false);
  } else {
    p.error(shape->GetLineNum(), what + ": unknown geometry <" + type +
                                     "> (expected box, cylinder, sphere or mesh)");
  }
}

void check_material(const XMLElement& m, Problems& p, const std::string& what) {
  p.text_attribute(m, "name", what, true);
  if (const XMLElement* c = m.FirstChildElement("color")) p.numbers_attribute(*c, "rgba", 4, what, true);
  if (const XMLElement* t = m.FirstChildElement("texture")) p.text_attribute(*t, "filename", what, false);
}

void check_link(const XMLElement& e, Problems& p, RobotModel& skeleton) {
  const char* name = e.Attribute("name");
  if (name == nullptr) {
    p.error(e.GetLineNum(), "<link> has no 'name' attribute");
    return;
  }
  const std::string what = quoted("link", name);
  if (const XMLElement* in = e.FirstChildElement("inertial")) {
    check_origin(*in, p, what);
    if (const XMLElement* m = in->FirstChildElement("mass")) {
      p.number_attribute(*m, "value", what, true);
    } else {
      p.error(in->GetLineNum(), what + ": <inertial> has no <mass>");
    }
    if (const XMLElement* i = in->FirstChildElement("inertia")) {
      for (const char* a : {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}) p.number_attribute(*i, a, what, true);
    } else {
      p.error(in->GetLineNum(), what + ": <inertial> has no <inertia>");
    }
  }
  for (const XMLElement* v = e.FirstChildElement("visual"); v; v = v->NextSiblingElement("visual")) {
    check_origin(*v, p, what);
    check_geometry(*v, p, what);
    if (const XMLElement* m = v->FirstChildElement("material")) check_material(*m, p, what);
  }
  for (const XMLElement* c = e.FirstChildElement("collision"); c; c = c->NextSiblingElement("collision")) {
    check_origin(*c, p, what);
    check_geometry(*c, p, what);
  }
  Link link;
  link.name = name;
  link.line = e.GetLineNum();
  skeleton.links.push_back(std::move(link));
}

std::optional<JointType> joint_type(const std::string& t) {
  if (t == "revolute") return JointType::Revolute;
  if (t == "continuous") return JointType::Continuous;
  if (t == "prismatic") return JointType::Prismatic;
  if (t == "fixed") return JointType::Fixed;
  if (t == "floating") return JointType::Floating;
  if (t == "planar") return JointType::Planar;
  return std::nullopt;
}

std::string link_of(const XMLElement& joint, const char* tag, Problems& p, const std::string& what) {
  const XMLElement* e = joint.FirstChildElement(tag);
  if (e == nullptr) {
    p.error(joint.GetLineNum(), what + ": no <" + tag + "> element");
    return {};
  }
  auto link = p.text_attribute(*e, "link", what, true);
  return link.value_or("");
}

void check_joint(const XMLElement& e, Problems& p, RobotModel& skeleton) {
  const char* name = e.Attribute("name");
  if (name == nullptr) {
    p.error(e.GetLineNum(), "<joint> has no 'name' attribute");
    return;
  }
  const std::string what = quoted("joint", name);
  Joint joint;
  joint.name = name;
  joint.line = e.GetLineNum();
  const char* type = e.Attribute("type");
  std::optional<JointType> jt;
  if (type == nullptr) {
    p.error(e.GetLineNum(), what + ": no 'type' attribute");
  } else if (!(jt = joint_type(type))) {
    p.error(e.GetLineNum(), what + ": unknown joint type '" + type +
                                "' (expected revolute, continuous, prismatic, fixed, floating or planar)");
  } else {
    joint.type = *jt;
  }
  joint.parent_link = link_of(e, "parent", p, what);
  joint.child_link = link_of(e, "child", p, what);
  check_origin(e, p, what);
  if (const XMLElement* a = e.FirstChildElement("axis")) p.numbers_attribute(*a, "xyz", 3, what, false);
  const XMLElement* limit = e.FirstChildElement("limit");
  if (limit != nullptr) {
    p.number_attribute(*limit, "lower", what, false);
    p.number_attribute(*limit, "upper", what, false);
    p.number_attribute(*limit, "effort", what, true);
    p.number_attribute(*limit, "velocity", what, true);
  } else if (jt == JointType::Revolute || jt == JointType::Prismatic) {
    p.error(e.GetLineNum(), what + ": a " + type + " joint needs a <limit> element");
  }
  if (const XMLElement* s = e.FirstChildElement("safety_controller")) {
    p.number_attribute(*s, "soft_lower_limit", what, false);
    p.number_attribute(*s, "soft_upper_limit", what, false);
    p.number_attribute(*s, "k_position", what, false);
    p.number_attribute(*s, "k_velocity", what, true);
  }
  if (const XMLElement* c = e.FirstChildElement("calibration")) {
    p.number_attribute(*c, "rising", what, false);
    p.number_attribute(*c, "falling", what, false);
    p.number_attribute(*c, "reference_position", what, false);
  }
  if (const XMLElement* d = e.FirstChildElement("dynamics")) {
    const bool damping = p.number_attribute(*d, "damping", what, false).has_value();
    const bool friction = p.number_attribute(*d, "friction", what, false).has_value();
    if (!damping && !friction && d->Attribute("damping") == nullptr && d->Attribute("friction") == nullptr)
      p.error(d->GetLineNum(), what + ": <dynamics> has neither 'damping' nor 'friction'");
  }
  if (const XMLElement* m = e.FirstChildElement("mimic")) {
    if (auto mimicked = p.text_attribute(*m, "joint", what, true)) {
      Mimic mimic;
      mimic.joint = *mimicked;
      joint.mimic = mimic;
    }
    p.number_attribute(*m, "multiplier", what, false);
    p.number_attribute(*m, "offset", what, false);
  }
  skeleton.joints.push_back(std::move(joint));
}

}  // namespace

void precheck_urdf(const XMLElement& robot, Problems& p, RobotModel& skeleton) {
  if (const char* name = robot.Attribute("name")) {
    skeleton.name = name;
  } else {
    p.error(robot.GetLineNum(), "<robot> has no 'name' attribute");
  }
  for (const XMLElement* e = robot.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "link") {
      check_link(*e, p, skeleton);
    } else if (tag == "joint") {
      check_joint(*e, p, skeleton);
    } else if (tag == "material") {
      check_material(*e, p, "material");
    }
  }
  if (skeleton.links.empty()) p.error(robot.GetLineNum(), "robot '" + skeleton.name + "' has no links");
}

}  // namespace mechsim::description::detail
