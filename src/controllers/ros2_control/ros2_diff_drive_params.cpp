#include "controllers/ros2_control/ros2_diff_drive_params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "control/hardware.hpp"
#include "controllers/param_checks.hpp"

namespace mechsim::control {

namespace {

std::string path_of(const Params& params, std::string_view key) { return join_param_path(params.path(), key); }

std::vector<std::string> names(const Params& params, const char* key) {
  if (!params.has(key)) throw ControllerConfigError("parameter " + path_of(params, key) + " not set (the wheel joints, a list)");
  const Params p = params.child(key);
  std::vector<std::string> out = p.is_scalar() ? std::vector<std::string>{p.as<std::string>()} : p.as<std::vector<std::string>>();
  if (out.empty()) throw ControllerConfigError("parameter " + path_of(params, key) + " lists no wheel joint");
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i].empty()) throw ControllerConfigError("parameter " + path_of(params, key) + "[" + std::to_string(i) + "] is empty");
    if (std::count(out.begin(), out.end(), out[i]) > 1) {
      throw ControllerConfigError("parameter " + path_of(params, key) + ": joint '" + out[i] + "' is listed twice");
    }
  }
  return out;
}

std::array<double, 6> diagonal(const Params& params, const char* key) {
  std::array<double, 6> out{};
  if (!params.has(key)) return out;
  const auto v = params.get<std::vector<double>>(key);
  if (v.size() != 6) {
    throw ControllerConfigError("parameter " + path_of(params, key) + " must list 6 values (x, y, z, roll, pitch, yaw); got " +
                                std::to_string(v.size()));
  }
  for (std::size_t i = 0; i < 6; ++i) {
    if (!std::isfinite(v[i])) throw ControllerConfigError("parameter " + path_of(params, key) + "[" + std::to_string(i) + "] is not finite");
    out[i] = v[i];
  }
  return out;
}

// One limit pair: NaN (unset) min is -max; switched on without a max: ros2_controllers throws.
void read_limit(const Params& params, const std::string& what, bool& has, double& min, double& max) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  has = params.get<bool>("has_" + what + "_limits", false);
  max = params.get<double>("max_" + what, nan);
  min = params.get<double>("min_" + what, nan);
  if (!has) return;
  if (std::isnan(max)) {
    throw ControllerConfigError("parameter " + path_of(params, "has_" + what + "_limits") + " is true but " +
                                path_of(params, "max_" + what) + " is not set (ros2_controllers: \"Cannot apply " + what +
                                " limits if max_" + what + " is not specified\")");
  }
  if (std::isnan(min)) min = -max;
  if (!std::isfinite(max) || !std::isfinite(min)) {
    throw ControllerConfigError("parameter " + path_of(params, "max_" + what) + " / min_" + what + " is not finite");
  }
  if (min > max) {
    throw ControllerConfigError("parameter " + path_of(params, "min_" + what) + " (" + std::to_string(min) + ") is above " +
                                path_of(params, "max_" + what) + " (" + std::to_string(max) + ")");
  }
}

}  // namespace

SpeedLimiter read_ros2_speed_limiter(const Params& params) {
  SpeedLimiter s;
  read_limit(params, "velocity", s.has_velocity_limits, s.min_velocity, s.max_velocity);
  read_limit(params, "acceleration", s.has_acceleration_limits, s.min_acceleration, s.max_acceleration);
  read_limit(params, "jerk", s.has_jerk_limits, s.min_jerk, s.max_jerk);
  return s;
}

DiffDriveConfig read_ros2_diff_drive_config(const Params& params) {
  DiffDriveConfig c;
  c.left_wheels = names(params, "left_wheel_names");
  c.right_wheels = names(params, "right_wheel_names");
  if (c.left_wheels.size() != c.right_wheels.size()) {
    throw ControllerConfigError("parameters " + path_of(params, "left_wheel_names") + " and " +
                                path_of(params, "right_wheel_names") + " list " + std::to_string(c.left_wheels.size()) +
                                " and " + std::to_string(c.right_wheels.size()) +
                                " wheels (ros2_controllers needs as many on each side)");
  }
  for (const std::string& l : c.left_wheels) {
    if (std::find(c.right_wheels.begin(), c.right_wheels.end(), l) != c.right_wheels.end()) {
      throw ControllerConfigError("joint '" + l + "' is in both " + path_of(params, "left_wheel_names") + " and " +
                                  path_of(params, "right_wheel_names"));
    }
  }
  for (const char* key : {"wheel_separation", "wheel_radius"}) {
    if (!params.has(key)) throw ControllerConfigError("parameter " + path_of(params, key) + " not set (m, > 0)");
  }
  c.wheel_separation = positive_param(params, "wheel_separation", 0.0);
  c.wheel_radius = positive_param(params, "wheel_radius", 0.0);
  c.wheel_separation_multiplier = positive_param(params, "wheel_separation_multiplier", 1.0);
  c.left_wheel_radius_multiplier = positive_param(params, "left_wheel_radius_multiplier", 1.0);
  c.right_wheel_radius_multiplier = positive_param(params, "right_wheel_radius_multiplier", 1.0);
  c.cmd_vel_timeout = params.get<double>("cmd_vel_timeout", 0.5);
  if (!std::isfinite(c.cmd_vel_timeout)) throw ControllerConfigError("parameter " + path_of(params, "cmd_vel_timeout") + " is not finite");
  c.publish_rate = params.get<double>("publish_rate", 50.0);
  if (!std::isfinite(c.publish_rate)) throw ControllerConfigError("parameter " + path_of(params, "publish_rate") + " is not finite");
  c.base_frame_id = params.get<std::string>("base_frame_id", "base_link");
  c.odom_frame_id = params.get<std::string>("odom_frame_id", "odom");
  c.enable_odom_tf = params.get<bool>("enable_odom_tf", true);
  c.pose_covariance_diagonal = diagonal(params, "pose_covariance_diagonal");
  c.twist_covariance_diagonal = diagonal(params, "twist_covariance_diagonal");
  c.open_loop = params.get<bool>("open_loop", false);
  c.position_feedback = params.get<bool>("position_feedback", true);
  c.velocity_rolling_window_size = params.get<int>("velocity_rolling_window_size", 10);
  if (c.velocity_rolling_window_size < 1) {
    throw ControllerConfigError("parameter " + path_of(params, "velocity_rolling_window_size") + " must be >= 1 (got " +
                                std::to_string(c.velocity_rolling_window_size) + ")");
  }
  c.publish_cmd = params.get<bool>("publish_limited_velocity", false);
  (void)params.get<bool>("use_stamped_vel", true);  // the wire layer's; read here for its type
  (void)params.get<int>("wheels_per_side", 0);
  if (auto linear = params.find("linear/x")) c.linear = read_ros2_speed_limiter(*linear);
  if (auto angular = params.find("angular/z")) c.angular = read_ros2_speed_limiter(*angular);
  return c;
}

}  // namespace mechsim::control
