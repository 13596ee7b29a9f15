#include "physics/terrain_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "physics/heightmap_sample.hpp"

namespace mechsim::physics {

std::vector<float> slope_grid_deg(const Heightmap& map) {
  const std::size_t rows = map.rows, cols = map.cols;
  const double hx = map.cell_x(), hy = map.cell_y();
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::vector<float> slopes(rows * cols);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t r0 = r == 0 ? 0 : r - 1, r1 = r + 1 == rows ? r : r + 1;
    const double dy = static_cast<double>(r1 - r0) * hy;
    for (std::size_t c = 0; c < cols; ++c) {
      const std::size_t c0 = c == 0 ? 0 : c - 1, c1 = c + 1 == cols ? c : c + 1;
      const double gx = (map.at(r, c1) - map.at(r, c0)) / (static_cast<double>(c1 - c0) * hx);
      const double gy = (map.at(r1, c) - map.at(r0, c)) / dy;
      slopes[r * cols + c] = static_cast<float>(std::atan(std::hypot(gx, gy)) * kDeg);
    }
  }
  return slopes;
}

double quantile(std::vector<float>& values, double q) {
  if (values.empty()) throw std::invalid_argument("quantile of no values");
  const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(pos);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(lo), values.end());
  const double a = values[lo];
  if (lo + 1 >= values.size()) return a;
  // The next rank is the smallest value above position lo.
  const double b = *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(lo) + 1, values.end());
  return a + (b - a) * (pos - static_cast<double>(lo));
}

TerrainStats compute_terrain_stats(const Heightmap& map, const std::optional<Region>& region,
                                   double steep_threshold_deg) {
  validate_heightmap(map, map.source.empty() ? "heightmap" : map.source);
  TerrainStats s;
  s.rows = map.rows;
  s.cols = map.cols;
  s.size_x = map.size_x;
  s.size_y = map.size_y;
  s.cell_x = map.cell_x();
  s.cell_y = map.cell_y();
  s.region = region.value_or(
      Region{-0.5 * map.size_x, 0.5 * map.size_x, -0.5 * map.size_y, 0.5 * map.size_y});
  s.usable_area = s.region.area();
  s.steep_threshold_deg = steep_threshold_deg;

  const std::vector<float> all = slope_grid_deg(map);
  std::vector<float> slopes;
  slopes.reserve(all.size());
  double z_sum = 0.0, slope_sum = 0.0;
  std::size_t steep = 0;
  s.z_min = INFINITY;
  s.z_max = -INFINITY;
  // A small tolerance keeps samples lying on the region's edge despite rounding.
  const double tol = 1e-9 * std::max(map.size_x, map.size_y);
  // Heights over every sample in the region; slopes leave out the grid's outer ring, which
  // has one-sided differences only.
  std::size_t z_count = 0;
  for (std::size_t r = 0; r < map.rows; ++r) {
    const double y = sample_y(map, r);
    if (y < s.region.y_min - tol || y > s.region.y_max + tol) continue;
    const bool ring_row = r == 0 || r + 1 == map.rows;
    for (std::size_t c = 0; c < map.cols; ++c) {
      const double x = sample_x(map, c);
      if (x < s.region.x_min - tol || x > s.region.x_max + tol) continue;
      const double z = map.at(r, c);
      s.z_min = std::min(s.z_min, z);
      s.z_max = std::max(s.z_max, z);
      z_sum += z;
      ++z_count;
      if (ring_row || c == 0 || c + 1 == map.cols) continue;
      const float slope = all[r * map.cols + c];
      slope_sum += slope;
      if (slope > steep_threshold_deg) ++steep;
      slopes.push_back(slope);
    }
  }
  if (slopes.empty()) {
    throw std::invalid_argument(
        "terrain statistics: the region holds no interior grid sample (a grid needs at least 3 x 3)");
  }
  s.samples = slopes.size();
  const auto n = static_cast<double>(s.samples);
  s.relief = s.z_max - s.z_min;
  s.z_mean = z_sum / static_cast<double>(z_count);
  s.slope_mean_deg = slope_sum / n;
  s.steep_share = static_cast<double>(steep) / n;
  s.slope_max_deg = *std::max_element(slopes.begin(), slopes.end());
  s.slope_median_deg = quantile(slopes, 0.5);
  s.slope_p90_deg = quantile(slopes, 0.9);
  s.slope_p95_deg = quantile(slopes, 0.95);
  return s;
}

}  // namespace mechsim::physics
