#include "controllers/plugins/tricycle_drive_plugin.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "controllers/plugins/gazebo_ros_names.hpp"
#include "controllers/plugins/plugin_params.hpp"
#include "controllers/plugins/world_odometry.hpp"

namespace mechsim::control {
namespace {

constexpr std::array<const char*, 4> kKeys = {"steeringJoint", "actuatedWheelJoint", "encoderWheelLeftJoint",
                                              "encoderWheelRightJoint"};
constexpr std::array<const char*, 4> kDefaults = {"front_steering_joint", "front_wheel_joint", "left_wheel_joint",
                                                  "right_wheel_joint"};

}  // namespace

std::vector<std::string> TricycleDrivePlugin::joints(const Params& params) {
  const PluginParams p(params);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < kKeys.size(); ++i) out.push_back(p.joint(kKeys[i], kDefaults[i]));
  return out;
}

bool TricycleDrivePlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  actuated_diameter_ = p.positive("actuatedWheelDiameter", 0.15);
  encoder_diameter_ = p.positive("encoderWheelDiameter", 0.15);
  encoder_separation_ = p.positive("encoderWheelSeparation", 0.5);
  torque_ = p.positive("wheelTorque", 5.0);
  acceleration_ = p.non_negative("wheelAcceleration", 0.0);
  deceleration_ = p.non_negative("wheelDeceleration", acceleration_);
  speed_tolerance_ = p.non_negative("wheelSpeedTolerance", 0.01);
  steering_speed_ = p.non_negative("steeringSpeed", 0.0);
  angle_tolerance_ = p.non_negative("steeringAngleTolerance", 0.01);
  update_rate_ = p.rate("updateRate", 100.0);
  update_period_ = period_of(update_rate_);
  const std::string source = p.text("odometrySource", "world");
  if (source != "world" && source != "encoder") p.fail("odometrySource", "must be world or encoder (got \"" + source + "\")");
  encoder_ = source == "encoder";
  publish_joint_state_ = p.boolean("publishWheelJointState", false);
  const bool publish_wheel_tf = p.boolean("publishWheelTF", false);

  const std::vector<std::string> names = joints(params);
  if (names[0] == names[1]) p.fail(kKeys[1], "names the same joint as <steeringJoint> ('" + names[0] + "')");
  if (names[2] == names[3]) p.fail(kKeys[3], "names the same joint as <encoderWheelLeftJoint> ('" + names[2] + "')");
  // A steered wheel steers with a position command, or a velocity one with steeringSpeed.
  steering_ = hardware.claim_joint(names[0], steering_speed_ > 0.0 ? HardwareInterface::Velocity : HardwareInterface::Position,
                                   p.location(kKeys[0]));
  actuated_ = hardware.claim_joint(names[1], HardwareInterface::Velocity, p.location(kKeys[1]));
  encoder_left_ = hardware.joint_state(names[2], p.location(kKeys[2]));
  encoder_right_ = hardware.joint_state(names[3], p.location(kKeys[3]));
  base_ = &hardware.base_state();
  if (!encoder_ && !base_->floating) {
    p.fail("odometrySource", "is world, but the robot is fixed to the world: its base does not move");
  }

  const GazeboRosNames ros_names = gazebo_ros_names(p, context_.robot_name);
  odom_.init(plugin_odometry_prototype(ros_names.frame(p.text("odometryFrame", "odom")),
                                       ros_names.frame(p.text("robotBaseFrame", "base_link")),
                                       {1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3}));
  JointStateSnapshot js;
  js.names = names;
  js.position.assign(4, 0.0);
  js.velocity.assign(4, 0.0);
  js.effort.assign(4, 0.0);
  joint_states_.init(js);

  ros_.robot_namespace = ros_names.robot_namespace;
  ros_.tf_prefix = ros_names.tf_prefix;
  ros_.wheel_tf_child_is_joint = true;
  ros_.topics.push_back({"cmd_vel", p.text("commandTopic", "cmd_vel"), ""});
  ros_.topics.push_back({"odom", p.text("odometryTopic", "odom"), ""});
  ros_.odom_tf = true;
  // publishWheelTF alone feeds /tf from the port without a joint_states topic, as the plugin.
  if (publish_joint_state_ || publish_wheel_tf) {
    ros_.topics.push_back({"joint_states", publish_joint_state_ ? "joint_states" : "", ""});
  }
  if (publish_wheel_tf) ros_.wheel_tf_joints = names;
  publish_joint_state_ = publish_joint_state_ || publish_wheel_tf;
  return true;
}

