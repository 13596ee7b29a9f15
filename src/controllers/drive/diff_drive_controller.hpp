#pragma once
// diff_drive_controller/DiffDriveController, with ros_controllers' parameters and behaviour: a
// differential (or skid-steer: several wheels a side) drive on velocity joint interfaces, driven
// by a Twist on cmd_vel, with wheel odometry. Kinematics and odometry are shared with Gazebo's
// diff drive plugin (controllers/drive/diff_drive_kinematics.hpp).
//
// Each tick:
//   1. odometry: the mean wheel joint position of each side (rad) times its radius gives the
//      side's travel; the exact arc integration moves the pose; the twist is a rolling mean over
//      velocity_rolling_window_size ticks. open_loop: the last limited command is integrated
//      instead. The "odom" snapshot (pose in odom_frame_id, twist in base_frame_id) every tick;
//      the ROS binding publishes it at publish_rate, with odom -> base on /tf if enable_odom_tf;
//   2. command: the latest "cmd_vel" (linear.x m/s, angular.z rad/s; other components ignored),
//      zero once older than cmd_vel_timeout s;
//   3. limits: linear/x and angular/z speed limiters, jerk then acceleration then velocity,
//      against the previous two limited commands; publish_cmd: the result on "cmd_vel_out";
//   4. wheels: every left wheel gets (v - w s / 2) / r_left, every right one (v + w s / 2) /
//      r_right (rad/s), s = wheel_separation * wheel_separation_multiplier, r_* = wheel_radius *
//      its multiplier (a skid steer's slip is what the separation multiplier calibrates).
// starting(): wheels braked (velocity 0), odometry reset to the origin; stopping(): brake.
//
// Parameters (ros_controllers' names and defaults):
//   left_wheel, right_wheel          string or [string]  wheel joints (VelocityJointInterface)
//   wheel_separation, wheel_radius   m; from the robot description when absent
//                                    (fill_diff_drive_geometry: first wheel of each side)
//   wheel_separation_multiplier      1.0
//   wheel_radius_multiplier          1.0 (sets both sides when given), else
//   left_wheel_radius_multiplier, right_wheel_radius_multiplier  1.0
//   cmd_vel_timeout                  s, 0.5
//   publish_rate                     Hz, 50 (the ROS binding's rate for odom)
//   base_frame_id, odom_frame_id     base_link, odom
//   enable_odom_tf                   true
//   pose_covariance_diagonal, twist_covariance_diagonal  6 values each, zeros
//   open_loop                        false
//   velocity_rolling_window_size     10
//   publish_cmd                      false: "cmd_vel_out" (TwistStamped) of the limited command
//   allow_multiple_cmd_vel_publishers  true (the ROS binding ignores cmd_vel while several
//                                    nodes publish it when false)
//   linear/x/{has_velocity_limits, max_velocity, min_velocity, has_acceleration_limits,
//   max_acceleration, min_acceleration, has_jerk_limits, max_jerk, min_jerk}, angular/z/... the same
//
// Ports: "cmd_vel" TwistCommandPort; "odom" StatePort<OdometrySnapshot>; "cmd_vel_out"
// StatePort<TwistSnapshot> (publish_cmd only).

#include <vector>

#include "control/controller.hpp"
#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/drive/diff_drive_params.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/drive/steered_drive.hpp"

namespace mechsim::control {

class DiffDriveController : public Controller {
 public:
  // ros2: ros2_controllers' parameters (controllers/ros2_control/ros2_diff_drive_params.hpp) and,
  // with position_feedback false, odometry from the wheels' velocities.
  explicit DiffDriveController(bool ros2 = false) : ros2_(ros2) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override;

  const DiffDriveConfig& config() const { return config_; }
  TwistCommandPort& command_port() { return command_; }
  StatePort<OdometrySnapshot>& odometry_port() { return odom_; }

 private:
  void brake() noexcept;
  double mean_position(const std::vector<JointHandle>& wheels) const noexcept;
  double mean_velocity(const std::vector<JointHandle>& wheels) const noexcept;

  bool ros2_ = false;
  DiffDriveConfig config_;
  std::vector<JointHandle> left_, right_;
  // position_feedback false: each side's travel integrated from its mean wheel velocity (rad).
  double left_travel_ = 0.0, right_travel_ = 0.0;
  double last_time_ = 0.0;
  DiffDriveOdometry odometry_;
  TwistCommandTimeout command_timeout_;
  double last0_linear_ = 0.0, last0_angular_ = 0.0;  // the previous limited command
  double last1_linear_ = 0.0, last1_angular_ = 0.0;  // the one before
  TwistCommandPort command_{"cmd_vel"};
  StatePort<OdometrySnapshot> odom_{"odom"};
  StatePort<TwistSnapshot> command_out_{"cmd_vel_out"};
};

}  // namespace mechsim::control
