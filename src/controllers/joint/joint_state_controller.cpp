#include "controllers/joint/joint_state_controller.hpp"

#include <cmath>

namespace mechsim::control {

bool JointStateController::init(RobotHardware& hardware, const Params& params, std::string& error) {
  const std::string path = join_param_path(params.path(), "publish_rate");
  if (!params.has("publish_rate")) {
    error = "parameter " + path + " not set (the joint state publishing rate, Hz)";
    return false;
  }
  publish_rate_ = params.get<double>("publish_rate");
  if (!(publish_rate_ > 0.0) || !std::isfinite(publish_rate_)) {
    error = "parameter " + path + " must be a positive rate in Hz, got " + std::to_string(publish_rate_);
    return false;
  }
  JointStateSnapshot prototype;
  for (std::size_t i = 0; i < hardware.joint_count(); ++i) {
    joints_.push_back(hardware.joint_state(i));
    prototype.names.push_back(joints_.back().name());
  }
  prototype.position.assign(joints_.size(), 0.0);
  prototype.velocity.assign(joints_.size(), 0.0);
  prototype.effort.assign(joints_.size(), 0.0);
  joint_states_.init(prototype);
  return true;
}

void JointStateController::starting(double time) { last_publish_time_ = time; }

UpdateStatus JointStateController::update(double time, double /*period*/) {
  const double interval = 1.0 / publish_rate_;
  if (last_publish_time_ + interval < time) {
    const bool published = joint_states_.publish_from_rt([&](JointStateSnapshot& s) {
      s.stamp = time;
      for (std::size_t i = 0; i < joints_.size(); ++i) {
        s.position[i] = joints_[i].position();
        s.velocity[i] = joints_[i].velocity();
        s.effort[i] = joints_[i].effort();
      }
    });
    // Like ros_control, a snapshot skipped because a reader held it is retried next tick.
    if (published) last_publish_time_ += interval;
  }
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
