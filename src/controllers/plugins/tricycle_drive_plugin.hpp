#pragma once
// libgazebo_ros_tricycle_drive.so (gazebo_plugins' GazeboRosTricycleDrive, noetic) as a model
// plugin controller: one steered, driven wheel (a steering joint and the wheel's joint below it)
// and two unpowered encoder wheels, with the plugin's elements and defaults. Encoder odometry
// shares the diff drive's (controllers/drive/diff_drive_kinematics.hpp: EncoderOdometry), world
// odometry the other drive plugins' (world_odometry.hpp).
//
// cmd_vel is not a body twist here, as in the plugin: linear.x is the driven wheel's ground speed
// (m/s) and angular.z the steering angle (rad), both held until the next command (no timeout).
//
// Every tick: with odometrySource encoder, the two encoder wheels' joint velocities times the
// encoder radius over the period move the odometry pose (mid-way heading, as the diff drive's).
// Every 1/updateRate s (every tick for 0):
//   - the odometry goes out on "odom" and odometryFrame -> robotBaseFrame on /tf (always: the
//     plugin has no switch for either); the pose from the encoders, or the base's world pose and
//     its velocity in the heading frame for odometrySource world;
//   - with publishWheelJointState, "joint_states" (steering, driven, left and right encoder joint:
//     position, velocity, measured effort); with publishWheelTF, each of these joints' parent ->
//     child transform on /tf (without the joint_states topic unless asked for, as the plugin);
//   - the driven wheel's set point (rad/s) moves towards linear.x / (actuatedWheelDiameter / 2):
//     at once when wheelAcceleration is 0; else it stays where it is within wheelSpeedTolerance
//     (rad/s) of the target, and otherwise steps by wheelAcceleration * dt when the target is below
//     it and by wheelDeceleration * dt when above (rad/s^2: the plugin's assignment, which for
//     forward driving speeds up at wheelDeceleration), reaching the target when a step would pass
//     it; commanded through a velocity motor bounded by wheelTorque (the joint's "fmax");
//   - the steering angle target is angular.z clamped to [-pi/2, pi/2]. steeringSpeed 0: a position
//     command (the plugin sets the joint's position outright; mechsim's position servo moves it
//     within the joint's own effort limit, none for a joint without one). steeringSpeed > 0: a
//     velocity command of +-steeringSpeed (rad/s) towards the target, 0 within
//     steeringAngleTolerance (rad), through a motor bounded by wheelTorque.
//
// Where mechsim departs from the plugin's source (each a slip there, documented in
// src/controllers/README.md): the encoder odometry turns as REP 103 says (the plugin's heading
// change is (left - right) / separation, so its yaw falls in a left turn) and its twist is in the
// base frame (the plugin's linear.x/y are the odometry frame's displacement over dt); with
// steeringSpeed > 0 the steering turns towards the target (the plugin compares the angle error
// with the wheel's target speed, so it steers one way only while the wheel's target exceeds the
// error).
//
// Elements (gazebo_plugins' names and defaults):
//   steeringJoint front_steering_joint, actuatedWheelJoint front_wheel_joint,
//   encoderWheelLeftJoint left_wheel_joint, encoderWheelRightJoint right_wheel_joint
//   actuatedWheelDiameter 0.15, encoderWheelDiameter 0.15, encoderWheelSeparation 0.5 (m, > 0)
//   wheelTorque 5 (N m, > 0), wheelAcceleration 0, wheelDeceleration = wheelAcceleration,
//   wheelSpeedTolerance 0.01, steeringSpeed 0, steeringAngleTolerance 0.01 (all >= 0)
//   commandTopic cmd_vel, odometryTopic odom, odometryFrame odom, robotBaseFrame base_link
//   odometrySource world (world | encoder), updateRate 100 (Hz, >= 0; 0: every step)
//   publishWheelTF false, publishWheelJointState false
//   robotNamespace: gazebo_ros_names.hpp (the namespace, and the TF prefix of every frame it
//                   publishes; the wheels' child frames are the joints' names, as the plugin's)
// Pose covariance diagonal (1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3), twist covariance zero.
// Ports: "cmd_vel" TwistCommandPort, "odom" StatePort<OdometrySnapshot>, "joint_states"
// StatePort<JointStateSnapshot>.

#include "control/ports.hpp"
#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/plugins/model_plugin.hpp"

namespace mechsim::control {

inline constexpr const char* kTricycleDrivePluginFile = "libgazebo_ros_tricycle_drive.so";

class TricycleDrivePlugin : public ModelPlugin {
 public:
  explicit TricycleDrivePlugin(PluginContext context = {}) : context_(std::move(context)) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&command_, &odom_, &joint_states_}; }

  // The joints it names (for the mechanism, before init): steeringJoint, actuatedWheelJoint,
  // encoderWheelLeftJoint, encoderWheelRightJoint.
  static std::vector<std::string> joints(const Params& params);

  double actuated_wheel_diameter() const { return actuated_diameter_; }
  double encoder_wheel_diameter() const { return encoder_diameter_; }
  double encoder_wheel_separation() const { return encoder_separation_; }
  double wheel_torque() const { return torque_; }
  double wheel_acceleration() const { return acceleration_; }
  double wheel_deceleration() const { return deceleration_; }
  double steering_speed() const { return steering_speed_; }
  double update_rate() const { return update_rate_; }
  bool encoder_odometry() const { return encoder_; }

 private:
  void publish_odometry(double time) noexcept;
  void drive_wheel(double target, double dt) noexcept;
  void steer(double target) noexcept;

  PluginContext context_;
  double actuated_diameter_ = 0.15, encoder_diameter_ = 0.15, encoder_separation_ = 0.5, torque_ = 5.0;
  double acceleration_ = 0.0, deceleration_ = 0.0, speed_tolerance_ = 0.01;
  double steering_speed_ = 0.0, angle_tolerance_ = 0.01;
  double update_rate_ = 100.0, update_period_ = 0.01;
  bool encoder_ = false, publish_joint_state_ = false;
  JointHandle steering_, actuated_;
  JointStateHandle encoder_left_, encoder_right_;
  const mechanism::BaseState* base_ = nullptr;
  EncoderOdometry encoder_odometry_;
  double last_update_ = 0.0;  // s
  double wheel_set_ = 0.0;    // rad/s: the driven wheel's set point
  TwistCommandPort command_{"cmd_vel"};
  StatePort<OdometrySnapshot> odom_{"odom"};
  StatePort<JointStateSnapshot> joint_states_{"joint_states"};
};

}  // namespace mechsim::control
