#include "controllers/drive/pr2_base_kinematics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "control/angles.hpp"

namespace mechsim::control {

double caster_steer_target(double vx, double vy, double current, bool& reversed) noexcept {
  const double forward = std::atan2(vy, vx);
  reversed = std::abs(shortest_angular_distance(current, forward)) > std::numbers::pi / 2.0;
  return reversed ? normalize_angle(forward + std::numbers::pi) : forward;
}

void caster_headings(const Pr2BaseKinematics& k, const PlanarTwist& twist, std::span<const double> current,
                     std::span<const double> hold, std::span<double> headings, double hold_speed) noexcept {
  for (std::size_t c = 0; c < k.casters.size(); ++c) {
    double vx = 0.0, vy = 0.0;
    point_velocity(twist, k.casters[c].x, k.casters[c].y, vx, vy);
    if (std::hypot(vx, vy) < hold_speed) {
      headings[c] = hold[c];
      continue;
    }
    bool reversed = false;
    headings[c] = caster_steer_target(vx, vy, current[c], reversed);
  }
}

double wheel_rolling_speed(const Pr2BaseKinematics& k, std::size_t w, const PlanarTwist& twist, double heading,
                           double caster_rate) noexcept {
  const Pr2Wheel& wheel = k.wheels[w];
  const Pr2Caster& caster = k.casters[wheel.caster];
  const double c = std::cos(heading), s = std::sin(heading);
  const double px = caster.x - wheel.offset * s, py = caster.y + wheel.offset * c;
  double vx = 0.0, vy = 0.0;
  point_velocity(twist, px, py, vx, vy);
  return vx * c + vy * s - wheel.offset * caster_rate;
}

void Pr2OdometryScratch::resize(std::size_t wheel_count) {
  rows.assign(6 * wheel_count, 0.0);
  rhs.assign(2 * wheel_count, 0.0);
  weights.assign(2 * wheel_count, 1.0);
  residual.assign(2 * wheel_count, 0.0);
  sorted.assign(2 * wheel_count, 0.0);
}

namespace {

// Solves the weighted normal equations of the rows; false when they are (nearly) singular.
bool solve_weighted(const Pr2OdometryScratch& s, std::size_t n, std::array<double, 3>& x) noexcept {
  std::array<std::array<double, 4>, 3> m{};  // [A^T W A | A^T W b]
  for (std::size_t r = 0; r < n; ++r) {
    const double w = s.weights[r];
    const double* a = &s.rows[3 * r];
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) m[i][j] += w * a[i] * a[j];
      m[i][3] += w * a[i] * s.rhs[r];
    }
  }
  const double scale = m[0][0] + m[1][1] + m[2][2];
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  for (std::size_t col = 0; col < 3; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < 3; ++r) {
      if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
    }
    if (std::abs(m[pivot][col]) < 1e-12 * scale) return false;
    std::swap(m[col], m[pivot]);
    for (std::size_t r = 0; r < 3; ++r) {
      if (r == col) continue;
      const double f = m[r][col] / m[col][col];
      for (std::size_t j = col; j < 4; ++j) m[r][j] -= f * m[col][j];
    }
  }
  for (std::size_t i = 0; i < 3; ++i) x[i] = m[i][3] / m[i][i];
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

void residuals(Pr2OdometryScratch& s, std::size_t n, const std::array<double, 3>& x) noexcept {
  for (std::size_t r = 0; r < n; ++r) {
    const double* a = &s.rows[3 * r];
    s.residual[r] = a[0] * x[0] + a[1] * x[1] + a[2] * x[2] - s.rhs[r];
  }
}

}  // namespace

bool estimate_base_twist(const Pr2BaseKinematics& k, std::span<const double> headings,
                         std::span<const double> caster_rates, std::span<const double> speeds,
                         Pr2OdometryScratch& scratch, PlanarTwist& twist, int iterations, IlsWeight weight,
                         double* rms_residual) noexcept {
  const std::size_t nw = k.wheels.size();
  const std::size_t n = 2 * nw;
  if (scratch.rhs.size() < n || nw == 0) return false;
  for (std::size_t w = 0; w < nw; ++w) {
    const Pr2Wheel& wheel = k.wheels[w];
    const Pr2Caster& caster = k.casters[wheel.caster];
    const double h = headings[wheel.caster];
    const double c = std::cos(h), s = std::sin(h);
    const double px = caster.x - wheel.offset * s, py = caster.y + wheel.offset * c;
    // The wheel centre's ground velocity: along the heading only (no side slip).
    const double along = speeds[w] + wheel.offset * caster_rates[wheel.caster];
    double* rx = &scratch.rows[6 * w];
    rx[0] = 1.0, rx[1] = 0.0, rx[2] = -py;
    rx[3] = 0.0, rx[4] = 1.0, rx[5] = px;
    scratch.rhs[2 * w] = along * c;
    scratch.rhs[2 * w + 1] = along * s;
  }
  std::fill(scratch.weights.begin(), scratch.weights.begin() + static_cast<std::ptrdiff_t>(n), 1.0);
  std::array<double, 3> x{};
  if (!solve_weighted(scratch, n, x)) return false;
  for (int it = 0; it < iterations && weight != IlsWeight::Uniform; ++it) {
    residuals(scratch, n, x);
    for (std::size_t r = 0; r < n; ++r) scratch.sorted[r] = std::abs(scratch.residual[r]);
    const auto mid = scratch.sorted.begin() + static_cast<std::ptrdiff_t>(n / 2);
    std::nth_element(scratch.sorted.begin(), mid, scratch.sorted.begin() + static_cast<std::ptrdiff_t>(n));
    const double sigma = std::fmax(1.4826 * *mid, 1e-3);
    for (std::size_t r = 0; r < n; ++r) {
      const double u = scratch.residual[r] / sigma;
      // Gaussian: discounts rows beyond ~2.5 sigma almost entirely; Cauchy: more gently.
      scratch.weights[r] = weight == IlsWeight::Gaussian ? std::fmax(std::exp(-0.5 * (u / 2.5) * (u / 2.5)), 1e-9)
                                                         : 1.0 / (1.0 + (u / 2.385) * (u / 2.385));
    }
    std::array<double, 3> next{};
    if (!solve_weighted(scratch, n, next)) break;  // keep the previous estimate
    x = next;
  }
  twist = {x[0], x[1], x[2]};
  if (rms_residual != nullptr) {
    residuals(scratch, n, x);
    double sum = 0.0;
    for (std::size_t r = 0; r < n; ++r) sum += scratch.residual[r] * scratch.residual[r];
    *rms_residual = std::sqrt(sum / static_cast<double>(n));
  }
  return true;
}

}  // namespace mechsim::control
