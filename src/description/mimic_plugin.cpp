#include "description/mimic_plugin.hpp"

#include <cstdlib>

namespace mechsim::description {
namespace {

std::optional<double> number(const GazeboPlugin& p, const char* key, double fallback) {
  auto it = p.parameters.find(key);
  if (it == p.parameters.end()) return fallback;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || end == nullptr || *end != '\0') return std::nullopt;
  return v;
}

}  // namespace

bool is_mimic_joint_plugin(const std::string& filename) {
  return filename == "libroboticsgroup_gazebo_mimic_joint_plugin.so" || is_upatras_mimic_joint_plugin(filename);
}

bool is_upatras_mimic_joint_plugin(const std::string& filename) {
  return filename == "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so";
}

std::optional<MimicPluginSpec> read_mimic_plugin(const GazeboPlugin& plugin) {
  if (!plugin.sensor.empty() || !is_mimic_joint_plugin(plugin.filename)) return std::nullopt;
  MimicPluginSpec s;
  auto joint = plugin.parameters.find("joint");
  auto mimic = plugin.parameters.find("mimicJoint");
  if (joint == plugin.parameters.end() || mimic == plugin.parameters.end()) return std::nullopt;
  s.joint = joint->second;
  s.mimic_joint = mimic->second;
  const auto multiplier = number(plugin, "multiplier", 1.0);
  const auto offset = number(plugin, "offset", 0.0);
  if (!multiplier || !offset) return std::nullopt;
  s.multiplier = *multiplier;
  s.offset = *offset;
  // upatras: <hasPID/> (or <hasPID>gains namespace</hasPID>) is there or not; roboticsgroup's
  // reads its value as a boolean.
  if (auto pid = plugin.parameters.find("hasPID"); pid != plugin.parameters.end()) {
    const std::string& t = pid->second;
    s.has_pid = is_upatras_mimic_joint_plugin(plugin.filename) || t.empty() || t == "true" || t == "1";
  }
  return s;
}

std::vector<MimicPluginSpec> mimic_plugins(const RobotModel& robot) {
  std::vector<MimicPluginSpec> out;
  for (const GazeboPlugin& p : robot.plugins) {
    if (auto s = read_mimic_plugin(p)) out.push_back(*s);
  }
  return out;
}

}  // namespace mechsim::description
