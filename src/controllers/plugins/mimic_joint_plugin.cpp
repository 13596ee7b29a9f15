#include "controllers/plugins/mimic_joint_plugin.hpp"

#include <algorithm>
#include <cmath>

#include "controllers/plugins/plugin_params.hpp"

namespace mechsim::control {

std::vector<std::string> MimicJointPlugin::joints(const Params& params) {
  const PluginParams p(params);
  return {p.required("joint"), p.required("mimicJoint")};
}

bool MimicJointPlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  const std::string leader = p.required("joint"), follower = p.required("mimicJoint");
  if (leader == follower) p.fail("mimicJoint", "names the joint it mimics ('" + leader + "')");
  multiplier_ = p.number("multiplier", 1.0);
  offset_ = p.number("offset", 0.0);
  sensitiveness_ = p.non_negative("sensitiveness", 0.0);
  leader_ = hardware.joint_state(leader, p.location("joint"));
  // Effort mode: with a PID the controller writes the effort; without, the physics' constraint
  // holds the follower and the effort stays 0.
  follower_ = hardware.claim_joint(follower, HardwareInterface::Effort, p.location("mimicJoint"));
  double fallback = 1.0;
  if (upatras_) {
    const auto& limits = follower_.info().limits;
    fallback = limits && limits->effort > 0.0 ? limits->effort : 1.0;
  }
  max_effort_ = p.positive("maxEffort", fallback);
  if (upatras_) {
    has_pid_ = p.has("hasPID");
  } else if (p.has("hasPID")) {
    has_pid_ = p.text("hasPID", "").empty() || p.boolean("hasPID", false);
  }
  if (has_pid_) {
    std::string ns = upatras_ ? p.text("hasPID", "") : "";
    if (ns.empty()) ns = "gazebo_ros_control/pid_gains/" + follower;
    while (!ns.empty() && ns.front() == '/') ns.erase(ns.begin());
    const auto gains = context_.server.find(ns);
    if ((!gains || !gains->is_map()) && !context_.runtime_params) {
      // The gains come with the run (the launch file's YAML): nothing to check yet.
      context_.deferred->push_back(p.location("hasPID") + ": <hasPID>: the PID gains at " + join_param_path(context_.server.path(), ns) +
                                   " are read from the parameter server when the run starts (not checked here)");
    } else {
      if (!gains || !gains->is_map()) {
        p.fail("hasPID", "asks for a PID, but the parameter server has no gains at " +
                             join_param_path(context_.server.path(), ns) + " (p, i, d, i_clamp)");
      }
      pid_.init(*gains);
    }
  }
  JointControllerState prototype;
  state_.init(prototype);
  ros_.robot_namespace = p.text("robotNamespace", "");
  return true;
}

void MimicJointPlugin::starting(double /*time*/) {
  pid_.reset();
  follower_.set_command(0.0);
}

UpdateStatus MimicJointPlugin::update(double time, double period) {
  const double target = multiplier_ * leader_.position() + offset_;
  const double error = target - follower_.position();
  double effort = 0.0;
  if (has_pid_ && std::abs(error) >= sensitiveness_) {
    effort = std::clamp(pid_.compute_command(error, period), -max_effort_, max_effort_);
  }
  follower_.set_command(effort);
  state_.publish_from_rt([&](JointControllerState& s) {
    s.stamp = time;
    s.set_point = target;
    s.process_value = follower_.position();
    s.process_value_dot = follower_.velocity();
    s.error = error;
    s.time_step = period;
    s.command = effort;
    s.gains = pid_.rt_gains();
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
