#pragma once
// Configuration of diff_drive_controller/DiffDriveController (diff_drive_controller.hpp): its
// parameters as ros_controllers names them, and the wheel geometry taken from the robot
// description when the YAML leaves it out (as ros_controllers reads it from robot_description).
// Configuration time only: allocates and throws ControllerConfigError or ParamsError naming the
// parameter path.

#include <array>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "controllers/drive/speed_limiter.hpp"
#include "description/robot_model.hpp"

namespace mechsim::control {

inline constexpr const char* kDiffDriveControllerType = "diff_drive_controller/DiffDriveController";

struct DiffDriveConfig {
  std::vector<std::string> left_wheels, right_wheels;  // >= 1 each (skid steer: 2 a side)
  double wheel_separation = 0.0;  // m, > 0
  double wheel_radius = 0.0;      // m, > 0
  double wheel_separation_multiplier = 1.0;
  double left_wheel_radius_multiplier = 1.0;
  double right_wheel_radius_multiplier = 1.0;
  double cmd_vel_timeout = 0.5;   // s; the command is zeroed when older
  double publish_rate = 50.0;     // Hz (sim time) of "odom" (and cmd_vel_out); <= 0: every tick
  std::string base_frame_id = "base_link";
  std::string odom_frame_id = "odom";
  bool enable_odom_tf = true;
  std::array<double, 6> pose_covariance_diagonal{};   // x, y, z, roll, pitch, yaw
  std::array<double, 6> twist_covariance_diagonal{};
  bool open_loop = false;                 // odometry from the command, not the wheels
  // ros2_controllers: odometry from the wheels' positions (true) or their velocities integrated.
  bool position_feedback = true;
  int velocity_rolling_window_size = 10;  // samples, >= 1
  bool publish_cmd = false;               // "cmd_vel_out": the command after the limits
  bool allow_multiple_cmd_vel_publishers = true;
  SpeedLimiter linear;   // linear/x
  SpeedLimiter angular;  // angular/z

  double separation() const { return wheel_separation_multiplier * wheel_separation; }  // m, as used
  double left_radius() const { return left_wheel_radius_multiplier * wheel_radius; }
  double right_radius() const { return right_wheel_radius_multiplier * wheel_radius; }
};

// `key` as a wheel list: a string or a list of strings, at least one, none repeated.
std::vector<std::string> read_wheel_list(const Params& params, const char* key);

// Every parameter (see diff_drive_controller.hpp). wheel_separation and wheel_radius must be
// there (fill_diff_drive_geometry puts the description's in).
DiffDriveConfig read_diff_drive_config(const Params& params);

// Sets wheel_separation and wheel_radius where the controller at `params` lacks them, from
// `model` as ros_controllers does from robot_description: the separation is the distance between
// the first left and the first right wheel joint's origins (at zero joint angles), the radius that
// of those wheels' collision cylinder or sphere. Returns the number of values set. Throws
// ControllerConfigError naming the parameter and the joint when the description cannot give them.
int fill_diff_drive_geometry(const Params& params, const description::RobotModel& model);

// fill_diff_drive_geometry for every diff_drive_controller under `ns`; one whose parameters
// cannot be completed is left as it is (loading it reports why). Returns how many were filled.
int fill_diff_drive_geometry_all(const Params& ns, const description::RobotModel& model);

}  // namespace mechsim::control
