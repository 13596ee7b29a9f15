#include "description/sensor_spec.hpp"

#include <algorithm>
#include <cmath>

namespace mechsim::description {

int RayAxis::count() const {
  const double n = std::round(static_cast<double>(samples) * resolution);
  return std::max(1, static_cast<int>(std::min(n, 1e6)));
}

const char* SensorSpec::kind_name() const {
  switch (details.index()) {
    case 1: return "ray";
    case 2: return "imu";
    case 3: return "contact";
    case 4: return "force_torque";
    case 5: return "ground_truth";
    case 6: return "camera";
    default: return "unsupported";
  }
}

std::string SensorPlugin::full_topic() const {
  if (!topic.empty() && topic.front() == '/') return topic;
  std::string ns = robot_namespace;
  while (!ns.empty() && ns.back() == '/') ns.pop_back();
  if (!ns.empty() && ns.front() != '/') ns.insert(ns.begin(), '/');
  return ns + "/" + topic;
}

std::string SensorSpec::where() const {
  std::string at = source.empty() ? std::string("<robot>") : source;
  if (line > 0) at.append(":").append(std::to_string(line));
  return at.append(": sensor '").append(name).append("'");
}

}  // namespace mechsim::description
