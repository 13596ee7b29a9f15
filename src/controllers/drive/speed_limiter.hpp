#pragma once
// One component of a velocity command limited as diff_drive_controller's SpeedLimiter does:
// first the jerk (the change of acceleration over two periods), then the acceleration, then the
// velocity, each only when its has_*_limits is set. Units: m/s (linear) or rad/s (angular), and
// their first and second derivatives. No function here allocates or throws.

#include "control/params.hpp"

namespace mechsim::control {

struct SpeedLimiter {
  bool has_velocity_limits = false;
  bool has_acceleration_limits = false;
  bool has_jerk_limits = false;
  double min_velocity = 0.0, max_velocity = 0.0;          // min defaults to -max
  double min_acceleration = 0.0, max_acceleration = 0.0;  // min defaults to -max
  double min_jerk = 0.0, max_jerk = 0.0;                  // min defaults to -max

  // `v` limited, given the previous two commands v0 (one period ago) and v1 (two periods ago),
  // over the period `dt` (s). Returns the limited value.
  double limit(double v, double v0, double v1, double dt) const noexcept;
  double limit_velocity(double v) const noexcept;
  double limit_acceleration(double v, double v0, double dt) const noexcept;
  double limit_jerk(double v, double v0, double v1, double dt) const noexcept;
};

// Reads ros_controllers' keys under `params` (e.g. the controller's "linear/x" or "angular/z"
// namespace): has_velocity_limits, max_velocity, min_velocity (default -max_velocity), and
// likewise for acceleration and jerk. Absent keys keep the defaults (no limits). Throws
// ControllerConfigError naming the parameter for a non-finite value or min > max.
SpeedLimiter read_speed_limiter(const Params& params);

}  // namespace mechsim::control
