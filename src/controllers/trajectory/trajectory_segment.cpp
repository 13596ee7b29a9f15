#include "controllers/trajectory/trajectory_segment.hpp"

namespace mechsim::control {

const char* spline_order_name(SplineOrder order) noexcept {
  switch (order) {
    case SplineOrder::Linear: return "linear";
    case SplineOrder::Cubic: return "cubic";
    case SplineOrder::Quintic: return "quintic";
  }
  return "?";
}

SplineSegment::SplineSegment(double start_time, const SplineState& start, double end_time, const SplineState& end,
                             SplineOrder order) noexcept
    : start_time_(start_time), duration_(end_time > start_time ? end_time - start_time : 0.0), order_(order) {
  const double T = duration_;
  if (T <= 0.0) {
    // A step: the end state from the start on. evaluate() returns coefs_[0..2] for t = 0.
    coefs_ = {end.position, end.velocity, 0.5 * end.acceleration, 0.0, 0.0, 0.0};
    if (order == SplineOrder::Linear) coefs_[1] = coefs_[2] = 0.0;
    if (order == SplineOrder::Cubic) coefs_[2] = 0.0;
    return;
  }
  const double dp = end.position - start.position;
  const double T2 = T * T;
  const double T3 = T2 * T;
  switch (order) {
    case SplineOrder::Linear:
      coefs_ = {start.position, dp / T, 0.0, 0.0, 0.0, 0.0};
      break;
    case SplineOrder::Cubic:
      coefs_ = {start.position,
                start.velocity,
                (3.0 * dp - (2.0 * start.velocity + end.velocity) * T) / T2,
                (-2.0 * dp + (start.velocity + end.velocity) * T) / T3,
                0.0,
                0.0};
      break;
    case SplineOrder::Quintic: {
      const double T4 = T3 * T;
      const double T5 = T4 * T;
      const double v0 = start.velocity, v1 = end.velocity, a0 = start.acceleration, a1 = end.acceleration;
      coefs_ = {start.position,
                v0,
                0.5 * a0,
                (20.0 * dp - (8.0 * v1 + 12.0 * v0) * T - (3.0 * a0 - a1) * T2) / (2.0 * T3),
                (-30.0 * dp + (14.0 * v1 + 16.0 * v0) * T + (3.0 * a0 - 2.0 * a1) * T2) / (2.0 * T4),
                (12.0 * dp - 6.0 * (v1 + v0) * T - (a0 - a1) * T2) / (2.0 * T5)};
      break;
    }
  }
}

SplineSegment SplineSegment::hold(double start_time, double position) noexcept {
  return SplineSegment(start_time, SplineState{position, 0.0, 0.0}, start_time, SplineState{position, 0.0, 0.0},
                       SplineOrder::Linear);
}

SplineState SplineSegment::evaluate(double t) const noexcept {
  const auto& c = coefs_;
  SplineState s;
  s.position = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
  s.velocity = c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])));
  s.acceleration = 2.0 * c[2] + t * (6.0 * c[3] + t * (12.0 * c[4] + t * 20.0 * c[5]));
  return s;
}

SplineState SplineSegment::sample(double time) const noexcept {
  const double t = time - start_time_;
  if (t < 0.0) return SplineState{coefs_[0], 0.0, 0.0};
  if (t > duration_) return SplineState{evaluate(duration_).position, 0.0, 0.0};
  return evaluate(t);
}

}  // namespace mechsim::control
