#include "description/ros_control_plugin.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {

namespace {

const XmlNode* child(const GazeboPlugin& p, const std::string& name) { return p.xml.child(name); }

std::string where(const RobotModel& robot, const GazeboPlugin& p, const XmlNode* node) {
  const int line = node != nullptr && node->line > 0 ? node->line : p.xml.line;
  return (robot.source.empty() ? std::string("<robot>") : robot.source) + ":" + std::to_string(line);
}

}  // namespace

std::string RosControlPlugin::pid_gains_path(const std::string& joint) const {
  std::string ns = legacy() ? std::string() : robot_namespace;
  while (!ns.empty() && ns.back() == '/') ns.pop_back();
  if (!ns.empty() && ns.front() != '/') ns = "/" + ns;
  return ns + "/gazebo_ros_control/pid_gains/" + joint;
}

std::optional<RosControlPlugin> find_ros_control_plugin(const RobotModel& robot) {
  for (const GazeboPlugin& p : robot.plugins) {
    if (!p.sensor.empty() || p.filename != "libgazebo_ros_control.so") continue;
    RosControlPlugin out;
    out.origin = where(robot, p, nullptr);
    auto text = [&](const char* key) -> std::optional<std::string> {
      auto it = p.parameters.find(key);
      if (it == p.parameters.end()) return std::nullopt;
      return it->second;
    };
    if (auto ns = text("robotNamespace")) out.robot_namespace = *ns;
    if (auto type = text("robotSimType"); type && !type->empty()) out.robot_sim_type = *type;
    if (auto topic = text("eStopTopic")) out.e_stop_topic = *topic;
    if (auto period = text("controlPeriod")) {
      errno = 0;
      char* end = nullptr;
      const double v = std::strtod(period->c_str(), &end);
      if (period->empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v) || v <= 0.0) {
        throw DescriptionError(where(robot, p, child(p, "controlPeriod")) + ": gazebo_ros_control <controlPeriod>" +
                               *period + "</controlPeriod> is not a positive number of seconds");
      }
      out.control_period = v;
    }
    if (auto legacy = text("legacyModeNS")) {
      if (*legacy == "true" || *legacy == "1") out.legacy_mode_ns = true;
      else if (*legacy == "false" || *legacy == "0") out.legacy_mode_ns = false;
      else
        throw DescriptionError(where(robot, p, child(p, "legacyModeNS")) + ": gazebo_ros_control <legacyModeNS>" + *legacy +
                               "</legacyModeNS> is not a boolean (true, false, 1 or 0)");
    }
    return out;
  }
  return std::nullopt;
}

}  // namespace mechsim::description
