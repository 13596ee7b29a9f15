#include "controllers/plugins/gazebo_ros_names.hpp"

namespace mechsim::control {

std::string tf_resolve(const std::string& prefix, const std::string& name) {
  if (!name.empty() && name.front() == '/') return name.substr(1);
  if (prefix.empty()) return name;
  return (prefix.front() == '/' ? prefix.substr(1) : prefix) + "/" + name;
}

std::string GazeboRosNames::frame(const std::string& name) const { return tf_resolve(tf_prefix, name); }

GazeboRosNames gazebo_ros_names(const PluginParams& params, const std::string& model_name) {
  GazeboRosNames out;
  if (params.has("robotNamespace")) {
    out.robot_namespace = params.text("robotNamespace", "");
    if (out.robot_namespace.empty()) out.robot_namespace = model_name;
  }
  out.tf_prefix = out.robot_namespace;
  while (!out.tf_prefix.empty() && out.tf_prefix.back() == '/') out.tf_prefix.pop_back();
  return out;
}

}  // namespace mechsim::control
