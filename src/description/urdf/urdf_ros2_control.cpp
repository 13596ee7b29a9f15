// <ros2_control> tags (description/ros2_control.hpp): read_ros2_control reads their structure as
// ros2_control's component parser does (it refuses what that parser refuses: a missing name or
// type, a <hardware> without <plugin>, a <param> without a name, an unknown child of the tag, a
// min/max/initial_value that is not a number); check_ros2_control then checks them against the
// robot, as the parser (Jazzy) and Gazebo's system plugins do. Every message names the file,
// line and element.
#include <cmath>
#include <set>
#include <string>

#include "description/ros2_control.hpp"
#include "description/ros2_control_plugin.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_reading.hpp"

namespace mechsim::description::detail {

namespace {

using tinyxml2::XMLElement;

std::string attr(const XMLElement& e, const char* name) {
  const char* v = e.Attribute(name);
  return v != nullptr ? v : "";
}

std::string text_of(const XMLElement& e) {
  const char* t = e.GetText();
  std::string s = t != nullptr ? t : "";
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// The <param name="...">text</param> children of `e`. ros2_control refuses a <param> without a
// name; one without text reads as "" (Jazzy's parser; Humble's refuses it: we warn).
std::map<std::string, std::string> read_params(const XMLElement& e, Problems& p, const std::string& what) {
  std::map<std::string, std::string> out;
  for (const XMLElement* c = e.FirstChildElement("param"); c != nullptr; c = c->NextSiblingElement("param")) {
    const std::string name = attr(*c, "name");
    if (name.empty()) {
      p.error(c->GetLineNum(), what + ": <param> has no name attribute");
      continue;
    }
    if (c->GetText() == nullptr) p.warning(c->GetLineNum(), what + ": <param name=\"" + name + "\"> has no text");
    out[name] = text_of(*c);
  }
  return out;
}

std::optional<double> number_param(const XMLElement& e, const std::map<std::string, std::string>& params,
                                   const char* key, Problems& p, const std::string& what) {
  auto it = params.find(key);
  if (it == params.end()) return std::nullopt;
  auto v = parse_number(it->second);
  int line = e.GetLineNum();
  for (const XMLElement* c = e.FirstChildElement("param"); c != nullptr; c = c->NextSiblingElement("param")) {
    if (attr(*c, "name") == key) line = c->GetLineNum();
  }
  if (!v || !std::isfinite(*v)) {
    p.error(line, what + ": <param name=\"" + key + "\">" + it->second + "</param> is not a finite number");
    return std::nullopt;
  }
  return v;
}

Ros2ControlInterface read_interface(const XMLElement& e, Problems& p, const std::string& owner) {
  Ros2ControlInterface i;
  i.line = e.GetLineNum();
  i.name = attr(e, "name");
  const std::string kind = e.Name();
  if (i.name.empty()) {
    p.error(i.line, owner + ": <" + kind + "> has no name attribute");
    return i;
  }
  const std::string what = owner + ": " + kind + " '" + i.name + "'";
  i.parameters = read_params(e, p, what);
  i.min = number_param(e, i.parameters, "min", p, what);
  i.max = number_param(e, i.parameters, "max", p, what);
  i.initial_value = number_param(e, i.parameters, "initial_value", p, what);
  if (i.min && i.max && *i.min > *i.max) {
    p.error(i.line, what + ": min " + i.parameters["min"] + " is greater than max " + i.parameters["max"]);
  }
  return i;
}

Ros2ControlComponent read_component(const XMLElement& e, Problems& p, const std::string& tag_what) {
  Ros2ControlComponent c;
  c.line = e.GetLineNum();
  c.name = attr(e, "name");
  const std::string kind = e.Name();
  if (c.name.empty()) {
    p.error(c.line, tag_what + ": <" + kind + "> has no name attribute");
    return c;
  }
  const std::string what = tag_what + ": " + kind + " '" + c.name + "'";
  if (kind == "joint" && e.Attribute("mimic") != nullptr) {
    auto b = parse_bool(attr(e, "mimic"));
    if (!b) p.error(c.line, what + ": mimic=\"" + attr(e, "mimic") + "\" is not a boolean");
    else c.mimic_attribute = *b;
  }
  for (const XMLElement* i = e.FirstChildElement("command_interface"); i != nullptr;
       i = i->NextSiblingElement("command_interface")) {
    c.command_interfaces.push_back(read_interface(*i, p, what));
  }
  for (const XMLElement* i = e.FirstChildElement("state_interface"); i != nullptr; i = i->NextSiblingElement("state_interface")) {
    c.state_interfaces.push_back(read_interface(*i, p, what));
  }
  c.parameters = read_params(e, p, what);
  if (auto it = c.parameters.find("multiplier"); it != c.parameters.end()) {
    if (auto v = parse_number(it->second); !v || !std::isfinite(*v)) {
      p.error(c.line, what + ": <param name=\"multiplier\">" + it->second + "</param> is not a finite number");
      c.parameters.erase(it);
    }
  }
  return c;
}

}  // namespace

void read_ros2_control(const XMLElement& robot, Problems& p, RobotModel& model) {
  for (const XMLElement* r = robot.FirstChildElement("ros2_control"); r != nullptr;
       r = r->NextSiblingElement("ros2_control")) {
    Ros2ControlHardware h;
    h.line = r->GetLineNum();
    h.name = attr(*r, "name");
    h.type = attr(*r, "type");
    const std::string what = "<ros2_control name=\"" + h.name + "\">";
    if (h.name.empty()) p.error(h.line, "<ros2_control> has no name attribute");
    if (h.type.empty()) p.error(h.line, what + ": no type attribute (system, actuator or sensor)");
    else if (h.type != "system" && h.type != "actuator" && h.type != "sensor")
      p.warning(h.line, what + ": type \"" + h.type + "\" is none of system, actuator, sensor");
    bool has_hardware = false;
    for (const XMLElement* c = r->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "hardware") {
        has_hardware = true;
        const XMLElement* plugin = c->FirstChildElement("plugin");
        if (plugin == nullptr) plugin = c->FirstChildElement("classType");  // Foxy's name for it
        if (plugin == nullptr || text_of(*plugin).empty()) {
          p.error(c->GetLineNum(), what + ": <hardware> names no <plugin> (e.g. gazebo_ros2_control/GazeboSystem)");
        } else {
          h.plugin = text_of(*plugin);
        }
        h.hardware_parameters = read_params(*c, p, what + " <hardware>");
      } else if (tag == "joint") {
        h.joints.push_back(read_component(*c, p, what));
      } else if (tag == "sensor") {
        h.sensors.push_back(read_component(*c, p, what));
      } else if (tag == "gpio") {
        h.gpios.push_back(read_component(*c, p, what));
      } else if (tag == "transmission") {
        h.transmissions.push_back(to_xml_node(*c));
      } else {
        // ros2_control's parser refuses the whole description ("invalid tag name").
        p.error(c->GetLineNum(), what + ": <" + tag + "> is not an element of <ros2_control> (hardware, joint, "
                                         "sensor, gpio or transmission)");
      }
    }
    if (!has_hardware) p.error(h.line, what + ": no <hardware> element");
    model.ros2_control.push_back(std::move(h));
  }
}

void check_ros2_control(RobotModel& model, Problems& p) {
  // The plugin's elements (a bad <hold_joints>, <remapping>, ...) are errors at load, not later.
  try {
    const std::optional<Ros2ControlPlugin> plugin = find_ros2_control_plugin(model);
    if (plugin && model.ros2_control.empty()) {
      p.report().warnings.push_back(plugin->origin + ": " + plugin->filename +
                                    " but no <ros2_control> tag: the controller manager has no hardware");
    }
  } catch (const DescriptionError& e) {
    p.report().errors.push_back(e.what());
  }
  std::map<std::string, const Ros2ControlHardware*> joint_owner;
  for (const Ros2ControlHardware& h : model.ros2_control) {
    const std::string what = "<ros2_control name=\"" + h.name + "\">";
    if (!h.plugin.empty() && !h.gazebo_system()) {
      p.warning(h.line, what + ": hardware plugin '" + h.plugin + "' is not one of Gazebo's (" + kGazeboSystem + ", " +
                            kGazeboSimSystem + "): NOT SIMULATED as written; its joints and sensors are simulated as " +
                            kGazeboSystem + " simulates them");
    }
    for (const Ros2ControlComponent& g : h.gpios) {
      p.warning(g.line, what + ": gpio '" + g.name + "' is NOT SIMULATED (Gazebo's system plugins export no GPIO)");
    }
    if (!h.transmissions.empty()) {
      p.warning(h.transmissions.front().line, what + ": <transmission> inside <ros2_control> is read by ros2_control but "
                                                     "ignored by Gazebo's system plugins; mechsim ignores it too");
    }
    for (const Ros2ControlComponent& j : h.joints) {
      const std::string jw = what + ": joint '" + j.name + "'";
      if (auto [it, fresh] = joint_owner.emplace(j.name, &h); !fresh) {
        p.error(j.line, jw + " is already in <ros2_control name=\"" + it->second->name + "\"> (line " +
                            std::to_string(it->second->line) + ")");
        continue;
      }
      const Joint* urdf = model.joint(j.name);
      if (urdf == nullptr) {
        // Jazzy's parser refuses it ("not found in URDF"); Humble's GazeboSystem skips it.
        p.error(j.line, jw + " is not a joint of the robot");
        continue;
      }
      if (urdf->type == JointType::Fixed || urdf->type == JointType::Floating || urdf->type == JointType::Planar) {
        p.error(j.line, jw + " is a fixed, floating or planar joint (ros2_control takes revolute, continuous and "
                             "prismatic joints)");
      }
      std::set<std::string> seen;
      for (const Ros2ControlInterface& i : j.command_interfaces) {
        if (!seen.insert(i.name).second) p.warning(i.line, jw + ": command interface '" + i.name + "' is given twice");
        if (is_joint_interface(i.name)) continue;
        if (i.name == "position_pid" || i.name == "velocity_pid" || i.name == "acceleration") {
          p.warning(i.line, jw + ": command interface '" + i.name + "' is NOT SIMULATED (mechsim simulates position, "
                                 "velocity and effort); no controller can claim it");
        } else {
          p.error(i.line, jw + ": unknown command interface '" + i.name + "' (Gazebo's systems simulate position, "
                               "velocity and effort)");
        }
      }
      seen.clear();
      for (const Ros2ControlInterface& i : j.state_interfaces) {
        if (!seen.insert(i.name).second) p.warning(i.line, jw + ": state interface '" + i.name + "' is given twice");
        if (!is_joint_interface(i.name)) {
          p.warning(i.line, jw + ": state interface '" + i.name + "' is NOT SIMULATED (position, velocity and effort "
                                 "are); no controller can read it");
        }
        if (i.initial_value && i.name == "velocity" && *i.initial_value != 0.0) {
          p.warning(i.line, jw + ": the initial_value of state interface 'velocity' is not applied (mechsim sets "
                                 "initial positions only)");
        }
      }
      for (const Ros2ControlInterface& i : j.command_interfaces) {
        if (i.initial_value) {
          p.warning(i.line, jw + ": initial_value belongs to a state interface; on command interface '" + i.name +
                                "' it is ignored (as ros2_control's Gazebo systems do)");
        }
      }
      // Mimic joints.
      const bool param_mimic = j.parameters.count("mimic") > 0;
      if (!param_mimic && j.parameters.count("multiplier") > 0) {
        p.warning(j.line, jw + ": <param name=\"multiplier\"> without <param name=\"mimic\"> does nothing");
      }
      if (j.mimic_attribute == true && !urdf->mimic && !param_mimic) {
        p.error(j.line, jw + " has mimic=\"true\" but its URDF joint has no <mimic>");
      }
      const std::optional<Ros2ControlMimic> mimic = ros2_control_mimic(model, j);
      if (!mimic) continue;
      if (model.joint(mimic->leader) == nullptr) {
        p.error(j.line, jw + " mimics joint '" + mimic->leader + "', which is not a joint of the robot");
        continue;
      }
      if (mimic->leader == j.name) {
        p.error(j.line, jw + " mimics itself");
        continue;
      }
      if (find_ros2_control_joint(model, mimic->leader) == nullptr) {
        // Both parsers look the leader up among the ros2_control joints.
        p.error(j.line, jw + " mimics joint '" + mimic->leader + "', which is in no <ros2_control> tag");
        continue;
      }
      if (!j.command_interfaces.empty()) {
        p.warning(j.line, jw + " is a mimic joint with command interfaces: it follows '" + mimic->leader +
                              "' and no controller can command it (Jazzy's parser refuses command interfaces on "
                              "an active mimic joint)");
      }
      if (mimic->from_param) {
        Joint* target = nullptr;
        for (Joint& candidate : model.joints)
          if (candidate.name == j.name) target = &candidate;
        if (target->mimic && (target->mimic->joint != mimic->leader || target->mimic->multiplier != mimic->multiplier)) {
          p.warning(j.line, jw + ": <param name=\"mimic\"> (" + mimic->leader + ", multiplier " +
                                std::to_string(mimic->multiplier) + ") differs from its URDF <mimic> (" +
                                target->mimic->joint + "); the parameters win, as in gazebo_ros2_control");
        }
        // Gazebo's system makes the follower track the leader; mechsim's physics does it with a
        // constraint, as for a URDF <mimic>.
        target->mimic = Mimic{mimic->leader, mimic->multiplier, 0.0};
      }
    }
    std::set<std::string> sensors;
    for (const Ros2ControlComponent& s : h.sensors) {
      const std::string sw = what + ": sensor '" + s.name + "'";
      if (!sensors.insert(s.name).second) p.error(s.line, sw + " is given twice");
      if (!s.command_interfaces.empty()) {
        p.warning(s.command_interfaces.front().line, sw + ": sensors have no command interfaces; ignored");
      }
      bool imu = false, ft = false;
      for (const Ros2ControlInterface& i : s.state_interfaces) {
        if (is_imu_interface(i.name)) {
          imu = true;
        } else if (is_force_torque_interface(i.name)) {
          ft = true;
        } else {
          // GazeboSystem looks the name up in a fixed table and fails on any other.
          p.error(i.line, sw + ": unknown state interface '" + i.name + "' (an IMU has orientation.x ... w, "
                               "angular_velocity.x ... z, linear_acceleration.x ... z; a force-torque sensor force.x "
                               "... z, torque.x ... z)");
        }
      }
      if (imu && ft) p.error(s.line, sw + " mixes IMU and force-torque state interfaces");
      // GazeboSystem binds the component to the Gazebo sensor of the same name in the model, and
      // skips it with a warning when there is none.
      const SensorSpec* spec = nullptr;
      for (const SensorSpec& candidate : model.sensors)
        if (candidate.name == s.name && candidate.type != "plugin") spec = &candidate;
      if (spec == nullptr) {
        p.warning(s.line, sw + " names no <sensor> of the robot's <gazebo> blocks: skipped (as Gazebo's systems skip "
                              "it); a broadcaster of it will not load");
      } else if (imu && spec->type != "imu") {
        p.warning(s.line, sw + " has IMU state interfaces but sensor '" + s.name + "' is of type " + spec->type);
      } else if (ft && spec->type != "force_torque") {
        p.warning(s.line, sw + " has force-torque state interfaces but sensor '" + s.name + "' is of type " + spec->type);
      }
    }
  }
}

}  // namespace mechsim::description::detail
