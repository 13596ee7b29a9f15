#pragma once
// Configuration of the rover drive controller (controllers/drive/rover_drive_controller.hpp): reading
// its parameters, and filling its geometry parameters from a robot description when the YAML
// leaves them out. Configuration time only: allocates and throws ControllerConfigError or
// ParamsError, each naming the parameter path.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "control/hardware.hpp"
#include "control/params.hpp"
#include "controllers/drive/rover_drive_kinematics.hpp"
#include "controllers/drive/rover_drive_odometry.hpp"
#include "description/robot_model.hpp"

namespace mechsim::control {

inline constexpr const char* kRoverDriveControllerType = "mechsim/RoverDriveController";

struct RoverDriveConfig {
  std::vector<std::string> steering_joints;
  std::vector<std::string> wheel_joints;
  RoverKinematics kinematics;  // finished (finish_rover_kinematics)

  double max_steering_rate = 0.0;         // rad/s of heading, > 0 (inf: unlimited)
  double max_wheel_speed = 0.0;           // rad/s of wheel joint, > 0 (inf: unlimited)
  double max_linear_velocity = 0.0;       // m/s, per component of the command (inf: unlimited)
  double max_angular_velocity = 0.0;      // rad/s (inf: unlimited)
  double max_linear_acceleration = 0.0;   // m/s^2, per component (inf: unlimited)
  double max_angular_acceleration = 0.0;  // rad/s^2 (inf: unlimited)
  double cmd_vel_timeout = 0.5;           // s; <= 0 disables the timeout
  double steering_tolerance = 0.05;       // rad: wheels at full speed within it
  double steering_stop_error = 0.35;      // rad: wheels stopped beyond it (linear in between)
  // Crab: wheels left unpowered while crabbing, so that they roll with the ground and measure
  // it. crab_sensing_wheels is a list of wheel joints (crab_sensing, per wheel) or
  // "trailing_side": the steered wheels on the side the rover crabs away from (y * vy < 0),
  // the lighter side, chosen each tick.
  enum class CrabSensing : std::uint8_t { None, Listed, TrailingSide };
  CrabSensing crab_sensing_mode = CrabSensing::None;
  std::vector<std::uint8_t> crab_sensing;  // Listed: 1 for a sensing wheel (wheel_count)
  // Odometry weights in crab while sensing wheels measure: the powered wheels' rolling rows
  // (they report their set points) and the steered wheels' no-side-slip rows (they creep
  // sideways under the fixed wheels' drag). The sensing wheels' rolling rows weigh 1.
  double crab_driven_rolling_weight = 0.01;
  double crab_lateral_weight = 0.1;
  // Crab heading hold: yaw rate correction (rad/s) = p * e + i * integral(e), e the odometry
  // yaw error (rad) from the yaw held at the start of the crab command, bounded by max_rate.
  double crab_heading_p = 0.0;         // 1/s; 0 with i = 0: off
  double crab_heading_i = 0.0;         // 1/s^2
  double crab_heading_max_rate = 0.2;  // rad/s
  // Where the heading hold reads the yaw: the drive's own odometry (the wheels, the default) or an
  // IMU's orientation (crab_heading_imu: its handle name, control/sensor_hardware.hpp; absent, the
  // robot's only IMU).
  enum class HeadingSource : std::uint8_t { Wheels, Imu };
  HeadingSource crab_heading_source = HeadingSource::Wheels;
  std::string crab_heading_imu;  // the IMU's handle name (Imu only)
  RobustOdometryOptions odometry_robust;  // odometry_robust_scale (m/s), odometry_robust_iterations
  std::string odom_frame_id = "odom";
  std::string base_frame_id = "base_link";
  std::array<double, 6> pose_covariance_diagonal{};   // x, y, z, roll, pitch, yaw
  std::array<double, 6> twist_covariance_diagonal{};  // vx, vy, vz, wx, wy, wz
};

// A list of joint names at `key` (steering_joints, wheel_joints): at least `min_count`, none
// empty or repeated.
std::vector<std::string> read_rover_joint_list(const Params& params, const char* key, std::size_t min_count);

// The steering (or caster) and wheel joint lists, each read by read_rover_joint_list; throws
// naming both parameters when a joint is in both.
struct SteeredJointLists {
  std::vector<std::string> steering;
  std::vector<std::string> wheels;
};
SteeredJointLists read_steered_joint_lists(const Params& params, const char* steering_key, std::size_t min_steering,
                                           const char* wheel_key, std::size_t min_wheels);

// Reads every parameter (see the list in rover_drive_controller.hpp). `hardware` gives the
// joints' URDF velocity limits, the defaults of max_steering_rate and max_wheel_speed. Throws
// ControllerConfigError / ParamsError naming the parameter path.
RoverDriveConfig read_rover_drive_config(const Params& params, const RobotHardware& hardware);

// Sets the geometry parameters the controller at `params` lacks (wheel_radius,
// wheel_positions, wheel_axis_signs, wheel_steering, steering_positions, steering_axis_signs)
// from `model` (description::rover_geometry, base link = the base_frame_id parameter, default
// base_link). Values already present are kept. Returns the number of parameters set. Throws
// ControllerConfigError when the joints parameters are missing or the description does not fit
// (the message names the parameter path and the joint).
int fill_rover_drive_geometry(const Params& params, const description::RobotModel& model);

// Calls fill_rover_drive_geometry for every controller under `ns` (a map of controllers, e.g.
// /cc8) whose `type` is kRoverDriveControllerType. Returns the number of controllers filled.
int fill_rover_drive_geometry_all(const Params& ns, const description::RobotModel& model);

}  // namespace mechsim::control
