// <gazebo> extension elements, which urdfdom ignores: per-link surface and physics properties,
// per-joint stop properties, and plugins (model plugins and plugins inside <sensor>s).
#include <set>
#include <string>

#include "description/urdf/urdf_reading.hpp"
#include "description/urdf/urdf_sensors.hpp"

namespace mechsim::description::detail {

namespace {

using tinyxml2::XMLElement;

std::optional<bool> bool_text(const XMLElement& e, Problems& p, const std::string& what) {
  const std::string text = value_text(e);
  auto v = parse_bool(text);
  if (!v) p.error(e.GetLineNum(), what + ": <" + e.Name() + "> is not a boolean: \"" + text + "\"");
  return v;
}

GazeboPlugin read_plugin(const XMLElement& e, const std::string& reference, const std::string& sensor,
                         Problems& p) {
  GazeboPlugin plugin;
  plugin.reference = reference;
  plugin.sensor = sensor;
  plugin.xml = to_xml_node(e);
  plugin.name = plugin.xml.attribute("name").value_or("");
  plugin.filename = plugin.xml.attribute("filename").value_or("");
  if (plugin.filename.empty())
    p.error(e.GetLineNum(), "gazebo plugin '" + plugin.name + "': no 'filename' attribute");
  for (const XmlNode& c : plugin.xml.children)
    if (c.children.empty()) plugin.parameters[c.name] = c.text;
  return plugin;
}

// Returns false when the tag is not a link property.
bool read_link_property(const XMLElement& c, Problems& p, const std::string& what,
                        GazeboLinkProperties& props) {
  const std::string tag = c.Name();
  if (tag == "mu1") props.mu1 = p.number_text(c, what);
  else if (tag == "mu2") props.mu2 = p.number_text(c, what);
  else if (tag == "fdir1") {
    // mu1's direction ("x y z" in the link's collision frame): MuJoCo 2.2.2 chooses its contact
    // frames' tangents itself, so no direction can be followed (physics/contact_defaults.hpp).
    const auto v = parse_numbers(value_text(c));
    if (!v || v->size() != 3) p.error(c.GetLineNum(), what + ": <fdir1> is not three numbers: \"" + value_text(c) + "\"");
    else p.warning(c.GetLineNum(), what + ": <fdir1> not followed (MuJoCo's contact frames have no set direction; mu1 and mu2 make one coefficient, their mean)");
  }
  else if (tag == "kp") props.kp = p.number_text(c, what);
  else if (tag == "kd") props.kd = p.number_text(c, what);
  else if (tag == "minDepth") props.min_depth = p.number_text(c, what);
  else if (tag == "maxVel") props.max_vel = p.number_text(c, what);
  else if (tag == "selfCollide") props.self_collide = bool_text(c, p, what);
  // sdformat's URDF reader knows <laserRetro> (it becomes every collision's <laser_retro>);
  // mechsim also takes the SDF spelling.
  else if (tag == "laserRetro" || tag == "laser_retro") props.laser_retro = p.number_text(c, what);
  else if (tag == "gravity") props.gravity = bool_text(c, p, what);
  else if (tag == "turnGravityOff") {
    if (auto off = bool_text(c, p, what)) props.gravity = !*off;
  } else if (tag == "material") {
    // Both spellings occur: <material>Gazebo/Grey</material> and <material value="PR2/Red"/>.
    props.material = value_text(c);
  } else {
    return false;
  }
  return true;
}

bool read_joint_property(const XMLElement& c, Problems& p, const std::string& what,
                         GazeboJointProperties& props) {
  const std::string tag = c.Name();
  if (tag == "stopKp") props.stop_kp = p.number_text(c, what);
  else if (tag == "stopKd") props.stop_kd = p.number_text(c, what);
  else if (tag == "fudgeFactor") props.fudge_factor = p.number_text(c, what);
  else if (tag == "provideFeedback") props.provide_feedback = bool_text(c, p, what);
  else if (tag == "implicitSpringDamper") props.implicit_spring_damper = bool_text(c, p, what);
  else return false;
  return true;
}

}  // namespace

void read_gazebo(const XMLElement& robot, Problems& p, RobotModel& model) {
  std::set<std::string> links, joints;
  for (const Link& l : model.links) links.insert(l.name);
  for (const Joint& j : model.joints) joints.insert(j.name);

  for (const XMLElement* g = robot.FirstChildElement("gazebo"); g != nullptr;
       g = g->NextSiblingElement("gazebo")) {
    const std::string reference = g->Attribute("reference") != nullptr ? g->Attribute("reference") : "";
    const bool is_link = links.count(reference) > 0;
    const bool is_joint = !is_link && joints.count(reference) > 0;
    if (!reference.empty() && !is_link && !is_joint)
      p.warning(g->GetLineNum(), "<gazebo reference=\"" + reference + "\"> names no link or joint");
    const std::string what = std::string(is_joint ? "joint '" : "link '") + reference + "' (gazebo)";
    for (const XMLElement* c = g->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "plugin") {
        model.plugins.push_back(read_plugin(*c, reference, "", p));
        read_sensor_plugin(model.plugins.back().xml, model, p, model.sensors);
      } else if (tag == "sensor") {
        const std::string sensor = c->Attribute("name") != nullptr ? c->Attribute("name") : "";
        if (!reference.empty() && !is_link && !is_joint) {
          // Gazebo's URDF reader attaches a sensor to the link it names, and ignores one whose link
          // the robot does not have (a macro used on another robot, a renamed link).
          p.warning(c->GetLineNum(), "sensor '" + sensor + "' left out: <gazebo reference=\"" + reference +
                                         "\"> names no link or joint of the robot (Gazebo ignores it too)");
          continue;
        }
        for (const XMLElement* s = c->FirstChildElement("plugin"); s; s = s->NextSiblingElement("plugin"))
          model.plugins.push_back(read_plugin(*s, reference, sensor, p));
        read_sensor(to_xml_node(*c), reference, model, p, model.sensors);
      } else if (is_link) {
        GazeboLinkProperties& props = model.gazebo_links[reference];
        if (props.line == 0) props.line = g->GetLineNum();
        read_link_property(*c, p, what, props);
      } else if (is_joint) {
        GazeboJointProperties& props = model.gazebo_joints[reference];
        if (props.line == 0) props.line = g->GetLineNum();
        read_joint_property(*c, p, what, props);
      }
    }
  }
}

}  // namespace mechsim::description::detail
