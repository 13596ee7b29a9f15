#pragma once
// ros2_controllers' diff_drive_controller/DiffDriveController parameters (Humble and Jazzy), read
// into the DiffDriveConfig mechsim's diff drive runs (controllers/drive/diff_drive_controller.hpp):
//
//   left_wheel_names, right_wheel_names   [string], required, as many on each side
//   wheel_separation, wheel_radius        m, required (> 0; ros2_controllers reads no URDF)
//   wheel_separation_multiplier, left_wheel_radius_multiplier, right_wheel_radius_multiplier  1.0
//   odom_frame_id, base_frame_id          odom, base_link
//   pose_covariance_diagonal, twist_covariance_diagonal   6 values, zeros
//   open_loop false; position_feedback true (false: odometry from the wheels' velocities)
//   enable_odom_tf true; cmd_vel_timeout 0.5 s; publish_limited_velocity false ("cmd_vel_out")
//   velocity_rolling_window_size 10; publish_rate 50 Hz (odometry and TF, for the wire layer)
//   linear.x.* and angular.z.*: has_{velocity,acceleration,jerk}_limits (false), max_/min_
//     {velocity, acceleration, jerk} (NaN: unset; a min unset is -max; a limit switched on
//     without its max is an error, as ros2_controllers' SpeedLimiter throws)
//   Read by the wire layer, not here: use_stamped_vel (Humble: TwistStamped on ~/cmd_vel when
//     true (default), Twist on ~/cmd_vel_unstamped when false; Jazzy takes TwistStamped only),
//     tf_frame_prefix_enable, tf_frame_prefix (Jazzy). wheels_per_side is read and ignored (its
//     meaning is what the separation multiplier calibrates).
// Throws ControllerConfigError or ParamsError naming the parameter's path.

#include "control/params.hpp"
#include "controllers/drive/diff_drive_params.hpp"
#include "controllers/drive/speed_limiter.hpp"

namespace mechsim::control {

DiffDriveConfig read_ros2_diff_drive_config(const Params& params);

// ros2_controllers' SpeedLimiter parameters under `params` (e.g. the controller's linear/x).
SpeedLimiter read_ros2_speed_limiter(const Params& params);

}  // namespace mechsim::control
