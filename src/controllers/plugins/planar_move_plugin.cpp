#include "controllers/plugins/planar_move_plugin.hpp"

#include <cmath>

#include "controllers/plugins/plugin_params.hpp"
#include "controllers/plugins/world_odometry.hpp"

namespace mechsim::control {

bool PlanarMovePlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  odometry_rate_ = p.rate("odometryRate", 20.0);
  timeout_ = p.has("cmdTimeout") ? p.number("cmdTimeout", -1.0) : p.number("cmd_timeout", -1.0);
  base_ = hardware.claim_base(params.location());
  odom_.init(plugin_odometry_prototype(p.text("odometryFrame", "odom"), p.text("robotBaseFrame", "base_footprint"),
                                       {1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3}));
  ros_.robot_namespace = p.text("robotNamespace", "");
  ros_.topics.push_back({"cmd_vel", p.text("commandTopic", "cmd_vel"), ""});
  if (odometry_rate_ > 0.0) ros_.topics.push_back({"odom", p.text("odometryTopic", "odom"), ""});
  ros_.odom_tf = odometry_rate_ > 0.0;
  return true;
}

void PlanarMovePlugin::starting(double time) {
  command_.reset_from_rt(Twist{});
  last_sequence_ = command_.accepted();
  last_command_ = time;
  last_odometry_ = time;
  const mechanism::BaseState& b = base_.state();
  last_x_ = b.X_WB.position.x;
  last_y_ = b.X_WB.position.y;
  last_yaw_ = yaw_of(b.X_WB.orientation);
}

void PlanarMovePlugin::stopping(double /*time*/) { base_.release(); }

UpdateStatus PlanarMovePlugin::update(double time, double /*period*/) {
  Twist command = command_.read_from_rt();
  if (const std::uint64_t seq = command_.accepted(); seq != last_sequence_) {
    last_sequence_ = seq;
    last_command_ = time;
  }
  if (timeout_ >= 0.0 && time - last_command_ > timeout_) command = Twist{};
  const mechanism::BaseState& b = base_.state();
  const double yaw = yaw_of(b.X_WB.orientation);
  const double c = std::cos(yaw), s = std::sin(yaw);
  base_.set_planar_velocity(command.linear.x * c - command.linear.y * s, command.linear.y * c + command.linear.x * s,
                            command.angular.z);

  const double since = time - last_odometry_;
  if (odometry_rate_ > 0.0 && since > 1.0 / odometry_rate_ - 1e-9) {
    odom_.publish_from_rt([&](OdometrySnapshot& o) {
      fill_world_odometry(o, b, time);
      // The plugin's twist: the pose change since its last odometry, in the heading frame.
      const double vx = (b.X_WB.position.x - last_x_) / since, vy = (b.X_WB.position.y - last_y_) / since;
      o.linear = {c * vx + s * vy, c * vy - s * vx, 0.0};
      o.angular = {0.0, 0.0, std::remainder(yaw - last_yaw_, 2.0 * M_PI) / since};
    });
    last_odometry_ = time;
    last_x_ = b.X_WB.position.x;
    last_y_ = b.X_WB.position.y;
    last_yaw_ = yaw;
  }
  return UpdateStatus::Ok();
}

std::vector<Port*> PlanarMovePlugin::ports() { return {&command_, &odom_}; }

}  // namespace mechsim::control
