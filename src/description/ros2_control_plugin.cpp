#include "description/ros2_control_plugin.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {

namespace {

namespace fs = std::filesystem;

std::string where(const RobotModel& robot, const GazeboPlugin& p, const XmlNode* node) {
  const int line = node != nullptr && node->line > 0 ? node->line : p.xml.line;
  return (robot.source.empty() ? std::string("<robot>") : robot.source) + ":" + std::to_string(line);
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// The description's own file: RobotModel::source is "PATH" or "PATH (expanded)".
std::string description_dir(const RobotModel& robot) {
  std::string source = robot.source;
  const std::string suffix = " (expanded)";
  if (source.size() > suffix.size() && source.compare(source.size() - suffix.size(), suffix.size(), suffix) == 0) {
    source.resize(source.size() - suffix.size());
  }
  if (source.empty() || source.front() == '<') return {};
  return fs::path(source).parent_path().string();
}

std::string resolve(const std::string& file, const std::string& dir) {
  std::error_code ec;
  if (file.empty()) return {};
  if (fs::is_regular_file(file, ec)) return file;
  if (fs::path(file).is_relative() && !dir.empty()) {
    const fs::path beside = fs::path(dir) / file;
    if (fs::is_regular_file(beside, ec)) return beside.lexically_normal().string();
  }
  return {};
}

}  // namespace

bool is_ros2_control_plugin(const std::string& filename) {
  return filename == "libgazebo_ros2_control.so" || filename == "gz_ros2_control-system" ||
         filename == "libgz_ros2_control-system.so" || filename == "ign_ros2_control-system" ||
         filename == "libign_ros2_control-system.so";
}

std::string normalize_ros2_namespace(const std::string& ns) {
  std::string out = trim(ns);
  while (!out.empty() && out.back() == '/') out.pop_back();
  if (out.empty() || out.front() != '/') out = "/" + out;
  return out;
}

std::string Ros2ControlPlugin::node_namespace() const { return normalize_ros2_namespace(ros_namespace); }

std::string Ros2ControlPlugin::controller_manager_node() const {
  const std::string ns = node_namespace();
  return (ns == "/" ? std::string() : ns) + "/" + controller_manager_name;
}

std::optional<Ros2ControlPlugin> find_ros2_control_plugin(const RobotModel& robot) {
  for (const GazeboPlugin& p : robot.plugins) {
    if (!p.sensor.empty() || !is_ros2_control_plugin(p.filename)) continue;
    Ros2ControlPlugin out;
    out.origin = where(robot, p, nullptr);
    out.name = p.name;
    out.filename = p.filename;
    out.modern_gazebo = p.filename.find("gz_") != std::string::npos || p.filename.find("ign_") != std::string::npos;
    const std::string dir = description_dir(robot);
    for (const XmlNode* e : p.xml.children_named("parameters")) out.parameters.push_back(trim(e->text));
    if (const XmlNode* e = p.xml.child("robot_param"); e != nullptr && !trim(e->text).empty()) out.robot_param = trim(e->text);
    if (const XmlNode* e = p.xml.child("robot_param_node"); e != nullptr && !trim(e->text).empty()) {
      out.robot_param_node = trim(e->text);
    }
    if (const XmlNode* e = p.xml.child("controller_manager_name"); e != nullptr && !trim(e->text).empty()) {
      out.controller_manager_name = trim(e->text);
    }
    if (const XmlNode* e = p.xml.child("hold_joints")) {
      const std::string t = trim(e->text);
      if (t == "true" || t == "1" || t == "True") out.hold_joints = true;
      else if (t == "false" || t == "0" || t == "False") out.hold_joints = false;
      else
        throw DescriptionError(where(robot, p, e) + ": " + p.filename + " <hold_joints>" + t +
                               "</hold_joints> is not a boolean (true, false, 1 or 0)");
    }
    if (const XmlNode* e = p.xml.child("e_stop_topic")) out.e_stop_topic = trim(e->text);
    if (const XmlNode* e = p.xml.child("position_proportional_gain")) {
      const std::string t = trim(e->text);
      char* end = nullptr;
      const double v = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0' || !std::isfinite(v)) {
        throw DescriptionError(where(robot, p, e) + ": " + p.filename + " <position_proportional_gain>" + t +
                               "</position_proportional_gain> is not a number");
      }
      out.position_proportional_gain = v;
    }
    if (const XmlNode* ros = p.xml.child("ros")) {
      if (const XmlNode* ns = ros->child("namespace")) out.ros_namespace = trim(ns->text);
      for (const XmlNode* r : ros->children_named("remapping")) {
        const std::string rule = trim(r->text);
        const auto at = rule.find(":=");
        if (at == std::string::npos || at == 0 || at + 2 == rule.size()) {
          throw DescriptionError(where(robot, p, r) + ": " + p.filename + " <remapping>" + rule +
                                 "</remapping> is not a remapping rule FROM:=TO");
        }
        out.remappings.push_back({rule.substr(0, at), rule.substr(at + 2)});
      }
      const std::vector<const XmlNode*> args = ros->children_named("argument");
      for (const XmlNode* a : args) out.arguments.push_back(trim(a->text));
      for (std::size_t i = 0; i < args.size(); ++i) {
        if (trim(args[i]->text) != "--params-file") continue;
        if (i + 1 >= args.size() || trim(args[i + 1]->text).empty()) {
          throw DescriptionError(where(robot, p, args[i]) + ": " + p.filename +
                                 " <argument>--params-file</argument> is not followed by an <argument> naming the file");
        }
        out.parameters.push_back(trim(args[i + 1]->text));
      }
    }
    for (const std::string& f : out.parameters) out.parameter_paths.push_back(resolve(f, dir));
    return out;
  }
  return std::nullopt;
}

}  // namespace mechsim::description
