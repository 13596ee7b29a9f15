#pragma once
// mechsim/RoverDriveController: drives a rover with steered and fixed wheels (the CC8's four
// steered corners and two fixed middle wheels) from a body twist, in one controller like
// diff_drive_controller, because steering and wheels must be coordinated. It claims every
// steering and wheel joint on the effort interface and closes a position PID per steering joint
// and a velocity PID per wheel joint. Kinematics: controllers/drive/rover_drive_kinematics.hpp.
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
//   8. odometry: the measured headings and wheel speeds give the body twist by weighted,
//      robust least squares (controllers/drive/rover_drive_odometry.hpp), integrated exactly over the
//      period. Weights: every row 1, except in crab, where the fixed wheels' no-side-slip rows
//      get 0 (they are dragged sideways) and, while sensing wheels are unpowered, the powered
//      wheels' rolling rows get crab_driven_rolling_weight (a wheel held at its set point reports
//      the set point, not the ground). The robust pass then lowers the weights of a wheel that
//      disagrees with the rest (a wheel spinning in the air, a wheel stuck).
//
// Crab. The fixed wheels cannot steer, so crabbing drags them sideways, and the steered wheels
// slip with them (in mechsim's CC8 at 45 deg: 4-9 % along their headings, 1-3 cm/s
// across them) and the body yaws. Wheels held at their set points cannot see any of it. Two
// remedies, both configurable:
//   - crab_sensing_wheels: wheels left unpowered (effort 0) while crabbing, so that they roll
//     with the ground and their rolling speeds measure it; the odometry trusts them;
//   - heading hold: a PI on the odometry yaw error from the yaw at the start of the crab
//     command adds a yaw rate correction to the crab twist before the inverse kinematics: the
//     front and rear wheels steer a little apart (and the wheel speeds follow), which turns
//     the body against the yaw. Off outside crab and while a non-zero wz is commanded;
//     re-armed (holding the then current yaw) whenever a crab motion starts and at an
//     odometry reset.
//     It can only hold what the odometry sees: with no sensing wheels, the yaw that slip
//     causes is invisible to it.
//   Measured on mechsim's CC8 crabbing 5 m at 45 deg (robots/cc8/scenarios/crab_45.yaml):
//   odometry error 7.7 % of the distance and 9 deg of heading drift without either; 1.5 %
//   and 1 deg with the trailing side sensing and the heading hold.
//   With crab_heading_source: imu (the ZED2 IMU's yaw) the heading stays within 0.31 deg instead
//   of 1.70 deg, but the direction of travel ends 1.8 deg short of the command instead of 0.7
//   (robots/cc8/README.md has both sets of figures); the default stays the odometry's yaw.
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
//   crab_sensing_wheels        [string] or trailing_side or none: wheels left unpowered in crab
//                                        to measure the ground (default none). trailing_side: the
//                                        steered wheels on the side the rover crabs away from
//                                        (the lighter side), chosen from the command's vy
//   crab_driven_rolling_weight [-]      odometry weight of the powered wheels' rolling rows in crab
//                                        while sensing wheels measure (default 0.01)
//   crab_lateral_weight        [-]      odometry weight of the steered wheels' no-side-slip rows
//                                        in crab while sensing wheels measure (default 0.1)
//   crab_heading_p             [1/s]    heading hold proportional gain (default 0: off unless i > 0)
//   crab_heading_i             [1/s^2]  heading hold integral gain (default 0)
//   crab_heading_max_rate      [rad/s]  bound of the heading hold's yaw rate correction (default 0.2)
//   crab_heading_source        [string] wheels (default) or imu: the yaw the heading hold acts on,
//                                        the odometry's or an IMU's (its orientation's yaw, the last
//                                        sample: control/sensor_hardware.hpp)
//   crab_heading_imu           [string] the IMU's handle name (its <sensor name>) for source imu;
//                                        absent: the robot's only IMU (an error naming them when
//                                        it has none or several)
//   odometry_robust_scale      [m/s]    Cauchy scale of the robust odometry: a wheel disagreeing
//                                        by this much keeps half its weight (default 0.05; 0: off)
//   odometry_robust_iterations [-]      reweighting passes (default 3; 0: off)
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
//                   (a sensing wheel shows its kinematic set point and an effort of 0)
//   "drive_status"  StatePort<RoverDriveStatus>: mode, applied twist, timeout, alignment, crab
//                   sensing wheels, heading hold
//   "gains/<joint>" PidGainsPort per joint
//
// starting() holds the measured steering headings, zeroes the command and resets the PIDs; the
// odometry pose persists across restarts (reset_odometry() zeroes it).

#include <atomic>
#include <vector>

#include "control/controller.hpp"
#include "controllers/drive/rover_drive_params.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/drive/steered_drive.hpp"

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
  StatePort<JointGroupControllerState>& state_port() { return drive_.state_port(); }
  StatePort<RoverDriveStatus>& status_port() { return status_; }
  const RoverDriveConfig& config() const { return config_; }
  // Any thread: the next update() puts the odometry pose back to (0, 0, 0).
  void reset_odometry() { reset_odometry_.store(true, std::memory_order_release); }

 private:
  PlanarTwist limit_command(const PlanarTwist& target, double period) const noexcept;
  void select_sensing_wheels(bool crabbing) noexcept;
  void update_heading_hold(const PlanarTwist& target, bool moving, double period) noexcept;
  void update_odometry(double time, double period) noexcept;
  void publish(double time, double period) noexcept;

  RoverDriveConfig config_;
  SteeredDrive drive_;  // joints, PIDs, wheel set points, efforts, "state"
  TwistCommandTimeout command_timeout_;

  // Real-time working state, sized at init.
  std::vector<double> measured_headings_;  // rad
  std::vector<double> target_headings_;    // rad, from the kinematics
  std::vector<double> setpoint_headings_;  // rad, rate limited
  std::vector<double> rolling_speeds_;     // m/s, target
  std::vector<double> measured_speeds_;    // m/s, rolling
  DriveMode requested_mode_ = DriveMode::Auto;
  PlanarTwist applied_;                    // after limits, before the mode
  ModeChoice choice_;
  std::uint64_t unsupported_count_ = 0;
  double alignment_scale_ = 1.0;
  double max_steering_error_ = 0.0;
  double wheel_speed_scale_ = 1.0;
  std::vector<double> rolling_weights_;    // odometry row weights, per wheel
  std::vector<double> lateral_weights_;
  std::vector<double> work_rolling_;       // scratch of the robust estimate
  std::vector<double> work_lateral_;
  std::vector<std::uint8_t> sensing_;      // per wheel: unpowered, measuring the ground, this tick
  bool crab_sensing_ = false;              // some wheel is sensing this tick
  bool heading_hold_ = false;
  ImuSensorHandle heading_imu_;  // valid when crab_heading_source is imu
  double held_yaw_ = 0.0;                  // rad, odometry frame
  double heading_integral_ = 0.0;          // rad s
  double yaw_correction_ = 0.0;            // rad/s
  PlanarOdometry odometry_;
  std::atomic<bool> reset_odometry_{false};

  TwistCommandPort command_{"cmd_vel"};
  DriveModeCommandPort mode_{"mode"};
  StatePort<OdometrySnapshot> odom_{"odom"};
  StatePort<RoverDriveStatus> status_{"drive_status"};
};

}  // namespace mechsim::control
