#include "controllers/pr2/laser_scan_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mechsim::control {

namespace {

bool fail(std::string* error, const std::string& why) {
  if (error) *error = why;
  return false;
}

// Shortest time (s) to move `distance` (rad) from rest to rest: at max velocity (linear), or
// accelerating and braking at max acceleration with the velocity capped (blended).
double minimum_duration(double distance, bool blended, const ScanLimits& l) noexcept {
  const double d = std::abs(distance);
  if (!blended) return d / l.max_velocity;
  const double v2_over_a = l.max_velocity * l.max_velocity / l.max_acceleration;
  return d >= v2_over_a ? d / l.max_velocity + l.max_velocity / l.max_acceleration : 2.0 * std::sqrt(d / l.max_acceleration);
}

}  // namespace

const char* periodic_profile_name(PeriodicProfile p) noexcept {
  switch (p) {
    case PeriodicProfile::Hold: return "hold";
    case PeriodicProfile::Linear: return "linear";
    case PeriodicProfile::BlendedLinear: return "blended_linear";
    case PeriodicProfile::Sine: return "sine";
  }
  return "?";
}

bool parse_periodic_profile(std::string_view text, PeriodicProfile& out) {
  if (text == "linear") {
    out = PeriodicProfile::Linear;
  } else if (text == "blended_linear") {
    out = PeriodicProfile::BlendedLinear;
  } else if (text == "sine") {
    out = PeriodicProfile::Sine;
  } else {
    return false;
  }
  return true;
}

LaserScanProfile LaserScanProfile::hold(double position) noexcept {
  LaserScanProfile p;
  p.kind_ = PeriodicProfile::Hold;
  p.offset_ = position;
  return p;
}

bool LaserScanProfile::from_periodic(const PeriodicCommand& c, const ScanLimits& limits, LaserScanProfile& out,
                                     std::string* error) {
  if (!std::isfinite(c.period) || !std::isfinite(c.amplitude) || !std::isfinite(c.offset)) {
    return fail(error, "a value is not finite");
  }
  if (!(c.period > 0.0)) return fail(error, "period " + std::to_string(c.period) + " s is not > 0");
  if (c.amplitude < 0.0) return fail(error, "amplitude " + std::to_string(c.amplitude) + " rad is negative");
  switch (c.profile) {
    case PeriodicProfile::Hold:
      out = hold(c.offset);
      return true;
    case PeriodicProfile::Sine:
      out = LaserScanProfile{};
      out.kind_ = PeriodicProfile::Sine;
      out.period_ = c.period;
      out.amplitude_ = c.amplitude;
      out.offset_ = c.offset;
      return true;
    case PeriodicProfile::Linear:
    case PeriodicProfile::BlendedLinear: {
      const double low = c.offset - c.amplitude, high = c.offset + c.amplitude;
      LaserTrajCommand t;
      t.profile = c.profile;
      t.positions = {low, high, low};
      t.times_from_start = {0.0, c.period / 2.0, c.period};
      return from_trajectory(t, limits, out, error);
    }
  }
  return fail(error, "unknown profile " + std::to_string(static_cast<int>(c.profile)));
}

