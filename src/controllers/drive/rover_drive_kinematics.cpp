#include "controllers/drive/rover_drive_kinematics.hpp"

#include <cmath>
#include <numbers>

#include "control/angles.hpp"

namespace mechsim::control {

const char* drive_mode_name(DriveMode mode) {
  switch (mode) {
    case DriveMode::Auto: return "auto";
    case DriveMode::Ackermann: return "ackermann";
    case DriveMode::Crab: return "crab";
    case DriveMode::PointTurn: return "point_turn";
  }
  return "?";
}

bool parse_drive_mode(std::string_view text, DriveMode& out) {
  for (DriveMode m : {DriveMode::Auto, DriveMode::Ackermann, DriveMode::Crab, DriveMode::PointTurn}) {
    if (text == drive_mode_name(m)) {
      out = m;
      return true;
    }
  }
  return false;
}

void finish_rover_kinematics(RoverKinematics& k) {
  double sum_x = 0.0;
  int fixed = 0;
  for (const RoverWheel& w : k.wheels) {
    if (w.steering >= 0) continue;
    sum_x += w.x;
    ++fixed;
  }
  k.axle_x = fixed > 0 ? sum_x / fixed : 0.0;
  double sum_r = 0.0;
  for (const RoverWheel& w : k.wheels) sum_r += std::hypot(w.x - k.axle_x, w.y);
  k.characteristic_length = k.wheels.empty() || sum_r <= 0.0 ? 1.0 : sum_r / static_cast<double>(k.wheels.size());
  k.steering_wheel.assign(k.steering_axis_signs.size(), -1);
  for (std::size_t i = 0; i < k.wheels.size(); ++i) {
    const int s = k.wheels[i].steering;
    if (s >= 0 && static_cast<std::size_t>(s) < k.steering_wheel.size()) k.steering_wheel[static_cast<std::size_t>(s)] = static_cast<int>(i);
  }
}

ModeChoice select_drive_mode(const RoverKinematics& k, DriveMode requested, const PlanarTwist& c, double deadband) {
  const bool has_vx = std::abs(c.vx) > deadband;
  const bool has_vy = std::abs(c.vy) > deadband;
  const bool has_wz = std::abs(c.wz) > deadband;
  ModeChoice out;
  DriveMode mode = requested;
  if (mode == DriveMode::Auto) {
    if (has_vy && !has_wz) {
      mode = DriveMode::Crab;
    } else if (!has_vx && !has_vy && has_wz) {
      mode = DriveMode::PointTurn;
    } else if (!has_vy) {
      mode = DriveMode::Ackermann;
    } else {
      // vy and wz together: the fixed wheels allow only one of them. Keep the larger, measured
      // as the wheel speed each produces.
      mode = std::abs(c.vy) > std::abs(c.wz) * k.characteristic_length ? DriveMode::Crab : DriveMode::Ackermann;
    }
  }
  out.mode = mode;
  switch (mode) {
    case DriveMode::Ackermann:
    case DriveMode::Auto:  // unreachable: resolved above
      out.mode = DriveMode::Ackermann;
      out.twist = {c.vx, 0.0, c.wz};
      out.unsupported = has_vy;
      break;
    case DriveMode::Crab:
      out.twist = {c.vx, c.vy, 0.0};
      out.unsupported = has_wz;
      break;
    case DriveMode::PointTurn:
      out.twist = {0.0, 0.0, c.wz};
      out.unsupported = has_vx || has_vy;
      break;
  }
  return out;
}

void wheel_point_velocity(const RoverKinematics& k, std::size_t i, const PlanarTwist& t, double& vx,
                          double& vy) noexcept {
  const RoverWheel& w = k.wheels[i];
  vx = t.vx - t.wz * w.y;
  vy = t.vy + t.wz * (w.x - k.axle_x);
}

double fold_heading(double vx, double vy, double max_angle, double reference, bool& reverse) noexcept {
  const double forward = std::atan2(vy, vx);
  const double backward = normalize_angle(forward + std::numbers::pi);
  const double slack = 1e-9;
  const bool forward_ok = std::abs(forward) <= max_angle + slack;
  const bool backward_ok = std::abs(backward) <= max_angle + slack;
  const auto distance = [reference](double a) { return std::abs(shortest_angular_distance(reference, a)); };
  if (forward_ok && backward_ok) {
    reverse = distance(backward) < distance(forward);
  } else if (forward_ok || backward_ok) {
    reverse = backward_ok;
  } else {
    reverse = distance(backward) < distance(forward);
    const double chosen = reverse ? backward : forward;
    return std::fmin(std::fmax(chosen, -max_angle), max_angle);
  }
  return reverse ? backward : forward;
}

double rolling_speed(const RoverKinematics& k, std::size_t i, double heading, const PlanarTwist& t) noexcept {
  double vx = 0.0, vy = 0.0;
  wheel_point_velocity(k, i, t, vx, vy);
  const RoverWheel& w = k.wheels[i];
  if (w.steering < 0) return vx;  // a fixed wheel rolls along x; what is across it slips
  return std::cos(heading) * vx + std::sin(heading) * vy - t.wz * w.offset;
}

void inverse_kinematics(const RoverKinematics& k, const PlanarTwist& t, std::span<const double> hold_headings,
                        std::span<const double> reference_headings, std::span<double> headings,
                        std::span<double> speeds, double min_speed) noexcept {
  for (std::size_t s = 0; s < k.steering_wheel.size(); ++s) {
    const auto i = static_cast<std::size_t>(k.steering_wheel[s]);
    double vx = 0.0, vy = 0.0;
    wheel_point_velocity(k, i, t, vx, vy);
    if (std::hypot(vx, vy) < min_speed) {
      headings[s] = hold_headings[s];
    } else {
      bool reverse = false;
      headings[s] = fold_heading(vx, vy, k.max_steering_angle, reference_headings[s], reverse);
    }
  }
  for (std::size_t i = 0; i < k.wheels.size(); ++i) {
    const int s = k.wheels[i].steering;
    const double heading = s >= 0 ? headings[static_cast<std::size_t>(s)] : 0.0;
    speeds[i] = rolling_speed(k, i, heading, t);
  }
}

bool estimate_twist(const RoverKinematics& k, std::span<const double> headings, std::span<const double> speeds,
                    PlanarTwist& twist, double* rms_residual, double fixed_lateral_weight) noexcept {
  // Unknowns u = (vx, vy, wz) of B's origin. The tyre at c moves at v + wz * (-c_y, c_x);
  // along the heading h this is the rolling speed, across it (n) zero: two rows a . u = b per
  // wheel. Normal equations M u = r with M = sum a a^T, r = sum a b.
  double M[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double r[3] = {0, 0, 0};
  const auto add_row = [&](const double a[3], double b) {
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) M[p][q] += a[p] * a[q];
      r[p] += a[p] * b;
    }
  };
  const auto rows = [&](std::size_t i, double out_h[3], double out_n[3]) {
    const RoverWheel& w = k.wheels[i];
    const double heading = w.steering >= 0 ? headings[static_cast<std::size_t>(w.steering)] : 0.0;
    const double hx = std::cos(heading), hy = std::sin(heading);
    const double nx = -hy, ny = hx;
    const double off = w.steering >= 0 ? w.offset : 0.0;
    const double cx = w.x + off * nx, cy = w.y + off * ny;
    out_h[0] = hx, out_h[1] = hy, out_h[2] = -hx * cy + hy * cx;
    out_n[0] = nx, out_n[1] = ny, out_n[2] = -nx * cy + ny * cx;
  };
  for (std::size_t i = 0; i < k.wheels.size(); ++i) {
    double a_h[3], a_n[3];
    rows(i, a_h, a_n);
    add_row(a_h, speeds[i]);
    if (k.wheels[i].steering < 0) {
      for (double& a : a_n) a *= fixed_lateral_weight;
    }
    add_row(a_n, 0.0);
  }
  const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                     M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  const double scale = M[0][0] * M[1][1] * M[2][2];
  if (!(std::abs(det) > 1e-12 * std::fmax(scale, 1e-300)) || !std::isfinite(det)) return false;
  double u[3];
  for (int col = 0; col < 3; ++col) {  // Cramer's rule: three unknowns, no allocation
    double A[3][3];
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) A[p][q] = q == col ? r[p] : M[p][q];
    }
    const double d = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    u[col] = d / det;
  }
  if (!std::isfinite(u[0]) || !std::isfinite(u[1]) || !std::isfinite(u[2])) return false;
  twist = {u[0], u[1], u[2]};
  if (rms_residual != nullptr) {
    double sum = 0.0;
    for (std::size_t i = 0; i < k.wheels.size(); ++i) {
      double a_h[3], a_n[3];
      rows(i, a_h, a_n);
      const double e_h = a_h[0] * u[0] + a_h[1] * u[1] + a_h[2] * u[2] - speeds[i];
      const double w = k.wheels[i].steering < 0 ? fixed_lateral_weight : 1.0;
      const double e_n = w * (a_n[0] * u[0] + a_n[1] * u[1] + a_n[2] * u[2]);
      sum += e_h * e_h + e_n * e_n;
    }
    *rms_residual = k.wheels.empty() ? 0.0 : std::sqrt(sum / (2.0 * static_cast<double>(k.wheels.size())));
  }
  return true;
}

PlanarPose integrate_pose(const PlanarPose& pose, const PlanarTwist& t, double dt) noexcept {
  const double dtheta = t.wz * dt;
  double a = 1.0, b = 0.0;  // sin(d)/d and (1 - cos(d))/d
  if (std::abs(dtheta) < 1e-6) {
    a = 1.0 - dtheta * dtheta / 6.0;
    b = dtheta / 2.0;
  } else {
    a = std::sin(dtheta) / dtheta;
    b = (1.0 - std::cos(dtheta)) / dtheta;
  }
  const double dx_body = (a * t.vx - b * t.vy) * dt;
  const double dy_body = (b * t.vx + a * t.vy) * dt;
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return {pose.x + c * dx_body - s * dy_body, pose.y + s * dx_body + c * dy_body, normalize_angle(pose.yaw + dtheta)};
}

}  // namespace mechsim::control