void TricycleDrivePlugin::starting(double time) {
  // A (re)start is Gazebo's plugin Reset(): odometry at the origin, command and set points zero.
  last_update_ = time;
  encoder_odometry_.reset();
  command_.reset_from_rt(Twist{});
  wheel_set_ = 0.0;
  actuated_.set_effort_limit(torque_);
  actuated_.set_command(0.0);
  // The plugin sets the steering joint's "fmax" too; it bounds the velocity motor, while a set
  // position ignores it (mechsim's position servo then has the joint's own limit).
  steering_.set_effort_limit(steering_speed_ > 0.0 ? torque_ : 0.0);
  steering_.set_command(steering_speed_ > 0.0 ? 0.0 : steering_.position());
}

void TricycleDrivePlugin::publish_odometry(double time) noexcept {
  odom_.publish_from_rt([&](OdometrySnapshot& o) {
    if (encoder_)
      fill_encoder_odometry(o, encoder_odometry_, time);
    else
      fill_world_odometry(o, *base_, time);
  });
}

void TricycleDrivePlugin::drive_wheel(double target, double dt) noexcept {
  if (acceleration_ > 0.0) {
    const double diff = wheel_set_ - target;
    const double step = (diff > 0.0 ? acceleration_ : deceleration_) * dt;
    if (std::abs(diff) < speed_tolerance_) {
      // Close enough: the set point stays, as the plugin keeps the wheel's speed.
    } else if (std::abs(diff) > step) {
      wheel_set_ += diff > 0.0 ? -step : step;
    } else {
      wheel_set_ = target;
    }
  } else {
    wheel_set_ = target;
  }
  actuated_.set_command(wheel_set_);
}

void TricycleDrivePlugin::steer(double target) noexcept {
  target = std::clamp(target, -M_PI_2, M_PI_2);
  if (steering_speed_ <= 0.0) {
    steering_.set_command(target);
    return;
  }
  const double error = target - steering_.position();
  steering_.set_command(std::abs(error) < angle_tolerance_ ? 0.0 : std::copysign(steering_speed_, error));
}

UpdateStatus TricycleDrivePlugin::update(double time, double period) {
  if (encoder_) {
    encoder_odometry_.update(encoder_left_.velocity(), encoder_right_.velocity(), encoder_diameter_ / 2.0, encoder_separation_,
                             period);
  }
  const double since = time - last_update_;
  // Once a period has passed (every step for a rate of 0); the next one is due a period later.
  if (since < update_period_ - 1e-9) return UpdateStatus::Ok();
  publish_odometry(time);
  if (publish_joint_state_) {
    joint_states_.publish_from_rt([&](JointStateSnapshot& s) {
      s.stamp = time;
      const double position[4] = {steering_.position(), actuated_.position(), encoder_left_.position(), encoder_right_.position()};
      const double velocity[4] = {steering_.velocity(), actuated_.velocity(), encoder_left_.velocity(), encoder_right_.velocity()};
      const double effort[4] = {steering_.effort(), actuated_.effort(), encoder_left_.effort(), encoder_right_.effort()};
      for (std::size_t i = 0; i < 4; ++i) {
        s.position[i] = position[i];
        s.velocity[i] = velocity[i];
        s.effort[i] = effort[i];
      }
    });
  }
  const Twist& command = command_.read_from_rt();
  drive_wheel(command.linear.x / (actuated_diameter_ / 2.0), since);
  steer(command.angular.z);
  last_update_ = update_period_ > 0.0 ? last_update_ + update_period_ : time;
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
