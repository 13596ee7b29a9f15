#pragma once
// One spline segment of one joint's trajectory (ros_control's trajectory_interface
// QuinticSplineSegment): a polynomial in time between two boundary states.
//   Linear:  positions only; the velocity is the constant slope, the acceleration 0.
//   Cubic:   positions and velocities at both ends.
//   Quintic: positions, velocities and accelerations at both ends.
// The boundary conditions of the chosen order hold exactly (to rounding). A segment of zero
// duration is a step to its end state.
// Sampling before the start gives the start position at rest; after the end, the end position
// at rest (the trajectory has finished there). Every member is real-time safe.

#include <array>
#include <cstdint>

namespace mechsim::control {

// Position (rad or m), velocity (rad/s or m/s), acceleration (rad/s^2 or m/s^2).
struct SplineState {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
};

enum class SplineOrder : std::uint8_t { Linear, Cubic, Quintic };
const char* spline_order_name(SplineOrder order) noexcept;
// The order ros_control picks from the fields a waypoint carries.
constexpr SplineOrder spline_order_for(bool has_velocities, bool has_accelerations) noexcept {
  return has_velocities ? (has_accelerations ? SplineOrder::Quintic : SplineOrder::Cubic) : SplineOrder::Linear;
}

class SplineSegment {
 public:
  SplineSegment() = default;
  // Times in simulation seconds, end_time >= start_time. Fields the order does not use are
  // ignored (a cubic ignores the accelerations; a linear segment the velocities too).
  SplineSegment(double start_time, const SplineState& start, double end_time, const SplineState& end,
                SplineOrder order) noexcept;
  // A segment that holds `position` at rest from `start_time` on.
  static SplineSegment hold(double start_time, double position) noexcept;

  double start_time() const noexcept { return start_time_; }
  double end_time() const noexcept { return start_time_ + duration_; }
  double duration() const noexcept { return duration_; }
  SplineOrder order() const noexcept { return order_; }

  SplineState sample(double time) const noexcept;

 private:
  SplineState evaluate(double t) const noexcept;  // t in [0, duration]

  double start_time_ = 0.0;
  double duration_ = 0.0;
  std::array<double, 6> coefs_{};  // p(t) = sum coefs_[k] t^k, t from the start
  SplineOrder order_ = SplineOrder::Linear;
};

}  // namespace mechsim::control
