#include "sim/ground_plane.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/heightmap_sample.hpp"

namespace mechsim::sim {

double GroundPlane::slope() const { return std::atan(std::hypot(gx, gy)); }

GroundPlane fit_ground_plane(const physics::Heightmap& map, const physics::Region& footprint, double x0, double y0) {
  const auto samples = [](double extent, double cell) {
    return std::clamp(static_cast<int>(std::ceil(extent / cell)) + 1, 2, 64);
  };
  const int nx = samples(footprint.x_max - footprint.x_min, map.cell_x());
  const int ny = samples(footprint.y_max - footprint.y_min, map.cell_y());
  // Normal equations of z = a + b u + c v over centred offsets u = x - x0, v = y - y0.
  std::array<double, 9> A{};
  std::array<double, 3> r{};
  for (int i = 0; i < nx; ++i) {
    const double x = footprint.x_min + (footprint.x_max - footprint.x_min) * i / (nx - 1);
    for (int k = 0; k < ny; ++k) {
      const double y = footprint.y_min + (footprint.y_max - footprint.y_min) * k / (ny - 1);
      const double z = physics::height_at(map, x, y);
      const double f[3] = {1.0, x - x0, y - y0};
      for (int p = 0; p < 3; ++p) {
        r[p] += f[p] * z;
        for (int q = 0; q < 3; ++q) A[3 * p + q] += f[p] * f[q];
      }
    }
  }
  // Cramer's rule on the symmetric, positive definite 3x3 system.
  auto det3 = [](const std::array<double, 9>& m) {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  };
  const double d = det3(A);
  GroundPlane plane{x0, y0, physics::height_at(map, x0, y0), 0.0, 0.0};
  if (!(std::abs(d) > 1e-12)) return plane;  // a degenerate footprint: the ground under (x0, y0)
  double solution[3];
  for (int c = 0; c < 3; ++c) {
    std::array<double, 9> M = A;
    for (int p = 0; p < 3; ++p) M[3 * p + c] = r[p];
    solution[c] = det3(M) / d;
  }
  plane.z0 = solution[0];
  plane.gx = solution[1];
  plane.gy = solution[2];
  return plane;
}

RollPitch roll_pitch_on(const GroundPlane& plane, double yaw) {
  // Upward normal n = (-gx, -gy, 1) / |.|; in the heading frame v = Rz(-yaw) n, and
  // Ry(pitch) Rx(roll) e_z = (sin p cos r, -sin r, cos p cos r) = v.
  const double norm = std::sqrt(1.0 + plane.gx * plane.gx + plane.gy * plane.gy);
  const double nx = -plane.gx / norm, ny = -plane.gy / norm, nz = 1.0 / norm;
  const double c = std::cos(yaw), s = std::sin(yaw);
  const double vx = c * nx + s * ny, vy = -s * nx + c * ny;
  RollPitch rp;
  rp.roll = -std::asin(std::clamp(vy, -1.0, 1.0));
  rp.pitch = std::atan2(vx, nz);
  return rp;
}

}  // namespace mechsim::sim
