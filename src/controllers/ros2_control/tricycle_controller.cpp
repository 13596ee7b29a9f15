#include "controllers/ros2_control/tricycle_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "controllers/param_checks.hpp"

namespace mechsim::control {

namespace {

constexpr double kBig = 1000.0;  // ros2_controllers' "arbitrarily big number" for an unset max

double nan_param(const Params& params, const std::string& key) {
  const double v = params.get<double>(key, std::numeric_limits<double>::quiet_NaN());
  if (std::isinf(v)) throw ControllerConfigError("parameter " + join_param_path(params.path(), key) + " is not finite");
  return v;
}

void pair_defaults(double& min, double& max, double min_default) {
  if (!std::isnan(min) && std::isnan(max)) max = kBig;
  if (!std::isnan(max) && std::isnan(min)) min = min_default;
}

void require_non_negative(const Params& params, const char* group, const char* what, double min, double max) {
  if (min < 0.0 || max < 0.0) {
    throw ControllerConfigError("parameters " + join_param_path(params.path(), std::string(group) + "/min_" + what) + " / max_" +
                                what + ": negative limits are refused (ros2_controllers applies the positive limit in "
                                "both directions)");
  }
  if (min > max) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), std::string(group) + "/min_" + what) +
                                " is above max_" + what);
  }
}

double clamp_magnitude(double v, double low, double high) { return std::copysign(std::clamp(std::fabs(v), low, high), v); }

bool set(double a, double b) { return !std::isnan(a) && !std::isnan(b); }

std::string required_string(const Params& params, const char* key) {
  const std::string path = join_param_path(params.path(), key);
  if (!params.has(key)) throw ControllerConfigError("parameter " + path + " not set (ros2_controllers requires it)");
  const std::string v = params.get<std::string>(key);
  if (v.empty()) throw ControllerConfigError("parameter " + path + " is empty");
  return v;
}

std::array<double, 6> diagonal(const Params& params, const char* key) {
  std::array<double, 6> out{};
  if (!params.has(key)) return out;
  const auto v = params.get<std::vector<double>>(key);
  if (v.size() != 6) throw ControllerConfigError("parameter " + join_param_path(params.path(), key) + " must list 6 values");
  std::copy(v.begin(), v.end(), out.begin());
  return out;
}

}  // namespace

double TractionLimiter::limit(double v, double v0, double v1, double dt) const noexcept {
  if (set(min_jerk, max_jerk)) {
    const double dv = v - v0, dv0 = v0 - v1, dt2 = 2.0 * dt * dt;
    const double da = std::clamp(std::fabs(dv - dv0), min_jerk * dt2, max_jerk * dt2);
    v = v0 + dv0 + std::copysign(da, dv - dv0 >= 0.0 ? 1.0 : -1.0);
  }
  if (set(min_acceleration, max_acceleration)) {
    const bool accelerating = std::fabs(v) >= std::fabs(v0);
    const double low = (accelerating ? min_acceleration : min_deceleration) * dt;
    const double high = (accelerating ? max_acceleration : max_deceleration) * dt;
    if (!std::isnan(low) && !std::isnan(high)) {
      const double dv = std::clamp(std::fabs(v - v0), low, high);
      v = v0 + (v - v0 >= 0.0 ? dv : -dv);
    }
  }
  if (set(min_velocity, max_velocity)) v = clamp_magnitude(v, min_velocity, max_velocity);
  return v;
}

double SteeringLimiter::limit(double p, double p0, double p1, double dt) const noexcept {
  if (set(min_acceleration, max_acceleration)) {
    const double dv = p - p0, dp0 = p0 - p1, dt2 = 2.0 * dt * dt;
    const double da = std::clamp(std::fabs(dv - dp0), min_acceleration * dt2, max_acceleration * dt2);
    p = p0 + dp0 + (dv - dp0 >= 0.0 ? da : -da);
  }
  if (set(min_velocity, max_velocity)) {
    const double dv = std::clamp(std::fabs(p - p0), min_velocity * dt, max_velocity * dt);
    p = p0 + (p - p0 >= 0.0 ? dv : -dv);
  }
  if (set(min_position, max_position)) p = std::clamp(p, min_position, max_position);
  return p;
}

