#pragma once
// mechsim/RoverDriveController: drives a rover with steered and fixed wheels (the CC8's four
// steered corners and two fixed middle wheels) from a body twist, in one controller like
// diff_drive_controller, because steering and wheels must be coordinated. It claims every
// steering and wheel joint on the effort interface and closes a position PID per steering joint
// and a velocity PID per wheel joint. Kinematics: control/rover_drive_kinematics.hpp.
//
// Each tick:
//   1. command = the latest "cmd_vel" twist (linear.x, linear.y in m/s, angular.z in rad/s, base
//      frame; the other components are ignored), or zero once no command arrived for
//      cmd_vel_timeout seconds (the rover brakes within its acceleration limits);
//   2. velocity limits clamp each component, acceleration limits bound its change per tick;
//   3. the mode ("mode" port, or chosen from the twist in auto) decides which components are
//      realised: Ackermann (vx, wz; turn centre on the fixed wheels' axle line), crab (vx, vy; all
//      wheels parallel) or point turn (wz); what a mode cannot do is dropped and reported;
//   4. inverse kinematics give each steering joint a target heading within +-max_steering_angle
//      (the wheel rolls backwards rather than steering past it, choosing the shorter way) and
//      each wheel a rolling speed; a stopped rover keeps its steering;
//   5. the steering set points move towards their targets at max_steering_rate at most;
//   6. the wheel speeds are scaled by the steering alignment: 1 while every steered wheel is
//      within steering_tolerance of its target, falling linearly to 0 at steering_stop_error
//      (the wheels wait for the steering before driving hard); then uniformly scaled so that no
//      wheel exceeds max_wheel_speed;
//   7. PIDs turn set points into efforts;
//   8. odometry: the measured headings and wheel speeds give the body twist by least squares,
//      integrated exactly over the period.
//
// Parameters (under the controller's namespace; units in brackets):
//   type                       mechsim/RoverDriveController
//   steering_joints            [string]   steering joints, e.g. [steering_FL, steering_FR, steering_RL, steering_RR]
//   wheel_joints               [string]   wheel joints, e.g. [wheel_joint_FL, ..., wheel_joint_RR] (>= 2)
//   steering_pid               {p, i, d, i_clamp, ...}  gains of every steering position PID [N m/rad ...]
//   wheel_pid                  {p, i, d, i_clamp, ...}  gains of every wheel velocity PID [N m s/rad ...]
//   Geometry (control::fill_rover_drive_geometry fills what is absent from the URDF):
//   wheel_radius               [m]
//   wheel_positions            {wheel joint: [x, y(, z)]} tyre centre in base_frame_id at zero joint angles [m]
//   wheel_axis_signs           {wheel joint: +1|-1}   +1 when a positive joint velocity rolls forward (axis +y)
//   wheel_steering             {wheel joint: steering joint}  for each steered wheel
//   steering_positions         {steering joint: [x, y(, z)]}  a point of the steering axis [m]
//   steering_axis_signs        {steering joint: +1|-1}  +1 for an axis up (+z), -1 down (the CC8)
//   max_steering_angle         [rad]   feasible heading range +-this (default pi/2, or less where
//                                      revolute steering joints have tighter URDF limits)
//   Limits and behaviour:
//   max_steering_rate          [rad/s] default: the steering joints' URDF velocity limit, else none
//   max_wheel_speed            [rad/s] wheel joint speed; default: the wheels' URDF velocity limit, else none
//   max_linear_velocity        [m/s]   per component (vx, vy) of the command; default none
//   max_angular_velocity       [rad/s] default none
//   max_linear_acceleration    [m/s^2] per component; default none
//   max_angular_acceleration   [rad/s^2] default none
//   cmd_vel_timeout            [s]     default 0.5; <= 0: never time out
//   steering_tolerance         [rad]   default 0.05
//   steering_stop_error        [rad]   default 0.35
//   odom_frame_id, base_frame_id       default "odom", "base_link" (base_frame_id is also the
//                                      link the geometry is measured in)
//   pose_covariance_diagonal, twist_covariance_diagonal  [6 values] default zeros
//
// Ports:
//   "cmd_vel"       TwistCommandPort: the command (non-finite twists rejected and counted)
//   "mode"          DriveModeCommandPort: auto (default), ackermann, crab, point_turn
//   "odom"          StatePort<OdometrySnapshot>: pose in odom_frame_id, twist in base_frame_id
//   "state"         StatePort<JointGroupControllerState>: per joint, steering joints first then
//                   wheels: set point (rad / rad/s), process value, error, effort command, gains
//   "drive_status"  StatePort<RoverDriveStatus>: mode, applied twist, timeout, alignment
//   "gains/<joint>" PidGainsPort per joint
//
// starting() holds the measured steering headings, zeroes the command and resets the PIDs; the
// odometry pose persists across restarts (reset_odometry() zeroes it).

#include <atomic>
#include <memory>
#include <vector>

#include "control/controller.hpp"
#include "control/pid.hpp"
#include "control/rover_drive_params.hpp"
#include "control/rover_drive_ports.hpp"

namespace mechsim::control {

class RoverDriveController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override;

  TwistCommandPort& command_port() { return command_; }
  DriveModeCommandPort& mode_port() { return mode_; }
  StatePort<OdometrySnapshot>& odometry_port() { return odom_; }
  StatePort<JointGroupControllerState>& state_port() { return state_; }
  StatePort<RoverDriveStatus>& status_port() { return status_; }
  const RoverDriveConfig& config() const { return config_; }
  // Any thread: the next update() puts the odometry pose back to (0, 0, 0).
  void reset_odometry() { reset_odometry_.store(true, std::memory_order_release); }

 private:
  PlanarTwist limit_command(const PlanarTwist& target, double period) const noexcept;
  void update_odometry(double time, double period) noexcept;
  void publish(double time, double period) noexcept;

  RoverDriveConfig config_;
  std::vector<JointHandle> steering_;
  std::vector<JointHandle> wheels_;
  std::vector<std::unique_ptr<Pid>> pids_;  // steering joints, then wheels
  std::vector<std::unique_ptr<PidGainsPort>> gains_;

  // Real-time working state, sized at init.
  std::vector<double> measured_headings_;  // rad
  std::vector<double> target_headings_;    // rad, from the kinematics
  std::vector<double> setpoint_headings_;  // rad, rate limited
  std::vector<double> rolling_speeds_;     // m/s, target
  std::vector<double> wheel_setpoints_;    // rad/s, joint
  std::vector<double> measured_speeds_;    // m/s, rolling
  std::vector<double> efforts_;            // N m, steering then wheels
  Twist command_value_;                    // this tick's command as read
  DriveMode requested_mode_ = DriveMode::Auto;
  PlanarTwist applied_;                    // after limits, before the mode
  ModeChoice choice_;
  std::uint64_t last_command_seq_ = 0;
  double last_command_time_ = 0.0;
  bool timed_out_ = false;
  std::uint64_t unsupported_count_ = 0;
  double alignment_scale_ = 1.0;
  double max_steering_error_ = 0.0;
  double wheel_speed_scale_ = 1.0;
  PlanarPose pose_;
  PlanarTwist odom_twist_;
  double odom_residual_ = 0.0;
  bool odom_valid_ = false;
  std::atomic<bool> reset_odometry_{false};

  TwistCommandPort command_{"cmd_vel"};
  DriveModeCommandPort mode_{"mode"};
  StatePort<OdometrySnapshot> odom_{"odom"};
  StatePort<JointGroupControllerState> state_{"state"};
  StatePort<RoverDriveStatus> status_{"drive_status"};
};

}  // namespace mechsim::control
