#include "controllers/plugins/joint_state_publisher_plugin.hpp"

#include <algorithm>

#include "controllers/plugins/gazebo_ros_names.hpp"
#include "controllers/plugins/plugin_params.hpp"

namespace mechsim::control {

std::vector<std::string> JointStatePublisherPlugin::joints(const Params& params) {
  const PluginParams p(params);
  std::string text = p.required("jointName");
  text.erase(std::remove_if(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }),
             text.end());
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty()) p.fail("jointName", "has an empty joint name in \"" + text + "\"");
    out.push_back(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

bool JointStatePublisherPlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  update_period_ = period_of(p.rate("updateRate", 100.0));
  JointStateSnapshot prototype;
  for (const std::string& name : joints(params)) {
    if (hardware.find_joint(name) < 0) p.fail("jointName", "names joint '" + name + "', which the robot does not have");
    joints_.push_back(hardware.joint_state(name));
    prototype.names.push_back(name);
  }
  prototype.position.assign(joints_.size(), 0.0);
  prototype.velocity.assign(joints_.size(), 0.0);
  joint_states_.init(prototype);
  ros_.robot_namespace = gazebo_ros_names(p, context_.robot_name).robot_namespace;
  ros_.topics.push_back({"joint_states", "joint_states", ""});
  return true;
}

void JointStatePublisherPlugin::starting(double time) { last_update_ = time; }

UpdateStatus JointStatePublisherPlugin::update(double time, double /*period*/) {
  if (time - last_update_ < update_period_ - 1e-9) return UpdateStatus::Ok();
  joint_states_.publish_from_rt([&](JointStateSnapshot& s) {
    s.stamp = time;
    for (std::size_t i = 0; i < joints_.size(); ++i) {
      s.position[i] = joints_[i].position();
      s.velocity[i] = joints_[i].velocity();
    }
  });
  last_update_ = update_period_ > 0.0 ? last_update_ + update_period_ : time;
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
