#include "controllers/plugins/diff_drive_plugin.hpp"

#include <cmath>

#include "controllers/drive/steered_drive.hpp"  // step_towards
#include "controllers/plugins/gazebo_ros_names.hpp"
#include "controllers/plugins/plugin_params.hpp"
#include "controllers/plugins/world_odometry.hpp"

namespace mechsim::control {

std::vector<std::string> DiffDrivePlugin::joints(const Params& params) {
  const PluginParams p(params);
  return {p.joint("leftJoint", "left_joint"), p.joint("rightJoint", "right_joint")};
}

bool DiffDrivePlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  separation_ = p.positive("wheelSeparation", 0.34);
  diameter_ = p.positive("wheelDiameter", 0.15);
  acceleration_ = p.non_negative("wheelAcceleration", 0.0);
  torque_ = p.positive("wheelTorque", 5.0);
  update_rate_ = p.rate("updateRate", 100.0);
  update_period_ = period_of(update_rate_);
  const std::string source = p.text("odometrySource", "world");
  if (source != "world" && source != "encoder") p.fail("odometrySource", "must be world or encoder (got \"" + source + "\")");
  encoder_ = source == "encoder";
  legacy_ = p.boolean("legacyMode", false);
  publish_tf_ = p.boolean("publishTf", true);
  publish_joint_state_ = p.boolean("publishWheelJointState", false);
  const bool publish_odom_tf = p.boolean("publishOdomTF", true);
  const bool publish_wheel_tf = p.boolean("publishWheelTF", false);
  const std::string left = p.joint("leftJoint", "left_joint"), right = p.joint("rightJoint", "right_joint");
  if (left == right) p.fail("rightJoint", "names the same joint as <leftJoint> ('" + left + "')");
  left_ = hardware.claim_joint(left, HardwareInterface::Velocity, p.location("leftJoint"));
  right_ = hardware.claim_joint(right, HardwareInterface::Velocity, p.location("rightJoint"));
  base_ = &hardware.base_state();
  if (!encoder_ && !base_->floating) {
    p.fail("odometrySource", "is world, but the robot is fixed to the world: its base does not move");
  }

  const GazeboRosNames names = gazebo_ros_names(p, context_.robot_name);
  odom_.init(plugin_odometry_prototype(names.frame(p.text("odometryFrame", "odom")),
                                       names.frame(p.text("robotBaseFrame", "base_footprint")),
                                       {1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3}));
  JointStateSnapshot js;
  js.names = {left, right};
  js.position.assign(2, 0.0);
  joint_states_.init(js);

  ros_.robot_namespace = names.robot_namespace;
  ros_.tf_prefix = names.tf_prefix;
  ros_.topics.push_back({"cmd_vel", p.text("commandTopic", "cmd_vel"), ""});
  if (publish_tf_) ros_.topics.push_back({"odom", p.text("odometryTopic", "odom"), ""});
  ros_.odom_tf = publish_tf_ && publish_odom_tf;
  // publishWheelTF alone feeds /tf from the port without a joint_states topic, as the plugin.
  if (publish_joint_state_ || publish_wheel_tf) {
    ros_.topics.push_back({"joint_states", publish_joint_state_ ? "joint_states" : "", ""});
  }
  if (publish_wheel_tf) ros_.wheel_tf_joints = {left, right};
  publish_joint_state_ = publish_joint_state_ || publish_wheel_tf;
  return true;
}

void DiffDrivePlugin::starting(double time) {
  // A (re)start is Gazebo's plugin Reset(): odometry at the origin, command zero.
  last_update_ = time;
  encoder_odometry_.reset();
  command_.reset_from_rt(Twist{});
  set_left_ = set_right_ = 0.0;
  left_.set_effort_limit(torque_);
  right_.set_effort_limit(torque_);
  left_.set_command(0.0);
  right_.set_command(0.0);
}

void DiffDrivePlugin::publish_odometry(double time) noexcept {
  odom_.publish_from_rt([&](OdometrySnapshot& o) {
    if (encoder_)
      fill_encoder_odometry(o, encoder_odometry_, time);
    else
      fill_world_odometry(o, *base_, time);
  });
}

UpdateStatus DiffDrivePlugin::update(double time, double period) {
  const double radius = diameter_ / 2.0;
  if (encoder_) encoder_odometry_.update(left_.velocity(), right_.velocity(), radius, separation_, period);
  const double since = time - last_update_;
  // Once a period has passed (every step for a rate of 0); the next one is due a period later.
  if (since < update_period_ - 1e-9) return UpdateStatus::Ok();
  if (publish_tf_) publish_odometry(time);
  if (publish_joint_state_) {
    joint_states_.publish_from_rt([&](JointStateSnapshot& s) {
      s.stamp = time;
      s.position[0] = left_.position();
      s.position[1] = right_.position();
    });
  }
  const Twist& command = command_.read_from_rt();
  WheelRimSpeeds target = diff_drive_rim_speeds(command.linear.x, command.angular.z, separation_);
  if (legacy_) std::swap(target.left, target.right);
  if (acceleration_ > 0.0) {
    set_left_ = step_towards(set_left_, target.left, acceleration_ * since);
    set_right_ = step_towards(set_right_, target.right, acceleration_ * since);
  } else {
    set_left_ = target.left;
    set_right_ = target.right;
  }
  left_.set_command(set_left_ / radius);
  right_.set_command(set_right_ / radius);
  last_update_ = update_period_ > 0.0 ? last_update_ + update_period_ : time;
  return UpdateStatus::Ok();
}

std::vector<Port*> DiffDrivePlugin::ports() { return {&command_, &odom_, &joint_states_}; }

}  // namespace mechsim::control
