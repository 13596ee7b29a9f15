#include "description/robot_summary.hpp"

#include <iomanip>
#include <map>
#include <sstream>

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
  std::size_t simulated = 0;
  for (const SensorSpec& sensor : model.sensors) simulated += sensor.simulated();
  out << "  sensors:         " << model.sensors.size() << " (" << simulated << " simulated)\n";
  for (const SensorSpec& sensor : model.sensors) out << "    " << describe_sensor(sensor) << "\n";
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
