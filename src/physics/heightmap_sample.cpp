#include "physics/heightmap_sample.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mechsim::physics {

void validate_heightmap(const Heightmap& map, const std::string& what) {
  auto fail = [&](const std::string& msg) { throw std::invalid_argument(what + ": " + msg); };
  if (map.rows < 2 || map.cols < 2) {
    fail("grid of " + std::to_string(map.cols) + " x " + std::to_string(map.rows) +
         " samples; a heightmap needs at least 2 x 2");
  }
  if (map.heights.size() != map.rows * map.cols) {
    fail("holds " + std::to_string(map.heights.size()) + " heights for a " +
         std::to_string(map.cols) + " x " + std::to_string(map.rows) + " grid");
  }
  if (!(std::isfinite(map.size_x) && map.size_x > 0.0 && std::isfinite(map.size_y) &&
        map.size_y > 0.0)) {
    fail("footprint " + std::to_string(map.size_x) + " m x " + std::to_string(map.size_y) +
         " m must be positive and finite");
  }
  for (std::size_t i = 0; i < map.heights.size(); ++i) {
    if (!std::isfinite(map.heights[i])) {
      fail("height at row " + std::to_string(i / map.cols) + ", column " +
           std::to_string(i % map.cols) + " is not finite");
    }
  }
}

namespace {

// Cell index and fraction along one axis; clamped marks a coordinate outside the footprint.
struct Axis {
  std::size_t i0;
  double t;
  bool clamped;
};

Axis locate(double coord, double size, std::size_t n) {
  const double cell = size / static_cast<double>(n - 1);
  double u = (coord + 0.5 * size) / cell;
  bool clamped = false;
  const double last = static_cast<double>(n - 1);
  if (!(u > 0.0)) {  // also catches NaN
    u = 0.0;
    clamped = true;
  } else if (u >= last) {
    clamped = u > last;
    u = last;
  }
  auto i0 = static_cast<std::size_t>(u);
  if (i0 >= n - 1) i0 = n - 2;
  return {i0, u - static_cast<double>(i0), clamped};
}

}  // namespace

double height_at(const Heightmap& map, double x, double y) {
  const Axis ax = locate(x, map.size_x, map.cols);
  const Axis ay = locate(y, map.size_y, map.rows);
  const double z00 = map.at(ay.i0, ax.i0), z01 = map.at(ay.i0, ax.i0 + 1);
  const double z10 = map.at(ay.i0 + 1, ax.i0), z11 = map.at(ay.i0 + 1, ax.i0 + 1);
  const double south = z00 + (z01 - z00) * ax.t;
  const double north = z10 + (z11 - z10) * ax.t;
  return south + (north - south) * ay.t;
}

std::array<double, 2> gradient_at(const Heightmap& map, double x, double y) {
  const Axis ax = locate(x, map.size_x, map.cols);
  const Axis ay = locate(y, map.size_y, map.rows);
  const double z00 = map.at(ay.i0, ax.i0), z01 = map.at(ay.i0, ax.i0 + 1);
  const double z10 = map.at(ay.i0 + 1, ax.i0), z11 = map.at(ay.i0 + 1, ax.i0 + 1);
  double gx = ((z01 - z00) * (1.0 - ay.t) + (z11 - z10) * ay.t) / map.cell_x();
  double gy = ((z10 - z00) * (1.0 - ax.t) + (z11 - z01) * ax.t) / map.cell_y();
  if (ax.clamped) gx = 0.0;
  if (ay.clamped) gy = 0.0;
  return {gx, gy};
}

double slope_at(const Heightmap& map, double x, double y) {
  const auto g = gradient_at(map, x, y);
  return std::atan(std::hypot(g[0], g[1]));
}

std::array<double, 3> normal_at(const Heightmap& map, double x, double y) {
  const auto g = gradient_at(map, x, y);
  const double inv = 1.0 / std::sqrt(1.0 + g[0] * g[0] + g[1] * g[1]);
  return {-g[0] * inv, -g[1] * inv, inv};
}

}  // namespace mechsim::physics