bool LaserScanProfile::from_trajectory(const LaserTrajCommand& c, const ScanLimits& defaults, LaserScanProfile& out,
                                       std::string* error) {
  if (c.profile != PeriodicProfile::Linear && c.profile != PeriodicProfile::BlendedLinear) {
    return fail(error, std::string("profile '") + periodic_profile_name(c.profile) +
                           "' is not a trajectory profile (linear or blended_linear)");
  }
  const std::size_t n = c.positions.size();
  if (n == 0) return fail(error, "no point");
  if (c.times_from_start.size() != n) {
    return fail(error, std::to_string(n) + " positions but " + std::to_string(c.times_from_start.size()) + " times");
  }
  if (n > kMaxLaserScanPoints) {
    return fail(error, std::to_string(n) + " points (at most " + std::to_string(kMaxLaserScanPoints) + ")");
  }
  if (!std::isfinite(c.max_velocity) || !std::isfinite(c.max_acceleration)) return fail(error, "a limit is not finite");
  ScanLimits l = defaults;
  if (c.max_velocity > 0.0) l.max_velocity = c.max_velocity;
  if (c.max_acceleration > 0.0) l.max_acceleration = c.max_acceleration;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(c.positions[k]) || !std::isfinite(c.times_from_start[k])) {
      return fail(error, "point " + std::to_string(k) + " is not finite");
    }
    if (k > 0 && c.times_from_start[k] < c.times_from_start[k - 1]) {
      return fail(error, "time of point " + std::to_string(k) + " (" + std::to_string(c.times_from_start[k]) +
                             " s) is before the one of point " + std::to_string(k - 1));
    }
  }
  const bool blended = c.profile == PeriodicProfile::BlendedLinear;
  LaserScanProfile p;
  p.kind_ = c.profile;
  p.count_ = n;
  p.offset_ = c.positions[0];
  // Times from 0, each segment stretched to what the limits allow.
  p.t_[0] = 0.0;
  p.q_[0] = c.positions[0];
  for (std::size_t k = 1; k < n; ++k) {
    const double given = c.times_from_start[k] - c.times_from_start[k - 1];
    p.q_[k] = c.positions[k];
    p.t_[k] = p.t_[k - 1] + std::max(given, minimum_duration(p.q_[k] - p.q_[k - 1], blended, l));
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double d = p.t_[k + 1] - p.t_[k];
    p.v_[k] = d > 0.0 ? (p.q_[k + 1] - p.q_[k]) / d : 0.0;
  }
  p.closed_ = n > 2 && p.q_[n - 1] == p.q_[0];
  if (blended && n > 2) {
    // A blend at an interior point (and at the loop of a closed profile) turns the incoming
    // segment's velocity into the outgoing one at max_acceleration; it never reaches past the
    // middle of either segment (points too close for max_acceleration blend harder).
    const auto segment = [&](std::size_t k) { return p.t_[k + 1] - p.t_[k]; };
    for (std::size_t k = 0; k < n; ++k) {
      const bool interior = k > 0 && k + 1 < n;
      if (!interior && !p.closed_) continue;
      const std::size_t in = k == 0 ? n - 2 : k - 1;
      const std::size_t outgoing = k + 1 == n ? 0 : k;
      const double width = std::abs(p.v_[outgoing] - p.v_[in]) / l.max_acceleration;
      p.blend_[k] = std::min({width, segment(in), segment(outgoing)});
    }
  }
  out = p;
  return true;
}

double LaserScanProfile::duration() const noexcept {
  switch (kind_) {
    case PeriodicProfile::Sine: return period_;
    case PeriodicProfile::Linear:
    case PeriodicProfile::BlendedLinear: return count_ > 0 ? t_[count_ - 1] : 0.0;
    case PeriodicProfile::Hold: break;
  }
  return 0.0;
}

void LaserScanProfile::sample(double t, double& position, double& velocity) const noexcept {
  t = std::fmax(t, 0.0);
  switch (kind_) {
    case PeriodicProfile::Hold: break;
    case PeriodicProfile::Sine: {
      const double phase = std::fmod(t, period_) / period_;
      const double w = 2.0 * std::numbers::pi / period_;
      position = offset_ + amplitude_ * std::sin(2.0 * std::numbers::pi * phase);
      velocity = amplitude_ * w * std::cos(2.0 * std::numbers::pi * phase);
      return;
    }
    case PeriodicProfile::Linear:
    case PeriodicProfile::BlendedLinear: sample_points(t, position, velocity); return;
  }
  position = offset_;
  velocity = 0.0;
}

void LaserScanProfile::sample_points(double t, double& position, double& velocity) const noexcept {
  const std::size_t n = count_;
  const double total = t_[n - 1];
  if (n == 1 || !(total > 0.0)) {
    position = q_[n - 1];
    velocity = 0.0;
    return;
  }
  t = std::fmod(t, total);
  // The segment [t_k, t_k+1) holding t.
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(t_.begin() + 1, t_.begin() + static_cast<std::ptrdiff_t>(n), t) -
                                                 t_.begin()) - 1;
  const std::size_t seg = std::min(k, n - 2);
  // A blend around point j: incoming velocity v_in, outgoing v_out, centred at t_j (tau = t - t_j).
  const auto blend = [&](std::size_t j, double tau, double v_in, double v_out) {
    const double b = blend_[j];
    const double a = (v_out - v_in) / b;
    const double s = tau + b / 2.0;
    position = q_[j] + v_in * tau + 0.5 * a * s * s;
    velocity = v_in + a * s;
  };
  const double tau_start = t - t_[seg];
  const double tau_end = t - t_[seg + 1];
  if (blend_[seg] > 0.0 && tau_start < blend_[seg] / 2.0) {
    blend(seg, tau_start, seg == 0 ? v_[n - 2] : v_[seg - 1], v_[seg]);
  } else if (blend_[seg + 1] > 0.0 && tau_end > -blend_[seg + 1] / 2.0) {
    const std::size_t j = seg + 1;
    blend(j, tau_end, v_[seg], j + 1 == n ? v_[0] : v_[j]);
  } else {
    position = q_[seg] + v_[seg] * tau_start;
    velocity = v_[seg];
  }
}

}  // namespace mechsim::control
