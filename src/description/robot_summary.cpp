#include "description/robot_summary.hpp"

#include <iomanip>
#include <map>
#include <sstream>

#include "description/ros2_control.hpp"
#include "description/ros2_control_plugin.hpp"
#include "description/sensor_spec.hpp"

namespace mechsim::description {

namespace {

const char* type_name(JointType t) {
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

// "3 a, 2 b" from name -> count.
std::string counts(const std::map<std::string, std::size_t>& by_name) {
  std::string out;
  for (const auto& [name, n] : by_name) out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + name;
  return out;
}

}  // namespace

std::string summarize_robot(const RobotModel& model) {
  std::ostringstream out;
  out << "robot '" << model.name << "' (" << model.source << ")\n";
  out << "  root link:       " << model.root_link << "\n";
  std::size_t massive = 0;
  for (const Link& l : model.links)
    if (l.inertial && l.inertial->mass > 0.0) ++massive;
  out << "  links:           " << model.links.size() << " (" << massive << " with mass)\n";

  std::map<std::string, std::size_t> joint_types;
  std::size_t mimic = 0;
  for (const Joint& j : model.joints) {
    ++joint_types[type_name(j.type)];
    if (j.mimic) ++mimic;
  }
  out << "  joints:          " << model.joints.size();
  if (!joint_types.empty()) out << ": " << counts(joint_types);
  out << "\n";
  out << "  degrees of freedom: " << model.dof();
  if (mimic > 0) out << " (" << mimic << " mimic joint" << (mimic == 1 ? "" : "s") << " not counted)";
  out << "\n";
  out << "  total mass:      " << std::fixed << std::setprecision(3) << model.total_mass() << " kg\n";
  out.unsetf(std::ios::floatfield);

  std::map<std::string, std::size_t> transmission_types;
  for (const Transmission& t : model.transmissions) ++transmission_types[t.type];
  out << "  transmissions:   " << model.transmissions.size();
  if (!transmission_types.empty()) out << ": " << counts(transmission_types);
  out << "\n";

  out << "  gazebo:          " << model.gazebo_links.size() << " link property sets, "
      << model.gazebo_joints.size() << " joint property sets\n";
  std::size_t sensor_plugins = 0;
  for (const GazeboPlugin& p : model.plugins)
    if (!p.sensor.empty()) ++sensor_plugins;
  out << "  gazebo plugins:  " << model.plugins.size() - sensor_plugins << " model, " << sensor_plugins
      << " sensor\n";
  for (const GazeboPlugin& p : model.plugins) {
    if (!p.sensor.empty()) continue;
    out << "    " << p.name << " (" << p.filename << ")";
    for (const auto& [key, value] : p.parameters) out << " " << key << "=" << value;
    out << "\n";
  }
  out << summarize_ros2_control(model);
  std::size_t simulated = 0;
  for (const SensorSpec& sensor : model.sensors) simulated += sensor.simulated();
  out << "  sensors:         " << model.sensors.size() << " (" << simulated << " simulated)\n";
  for (const SensorSpec& sensor : model.sensors) out << "    " << describe_sensor(sensor) << "\n";
  return out.str();
}

namespace {

// "position [-1, 1]" / "position (initial 0.5)" for one interface.
std::string describe_interface(const Ros2ControlInterface& i) {
  std::ostringstream out;
  out << i.name;
  if (i.min || i.max) {
    out << " [";
    if (i.min) out << *i.min;
    else out << "-inf";
    out << ", ";
    if (i.max) out << *i.max;
    else out << "inf";
    out << "]";
  }
  if (i.initial_value) out << " (initial " << *i.initial_value << ")";
  return out.str();
}

std::string describe_interfaces(const std::vector<Ros2ControlInterface>& list) {
  std::string out;
  for (const Ros2ControlInterface& i : list) out += (out.empty() ? "" : ", ") + describe_interface(i);
  return out.empty() ? "none" : out;
}

}  // namespace

std::string summarize_ros2_control(const RobotModel& model) {
  if (model.ros2_control.empty()) return {};
  std::ostringstream out;
  out << "  ros2_control:    " << model.ros2_control.size() << " hardware component"
      << (model.ros2_control.size() == 1 ? "" : "s") << "\n";
  for (const Ros2ControlHardware& h : model.ros2_control) {
    out << "    " << h.name << " (" << h.type << ", " << (h.plugin.empty() ? std::string("no plugin") : h.plugin)
        << (h.gazebo_system() ? "" : ": NOT a Gazebo system, simulated as one") << ")\n";
    for (const Ros2ControlComponent& j : h.joints) {
      out << "      joint " << j.name << ": command " << describe_interfaces(j.command_interfaces) << "; state "
          << describe_interfaces(j.state_interfaces);
      if (const std::optional<Ros2ControlMimic> m = ros2_control_mimic(model, j)) {
        out << "; mimics " << m->leader << " (x " << m->multiplier;
        if (m->offset != 0.0) out << ", + " << m->offset;
        out << (m->from_param ? ", <param name=\"mimic\">" : ", URDF <mimic>") << ")";
      }
      out << "\n";
    }
    for (const Ros2ControlComponent& c : h.sensors) out << "      sensor " << c.name << ": state " << describe_interfaces(c.state_interfaces) << "\n";
    for (const Ros2ControlComponent& g : h.gpios) out << "      gpio " << g.name << ": NOT SIMULATED\n";
  }
  if (const std::optional<Ros2ControlPlugin> p = find_ros2_control_plugin(model)) {
    out << "    plugin " << p->filename << ": controller manager " << p->controller_manager_node() << ", hold_joints "
        << (p->hold_joints ? "true" : "false");
    for (const Ros2Remapping& r : p->remappings) out << ", remap " << r.from << ":=" << r.to;
    out << "\n";
    for (std::size_t i = 0; i < p->parameters.size(); ++i) {
      out << "      parameters " << p->parameters[i] << (p->parameter_paths[i].empty() ? " (NOT FOUND)" : "") << "\n";
    }
  } else {
    out << "    no gazebo_ros2_control / gz_ros2_control plugin: its defaults (namespace /, controller_manager)\n";
  }
  return out.str();
}

std::string describe_sensor(const SensorSpec& s) {
  std::ostringstream out;
  out << s.name << ": " << s.type;
  if (s.type == "plugin" && s.plugin) out << " " << s.plugin->filename;
  out << " on " << (s.link.empty() ? "?" : s.link);
  if (s.update_rate > 0.0) out << ", " << s.update_rate << " Hz";
  else out << ", every step";
  if (!s.simulated()) {
    out << ", NOT SIMULATED: " << std::get<UnsupportedSpec>(s.details).reason;
  } else if (s.plugin) {
    if (!s.plugin->unsupported.empty()) out << ", not published: " << s.plugin->unsupported;
    else out << ", topic " << s.plugin->full_topic() << " (frame " << s.plugin->frame << ")";
  } else {
    out << ", no ROS plugin: recorded, not published";
  }
  return out.str();
}

}  // namespace mechsim::description