bool TricycleController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string traction = required_string(params, "traction_joint_name");
  const std::string steering = required_string(params, "steering_joint_name");
  for (const char* key : {"wheelbase", "wheel_radius"}) {
    if (!params.has(key)) throw ControllerConfigError("parameter " + join_param_path(params.path(), key) + " not set (m, > 0)");
  }
  wheelbase_ = positive_param(params, "wheelbase", 0.0);
  radius_ = positive_param(params, "wheel_radius", 0.0);
  open_loop_ = params.get<bool>("open_loop", false);
  odom_only_twist_ = params.get<bool>("odom_only_twist", false);
  (void)params.get<bool>("enable_odom_tf", false);
  (void)params.get<bool>("publish_ackermann_command", false);
  const int timeout_ms = params.get<int>("cmd_vel_timeout", 500);
  cmd_vel_timeout_ = static_cast<double>(timeout_ms) / 1000.0;
  const int window = params.get<int>("velocity_rolling_window_size", 10);
  if (window < 1) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "velocity_rolling_window_size") + " must be > 0");
  }

  TractionLimiter& t = traction_limits_;
  t = {nan_param(params, "traction/min_velocity"),     nan_param(params, "traction/max_velocity"),
       nan_param(params, "traction/min_acceleration"), nan_param(params, "traction/max_acceleration"),
       nan_param(params, "traction/min_deceleration"), nan_param(params, "traction/max_deceleration"),
       nan_param(params, "traction/min_jerk"),         nan_param(params, "traction/max_jerk")};
  pair_defaults(t.min_velocity, t.max_velocity, 0.0);
  pair_defaults(t.min_acceleration, t.max_acceleration, 0.0);
  pair_defaults(t.min_deceleration, t.max_deceleration, 0.0);
  pair_defaults(t.min_jerk, t.max_jerk, 0.0);
  require_non_negative(params, "traction", "velocity", t.min_velocity, t.max_velocity);
  require_non_negative(params, "traction", "acceleration", t.min_acceleration, t.max_acceleration);
  require_non_negative(params, "traction", "deceleration", t.min_deceleration, t.max_deceleration);
  require_non_negative(params, "traction", "jerk", t.min_jerk, t.max_jerk);
  SteeringLimiter& s = steering_limits_;
  s = {nan_param(params, "steering/min_position"),     nan_param(params, "steering/max_position"),
       nan_param(params, "steering/min_velocity"),     nan_param(params, "steering/max_velocity"),
       nan_param(params, "steering/min_acceleration"), nan_param(params, "steering/max_acceleration")};
  if (!std::isnan(s.min_position) && std::isnan(s.max_position)) s.max_position = -s.min_position;
  if (!std::isnan(s.max_position) && std::isnan(s.min_position)) s.min_position = -s.max_position;
  pair_defaults(s.min_velocity, s.max_velocity, 0.0);
  pair_defaults(s.min_acceleration, s.max_acceleration, 0.0);
  require_non_negative(params, "steering", "velocity", s.min_velocity, s.max_velocity);
  require_non_negative(params, "steering", "acceleration", s.min_acceleration, s.max_acceleration);

  const std::string tpath = join_param_path(params.path(), "traction_joint_name");
  const std::string spath = join_param_path(params.path(), "steering_joint_name");
  traction_ = hardware.claim_joint(traction, HardwareInterface::Velocity, tpath);
  steering_ = hardware.claim_joint(steering, HardwareInterface::Position, spath);
  if (!traction_.info().has_state_interface("velocity")) {
    throw ControllerConfigError("joint '" + traction + "' (" + tpath + ") has no velocity state interface");
  }
  if (!steering_.info().has_state_interface("position")) {
    throw ControllerConfigError("joint '" + steering + "' (" + spath + ") has no position state interface");
  }
  linear_mean_.init(static_cast<std::size_t>(window));
  angular_mean_.init(static_cast<std::size_t>(window));
  odom_.init(odometry_prototype(params.get<std::string>("odom_frame_id", "odom"), params.get<std::string>("base_frame_id", "base_link"),
                                diagonal(params, "pose_covariance_diagonal"), diagonal(params, "twist_covariance_diagonal")));
  return true;
}

void TricycleController::starting(double time) {
  command_timeout_.start(command_, time);
  pose_ = PlanarPose{};
  linear_mean_.reset();
  angular_mean_.reset();
  last_speed_[0] = last_speed_[1] = last_angle_[0] = last_angle_[1] = 0.0;
  traction_.set_command(0.0);
  steering_.set_command(steering_.position());
}

void TricycleController::stopping(double /*time*/) {
  traction_.set_command(0.0);
  steering_.set_command(0.0);
}

UpdateStatus TricycleController::update(double time, double period) {
  const PlanarTwist command = command_timeout_.read(command_, time, cmd_vel_timeout_);
  const double ws_read = traction_.velocity();
  const double alpha_read = steering_.position();
  double linear = 0.0, angular = 0.0;
  if (open_loop_) {
    linear = command.vx;
    angular = command.wz;
    pose_ = integrate_unicycle(pose_, linear * period, angular * period);
  } else {
    const double vs = ws_read * radius_;
    const double vx = vs * std::cos(alpha_read);
    const double w = vs * std::sin(alpha_read) / wheelbase_;
    pose_ = integrate_unicycle(pose_, vx * period, w * period);
    linear_mean_.push(vx);
    angular_mean_.push(w);
    linear = linear_mean_.mean();
    angular = angular_mean_.mean();
  }
  odom_.publish_from_rt([&](OdometrySnapshot& o) {
    o.stamp = time;
    if (!odom_only_twist_) {
      o.x = pose_.x;
      o.y = pose_.y;
      o.yaw = std::remainder(pose_.yaw, 2.0 * M_PI);
    }
    o.linear = {linear, 0.0, 0.0};
    o.angular = {0.0, 0.0, angular};
    o.valid = true;
  });

  double alpha = 0.0, ws = 0.0;
  if (command.vx == 0.0 && command.wz != 0.0) {
    alpha = command.wz > 0.0 ? M_PI_2 : -M_PI_2;
    ws = std::fabs(command.wz) * wheelbase_ / radius_;
  } else {
    alpha = command.wz == 0.0 || command.vx == 0.0 ? 0.0 : std::atan(command.wz * wheelbase_ / command.vx);
    ws = command.vx / (radius_ * std::cos(alpha));
  }
  const double delta = std::fabs(alpha - alpha_read);
  const double scale = delta < M_PI / 6.0 ? 1.0 : (delta > M_PI_2 ? 0.01 : std::cos(delta));
  ws *= scale;
  ws = traction_limits_.limit(ws, last_speed_[0], last_speed_[1], period);
  alpha = steering_limits_.limit(alpha, last_angle_[0], last_angle_[1], period);
  last_speed_[1] = last_speed_[0];
  last_speed_[0] = ws;
  last_angle_[1] = last_angle_[0];
  last_angle_[0] = alpha;
  traction_.set_command(ws);
  steering_.set_command(alpha);
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
