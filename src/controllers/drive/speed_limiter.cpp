#include "controllers/drive/speed_limiter.hpp"

#include <algorithm>
#include <cmath>

#include "control/hardware.hpp"

namespace mechsim::control {

double SpeedLimiter::limit(double v, double v0, double v1, double dt) const noexcept {
  v = limit_jerk(v, v0, v1, dt);
  v = limit_acceleration(v, v0, dt);
  return limit_velocity(v);
}

double SpeedLimiter::limit_velocity(double v) const noexcept {
  return has_velocity_limits ? std::clamp(v, min_velocity, max_velocity) : v;
}

double SpeedLimiter::limit_acceleration(double v, double v0, double dt) const noexcept {
  if (!has_acceleration_limits) return v;
  const double dv = std::clamp(v - v0, min_acceleration * dt, max_acceleration * dt);
  return v0 + dv;
}

double SpeedLimiter::limit_jerk(double v, double v0, double v1, double dt) const noexcept {
  if (!has_jerk_limits) return v;
  // The change of velocity change from one period to the next is a jerk over dt^2; ros_controllers
  // bounds it by the jerk limits times 2 dt^2.
  const double dv = v - v0;
  const double dv0 = v0 - v1;
  const double dt2 = 2.0 * dt * dt;
  const double da = std::clamp(dv - dv0, min_jerk * dt2, max_jerk * dt2);
  return v0 + dv0 + da;
}

namespace {

// Reads `has_<what>_limits`, `max_<what>` and `min_<what>` (default -max).
void read_pair(const Params& params, const std::string& what, bool& has, double& min, double& max) {
  has = params.get<bool>("has_" + what + "_limits", false);
  max = params.get<double>("max_" + what, 0.0);
  min = params.get<double>("min_" + what, -max);
  if (!std::isfinite(max)) throw ControllerConfigError("parameter " + join_param_path(params.path(), "max_" + what) + " is not finite");
  if (!std::isfinite(min)) throw ControllerConfigError("parameter " + join_param_path(params.path(), "min_" + what) + " is not finite");
  if (has && min > max) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "min_" + what) + " (" + std::to_string(min) +
                                ") is above " + join_param_path(params.path(), "max_" + what) + " (" + std::to_string(max) + ")");
  }
}

}  // namespace

SpeedLimiter read_speed_limiter(const Params& params) {
  SpeedLimiter s;
  read_pair(params, "velocity", s.has_velocity_limits, s.min_velocity, s.max_velocity);
  read_pair(params, "acceleration", s.has_acceleration_limits, s.min_acceleration, s.max_acceleration);
  read_pair(params, "jerk", s.has_jerk_limits, s.min_jerk, s.max_jerk);
  return s;
}

}  // namespace mechsim::control
