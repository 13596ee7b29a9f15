#include "controllers/drive/rover_drive_odometry.hpp"

#include <cmath>

namespace mechsim::control {
namespace {

double det3(const double A[3][3]) noexcept {
  return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
         A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

double weight_of(std::span<const double> weights, std::size_t i) noexcept { return weights.empty() ? 1.0 : weights[i]; }

}  // namespace

void wheel_odometry_rows(const RoverKinematics& k, std::size_t i, double heading, double a_h[3], double a_n[3]) noexcept {
  // The tyre at c moves at v + wz * (-c_y, c_x); h is the heading, n = h turned by +90 deg.
  const RoverWheel& w = k.wheels[i];
  if (w.steering < 0) heading = 0.0;
  const double hx = std::cos(heading), hy = std::sin(heading);
  const double nx = -hy, ny = hx;
  const double off = w.steering >= 0 ? w.offset : 0.0;
  const double cx = w.x + off * nx, cy = w.y + off * ny;
  a_h[0] = hx, a_h[1] = hy, a_h[2] = -hx * cy + hy * cx;
  a_n[0] = nx, a_n[1] = ny, a_n[2] = -nx * cy + ny * cx;
}

bool estimate_twist_weighted(const RoverKinematics& k, std::span<const double> headings, std::span<const double> speeds,
                             std::span<const double> rolling_weights, std::span<const double> lateral_weights,
                             PlanarTwist& twist, double* rms_residual) noexcept {
  // Normal equations M u = r, M = sum w a a^T, r = sum w a b, for u = (vx, vy, wz).
  double M[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double r[3] = {0, 0, 0};
  const auto heading_of = [&](std::size_t i) {
    const int s = k.wheels[i].steering;
    return s >= 0 ? headings[static_cast<std::size_t>(s)] : 0.0;
  };
  const auto add_row = [&](const double a[3], double b, double w) {
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) M[p][q] += w * a[p] * a[q];
      r[p] += w * a[p] * b;
    }
  };
  for (std::size_t i = 0; i < k.wheels.size(); ++i) {
    double a_h[3], a_n[3];
    wheel_odometry_rows(k, i, heading_of(i), a_h, a_n);
    add_row(a_h, speeds[i], weight_of(rolling_weights, i));
    add_row(a_n, 0.0, weight_of(lateral_weights, i));
  }
  const double det = det3(M);
  const double scale = M[0][0] * M[1][1] * M[2][2];
  if (!std::isfinite(det) || !(std::abs(det) > 1e-12 * std::fmax(scale, 1e-300))) return false;
  double u[3];
  for (int col = 0; col < 3; ++col) {  // Cramer's rule: three unknowns, no allocation
    double A[3][3];
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) A[p][q] = q == col ? r[p] : M[p][q];
    }
    u[col] = det3(A) / det;
  }
  if (!std::isfinite(u[0]) || !std::isfinite(u[1]) || !std::isfinite(u[2])) return false;
  twist = {u[0], u[1], u[2]};
  if (rms_residual != nullptr) {
    double sum = 0.0, weight = 0.0;
    for (std::size_t i = 0; i < k.wheels.size(); ++i) {
      double a_h[3], a_n[3];
      wheel_odometry_rows(k, i, heading_of(i), a_h, a_n);
      const double e_h = a_h[0] * u[0] + a_h[1] * u[1] + a_h[2] * u[2] - speeds[i];
      const double e_n = a_n[0] * u[0] + a_n[1] * u[1] + a_n[2] * u[2];
      const double w_h = weight_of(rolling_weights, i), w_n = weight_of(lateral_weights, i);
      sum += w_h * e_h * e_h + w_n * e_n * e_n;
      weight += w_h + w_n;
    }
    *rms_residual = weight > 0.0 ? std::sqrt(sum / weight) : 0.0;
  }
  return true;
}

bool estimate_twist_robust(const RoverKinematics& k, std::span<const double> headings, std::span<const double> speeds,
                           std::span<const double> rolling_weights, std::span<const double> lateral_weights,
                           const RobustOdometryOptions& options, std::span<double> work_rolling,
                           std::span<double> work_lateral, PlanarTwist& twist, double* rms_residual,
                           std::span<double> wheel_trust) noexcept {
  const std::size_t n = k.wheels.size();
  for (std::size_t i = 0; i < n; ++i) {
    work_rolling[i] = weight_of(rolling_weights, i);
    work_lateral[i] = weight_of(lateral_weights, i);
    if (!wheel_trust.empty()) wheel_trust[i] = 1.0;
  }
  PlanarTwist u;
  if (!estimate_twist_weighted(k, headings, speeds, work_rolling, work_lateral, u, rms_residual)) return false;
  const int passes = options.scale > 0.0 ? options.iterations : 0;
  for (int pass = 0; pass < passes; ++pass) {
    // Each wheel's residual over the rows it takes part in, from the previous estimate; the
    // weights always restart from the given ones, so a wheel can regain trust.
    for (std::size_t i = 0; i < n; ++i) {
      const int s = k.wheels[i].steering;
      double a_h[3], a_n[3];
      wheel_odometry_rows(k, i, s >= 0 ? headings[static_cast<std::size_t>(s)] : 0.0, a_h, a_n);
      const double e_h = a_h[0] * u.vx + a_h[1] * u.vy + a_h[2] * u.wz - speeds[i];
      const double e_n = a_n[0] * u.vx + a_n[1] * u.vy + a_n[2] * u.wz;
      const double w_h = weight_of(rolling_weights, i), w_n = weight_of(lateral_weights, i);
      const double e2 = (w_h > 0.0 ? e_h * e_h : 0.0) + (w_n > 0.0 ? e_n * e_n : 0.0);
      const double trust = 1.0 / (1.0 + e2 / (options.scale * options.scale));
      work_rolling[i] = w_h * trust;
      work_lateral[i] = w_n * trust;
      if (!wheel_trust.empty()) wheel_trust[i] = trust;
    }
    PlanarTwist next;
    double rms = 0.0;
    if (!estimate_twist_weighted(k, headings, speeds, work_rolling, work_lateral, next, &rms)) break;
    u = next;
    if (rms_residual != nullptr) *rms_residual = rms;
  }
  twist = u;
  return true;
}

}  // namespace mechsim::control
