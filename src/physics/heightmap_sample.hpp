#pragma once
// Sampling a Heightmap as a continuous surface: bilinear height, its gradient, slope and
// normal. World frame W: x east, y north, z up (m); the footprint is centred on the origin.
// These run in hot paths (contact queries, spawning): they allocate nothing and throw nothing.

#include <array>
#include <cstddef>
#include <string>

#include "physics/heightmap.hpp"

namespace mechsim::physics {

// Throws std::invalid_argument naming what is wrong (grid < 2x2, heights.size() != rows*cols,
// non-positive or non-finite footprint, non-finite heights). `what` prefixes the message.
void validate_heightmap(const Heightmap& map, const std::string& what = "heightmap");

// World x (m) of column `col` and world y (m) of row `row`.
inline double sample_x(const Heightmap& map, std::size_t col) {
  return -0.5 * map.size_x + static_cast<double>(col) * map.cell_x();
}
inline double sample_y(const Heightmap& map, std::size_t row) {
  return -0.5 * map.size_y + static_cast<double>(row) * map.cell_y();
}

// Height (m) of the bilinear surface at world (x, y) (m). Points outside the footprint are
// clamped to its edge, so the surface continues flat-sided beyond it.
double height_at(const Heightmap& map, double x, double y);

// Gradient (dz/dx, dz/dy) (dimensionless) of the bilinear surface at (x, y); zero across the
// clamped directions outside the footprint.
std::array<double, 2> gradient_at(const Heightmap& map, double x, double y);

// Slope (rad, 0 = level) of the bilinear surface at (x, y): atan(|gradient|).
double slope_at(const Heightmap& map, double x, double y);

// Upward unit normal (nx, ny, nz) of the bilinear surface at (x, y), nz > 0.
std::array<double, 3> normal_at(const Heightmap& map, double x, double y);

}  // namespace mechsim::physics
