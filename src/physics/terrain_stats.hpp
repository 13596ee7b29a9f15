#pragma once
// Terrain statistics of a Heightmap: size, relief and the slope distribution.
//
// Slope is measured per grid sample from the grid gradient: central differences
// (z[i+1] - z[i-1]) / (2 h) inside, one-sided differences on the border; slope =
// atan(|gradient|). Each sample stands for one cell of area cell_x * cell_y, so shares of
// samples are shares of area. Statistics cover the grid samples inside a region (the whole
// footprint by default, the usable driving area for a yard with a margin); slope statistics
// take those with central differences, i.e. all but the grid's outer ring.

#include <cstddef>
#include <optional>
#include <vector>

#include "physics/heightmap.hpp"

namespace mechsim::physics {

// Axis-aligned rectangle in the world frame (m).
struct Region {
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
  double area() const { return (x_max - x_min) * (y_max - y_min); }
  bool contains(double x, double y) const {
    return x >= x_min && x <= x_max && y >= y_min && y <= y_max;
  }
};

struct TerrainStats {
  std::size_t rows = 0, cols = 0;        // grid samples along y and x
  double size_x = 0.0, size_y = 0.0;     // footprint (m)
  double cell_x = 0.0, cell_y = 0.0;     // sample spacing (m)
  Region region;                         // where the statistics below were taken
  double usable_area = 0.0;              // area of the region (m^2)
  std::size_t samples = 0;               // interior grid samples inside the region
  double z_min = 0.0, z_max = 0.0;       // lowest and highest height in the region (m), all samples
  double relief = 0.0;                   // z_max - z_min (m)
  double z_mean = 0.0;                   // mean height (m)
  double slope_mean_deg = 0.0;           // slope statistics (deg)
  double slope_median_deg = 0.0;
  double slope_p90_deg = 0.0;            // 90th percentile
  double slope_p95_deg = 0.0;
  double slope_max_deg = 0.0;
  double steep_threshold_deg = 30.0;     // threshold used for steep_share
  double steep_share = 0.0;              // share of the region's area steeper than the threshold (0..1)
};

// Slope (deg) of every grid sample, row-major like Heightmap::heights. Map must be valid.
std::vector<float> slope_grid_deg(const Heightmap& map);

// Statistics over `region` (default: the whole footprint). Throws std::invalid_argument when
// the map is invalid or the region holds no sample.
TerrainStats compute_terrain_stats(const Heightmap& map,
                                   const std::optional<Region>& region = std::nullopt,
                                   double steep_threshold_deg = 30.0);

// Value at quantile q (0..1) of `values`, linear between closest ranks; reorders `values`.
// Throws std::invalid_argument when empty.
double quantile(std::vector<float>& values, double q);

}  // namespace mechsim::physics
