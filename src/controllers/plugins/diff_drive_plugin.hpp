#pragma once
// libgazebo_ros_diff_drive.so (gazebo_plugins' GazeboRosDiffDrive) as a model plugin controller,
// with the plugin's elements and defaults; kinematics and odometry shared with
// diff_drive_controller (controllers/drive/diff_drive_kinematics.hpp).
//
// Every tick: the encoder odometry (odometrySource encoder) integrates the wheel joints'
// velocities times the radius along the mid-way heading. Every 1/updateRate s (every tick for 0):
// the odometry goes out on "odom" (publishTf; the pose from the encoders, or the base's world
// pose for odometrySource world; odom -> base on /tf with publishOdomTF), the wheels' positions on
// "joint_states" (publishWheelJointState), and the latest cmd_vel (linear.x m/s, angular.z
// rad/s; held until the next one, the plugin has no timeout) becomes wheel rim speeds v -+ w s/2
// (left, right; swapped with legacyMode), each wheel's set point moving towards its target by at
// most wheelAcceleration * (time since the last update) m/s (wheelAcceleration 0: at once),
// commanded as the joint's velocity (set point / radius) through a velocity motor whose torque is
// bounded by wheelTorque (Gazebo's joint "fmax").
//
// Gazebo's plugin steps its set point by min(target - measured rim speed, a dt) and jumps to the
// target once either wheel is within 0.01 m/s of it; mechsim moves the set point itself by at most
// a dt, so the configured acceleration is what the wheels get while they track (the two agree
// then).
//
// Elements (gazebo_plugins' names and defaults):
//   leftJoint left_joint, rightJoint right_joint    wheel joints
//   wheelSeparation 0.34 (m), wheelDiameter 0.15 (m), both > 0
//   wheelAcceleration 0 (m/s^2 at the rim, >= 0; 0: none), wheelTorque 5 (N m, > 0)
//   commandTopic cmd_vel, odometryTopic odom, odometryFrame odom, robotBaseFrame base_footprint
//   odometrySource world (world | encoder)
//   publishWheelTF false, publishOdomTF true, publishWheelJointState false
//   publishTf true (false: no odometry topic nor odom TF at all, as the plugin)
//   updateRate 100 (Hz, >= 0; 0: every step)
//   legacyMode false (noetic's behaviour; true swaps the wheels' turning direction as the older
//                     plugins did)
//   robotNamespace: gazebo_ros_names.hpp (the namespace, and the TF prefix of every frame it
//                   publishes: odometryFrame, robotBaseFrame, the wheels')
// Pose covariance diagonal (1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3), twist covariance zero.
// Ports: "cmd_vel" TwistCommandPort, "odom" StatePort<OdometrySnapshot>, "joint_states"
// StatePort<JointStateSnapshot> (the two wheels: position).

#include "control/ports.hpp"
#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/plugins/model_plugin.hpp"

namespace mechsim::control {

inline constexpr const char* kDiffDrivePluginFile = "libgazebo_ros_diff_drive.so";

class DiffDrivePlugin : public ModelPlugin {
 public:
  explicit DiffDrivePlugin(PluginContext context = {}) : context_(std::move(context)) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override;

  // The joints it names (for the mechanism, before init): leftJoint, rightJoint.
  static std::vector<std::string> joints(const Params& params);

  double wheel_separation() const { return separation_; }
  double wheel_diameter() const { return diameter_; }
  double wheel_acceleration() const { return acceleration_; }
  double wheel_torque() const { return torque_; }
  double update_rate() const { return update_rate_; }
  bool encoder_odometry() const { return encoder_; }
  bool legacy_mode() const { return legacy_; }

 private:
  void publish_odometry(double time) noexcept;

  PluginContext context_;
  double separation_ = 0.34, diameter_ = 0.15, acceleration_ = 0.0, torque_ = 5.0, update_rate_ = 100.0;
  double update_period_ = 0.01;
  bool encoder_ = false, legacy_ = false, publish_tf_ = true, publish_joint_state_ = false;
  JointHandle left_, right_;
  const mechanism::BaseState* base_ = nullptr;
  EncoderOdometry encoder_odometry_;
  double last_update_ = 0.0;            // s
  double set_left_ = 0.0, set_right_ = 0.0;  // m/s: the rim speed set points
  TwistCommandPort command_{"cmd_vel"};
  StatePort<OdometrySnapshot> odom_{"odom"};
  StatePort<JointStateSnapshot> joint_states_{"joint_states"};
};

}  // namespace mechsim::control
