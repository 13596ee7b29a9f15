#pragma once
// ros2_controllers' tricycle_controller/TricycleController: one steered traction wheel (a
// velocity joint that drives and a position joint that steers it) at `wheelbase` m ahead of the
// rear axle, driven by a Twist on "cmd_vel", with odometry from the traction wheel's velocity and
// the steering angle. As ros2_controllers computes it, each update:
//
//   1. odometry: Vs = Ws r (Ws: traction joint velocity, rad/s; r: wheel_radius), vx = Vs cos a,
//      w = Vs sin a / wheelbase (a: steering joint position); the pose integrated exactly over
//      the period (Runge-Kutta 2 when |w dt| < 1e-6); the twist published is the rolling mean
//      over velocity_rolling_window_size updates; open_loop: the command integrated instead;
//   2. command: the latest "cmd_vel" (linear.x, angular.z), zero once older than cmd_vel_timeout;
//   3. twist to wheel: turning in place (vx = 0, w != 0): a = +-pi/2, Ws = |w| wheelbase / r;
//      else a = atan(w wheelbase / vx) (0 when w or vx is 0), Ws = vx / (r cos a);
//   4. the traction speed scaled down while the steering is far from its target (error e = |a -
//      a_measured|: scale 1 below pi/6, 0.01 above pi/2, cos e between), then limited (traction:
//      jerk, acceleration/deceleration, velocity on |Ws|; steering: acceleration, velocity,
//      position), against the last two commands;
//   5. traction joint <- Ws (velocity), steering joint <- a (position).
// starting(): odometry and command history reset, the command zeroed; stopping(): both joints 0.
//
// Parameters (ros2_controllers' names and defaults): traction_joint_name, steering_joint_name
// (required), wheelbase, wheel_radius (m, required > 0), odom_frame_id (odom), base_frame_id
// (base_link), pose_covariance_diagonal, twist_covariance_diagonal (6 zeros), open_loop (false),
// enable_odom_tf (false), odom_only_twist (false), cmd_vel_timeout (ms, 500),
// velocity_rolling_window_size (10), traction.{max,min}_{velocity,acceleration,deceleration,jerk}
// and steering.{max,min}_{position,velocity,acceleration} (NaN: no limit; a traction min unset is
// 0, a steering position min unset is -max; negative traction or steering rate limits are
// refused), publish_ackermann_command (read; the AckermannDrive output is not simulated).
// Humble's use_stamped_vel is the wire layer's (TwistStamped or Twist on ~/cmd_vel).
//
// Ports: "cmd_vel" TwistCommandPort; "odom" StatePort<OdometrySnapshot>.

#include "control/controller.hpp"
#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/drive/steered_drive.hpp"

namespace mechsim::control {

inline constexpr const char* kTricycleControllerType = "tricycle_controller/TricycleController";

// ros2_controllers' TractionLimiter (on |v|, rad/s of the traction wheel) and SteeringLimiter
// (on the angle, rad). NaN members: no limit.
struct TractionLimiter {
  double min_velocity, max_velocity, min_acceleration, max_acceleration, min_deceleration, max_deceleration, min_jerk,
      max_jerk;
  double limit(double v, double v0, double v1, double dt) const noexcept;
};
struct SteeringLimiter {
  double min_position, max_position, min_velocity, max_velocity, min_acceleration, max_acceleration;
  double limit(double p, double p0, double p1, double dt) const noexcept;
};

class TricycleController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override { return {&command_, &odom_}; }

  TwistCommandPort& command_port() { return command_; }
  StatePort<OdometrySnapshot>& odometry_port() { return odom_; }

 private:
  JointHandle traction_, steering_;
  double wheelbase_ = 0.0, radius_ = 0.0;
  bool open_loop_ = false, odom_only_twist_ = false;
  double cmd_vel_timeout_ = 0.5;  // s
  TractionLimiter traction_limits_{};
  SteeringLimiter steering_limits_{};
  TwistCommandTimeout command_timeout_;
  PlanarPose pose_;
  RollingMean linear_mean_, angular_mean_;
  double last_speed_[2] = {0.0, 0.0}, last_angle_[2] = {0.0, 0.0};  // [0]: last command, [1]: the one before
  TwistCommandPort command_{"cmd_vel"};
  StatePort<OdometrySnapshot> odom_{"odom"};
};

}  // namespace mechsim::control
