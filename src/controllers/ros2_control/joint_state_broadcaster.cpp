#include "controllers/ros2_control/joint_state_broadcaster.hpp"

#include <algorithm>
#include <limits>

namespace mechsim::control {

namespace {

std::vector<std::string> list_param(const Params& params, const char* key) {
  if (!params.has(key)) return {};
  const Params p = params.child(key);
  if (p.kind() == Params::Kind::Null) return {};
  return p.is_scalar() ? std::vector<std::string>{p.as<std::string>()} : p.as<std::vector<std::string>>();
}

}  // namespace

bool JointStateBroadcaster::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::vector<std::string> joints = list_param(params, "joints");
  const std::vector<std::string> interfaces = list_param(params, "interfaces");
  const std::vector<std::string> extra = list_param(params, "extra_joints");
  (void)params.get<bool>("use_local_topics", false);
  (void)params.get<bool>("use_urdf_to_filter", true);
  if (!joints.empty() && !interfaces.empty()) {
    const std::string ipath = join_param_path(params.path(), "interfaces");
    for (const std::string& i : interfaces) {
      if (i != "position" && i != "velocity" && i != "effort") {
        throw ControllerConfigError("parameter " + ipath + ": state interface '" + i +
                                    "' is not simulated (position, velocity, effort)");
      }
    }
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const std::string jpath = join_param_path(params.path(), "joints") + "[" + std::to_string(k) + "]";
      Source s;
      s.joint = hardware.joint_state(joints[k], jpath);
      for (const std::string& i : interfaces) {
        if (!s.joint.info().has_state_interface(i)) {
          throw ControllerConfigError("joint '" + joints[k] + "' (" + jpath + ") has no " + i + " state interface, which " +
                                      ipath + " lists");
        }
      }
      const auto has = [&](const char* i) { return std::find(interfaces.begin(), interfaces.end(), i) != interfaces.end(); };
      s.position = has("position");
      s.velocity = has("velocity");
      s.effort = has("effort");
      sources_.push_back(s);
    }
  } else {
    bool any_ros2 = false;
    for (std::size_t j = 0; j < hardware.joint_count(); ++j) any_ros2 = any_ros2 || hardware.joint_state(j).info().ros2_control;
    for (std::size_t j = 0; j < hardware.joint_count(); ++j) {
      const JointStateHandle h = hardware.joint_state(j);
      const mechanism::JointInfo& info = h.info();
      if (any_ros2 ? !info.ros2_control : info.role == mechanism::JointRole::Direct) continue;
      Source s;
      s.joint = h;
      s.position = info.has_state_interface("position");
      s.velocity = info.has_state_interface("velocity");
      s.effort = info.has_state_interface("effort");
      if (s.position || s.velocity || s.effort) sources_.push_back(s);
    }
  }
  JointStateSnapshot prototype;
  for (const Source& s : sources_) prototype.names.push_back(s.joint.name());
  for (const std::string& e : extra) prototype.names.push_back(e);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  prototype.position.assign(prototype.names.size(), nan);
  prototype.velocity.assign(prototype.names.size(), nan);
  prototype.effort.assign(prototype.names.size(), nan);
  for (std::size_t k = sources_.size(); k < prototype.names.size(); ++k) {
    prototype.position[k] = prototype.velocity[k] = prototype.effort[k] = 0.0;
  }
  joint_states_.init(prototype);
  return true;
}

UpdateStatus JointStateBroadcaster::update(double time, double /*period*/) {
  joint_states_.publish_from_rt([&](JointStateSnapshot& s) {
    s.stamp = time;
    for (std::size_t k = 0; k < sources_.size(); ++k) {
      const Source& src = sources_[k];
      if (src.position) s.position[k] = src.joint.position();
      if (src.velocity) s.velocity[k] = src.joint.velocity();
      if (src.effort) s.effort[k] = src.joint.effort();
    }
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
