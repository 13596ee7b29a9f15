// Terrain statistics on analytic surfaces.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "physics/heightmap_sample.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::physics {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Heightmap surface(std::size_t rows, std::size_t cols, double size_x, double size_y,
                  const std::function<double(double, double)>& z) {
  Heightmap map;
  map.rows = rows;
  map.cols = cols;
  map.size_x = size_x;
  map.size_y = size_y;
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      map.heights.push_back(static_cast<float>(z(sample_x(map, c), sample_y(map, r))));
    }
  }
  return map;
}

TEST(TerrainStats, PlaneTiltedTwentyDegreesHasAllSlopesTwenty) {
  const double k = std::tan(20.0 * kDeg);
  // Tilted along a diagonal so both gradient components matter.
  const Heightmap map = surface(81, 121, 6.0, 4.0, [&](double x, double y) {
    return k * (0.6 * x + 0.8 * y) + 1.0;
  });
  const TerrainStats s = compute_terrain_stats(map);
  EXPECT_NEAR(s.slope_median_deg, 20.0, 1e-3);
  EXPECT_NEAR(s.slope_p90_deg, 20.0, 1e-3);
  EXPECT_NEAR(s.slope_max_deg, 20.0, 1e-3);
  EXPECT_NEAR(s.slope_mean_deg, 20.0, 1e-3);
  EXPECT_EQ(s.steep_share, 0.0);
  EXPECT_EQ(s.samples, 79u * 119u);
  EXPECT_NEAR(s.usable_area, 24.0, 1e-12);
  EXPECT_NEAR(s.relief, k * (0.6 * 6.0 + 0.8 * 4.0), 1e-4);
  EXPECT_NEAR(s.z_mean, 1.0, 1e-4);
}

TEST(TerrainStats, ConeHasItsFlankSlopeAlmostEverywhere) {
  // Cone of 35 deg flanks rising to a peak at the origin, inside a 10 m square.
  const double k = std::tan(35.0 * kDeg);
  const Heightmap map = surface(201, 201, 10.0, 10.0, [&](double x, double y) {
    return 3.0 - k * std::hypot(x, y);
  });
  const TerrainStats s = compute_terrain_stats(map);
  EXPECT_NEAR(s.slope_median_deg, 35.0, 1e-3);
  EXPECT_NEAR(s.slope_p90_deg, 35.0, 1e-3);
  // Only the samples around the apex see a flatter, averaged gradient.
  EXPECT_GT(s.steep_share, 0.999);
  EXPECT_NEAR(s.z_max, 3.0, 1e-6);
}

TEST(TerrainStats, MixedSurfaceSharesFollowTheArea) {
  // West half flat, east half rising at 40 deg: half the area is steeper than 30 deg.
  const double k = std::tan(40.0 * kDeg);
  const Heightmap map = surface(41, 402, 20.1, 2.0, [&](double x, double) {
    return x > 0.0 ? k * x : 0.0;
  });
  const TerrainStats s = compute_terrain_stats(map);
  EXPECT_NEAR(s.steep_share, 0.5, 0.01);
  EXPECT_NEAR(s.slope_p90_deg, 40.0, 1e-3);
  // A region over the east half only.
  const TerrainStats east = compute_terrain_stats(map, Region{1.0, 10.0, -1.0, 1.0});
  EXPECT_NEAR(east.slope_median_deg, 40.0, 1e-3);
  EXPECT_NEAR(east.steep_share, 1.0, 1e-12);
  EXPECT_NEAR(east.usable_area, 18.0, 1e-12);
  std::size_t first = 0;
  while (sample_x(map, first) < 1.0) ++first;
  EXPECT_NEAR(east.z_min, k * sample_x(map, first), 1e-4);
}

TEST(TerrainStats, EmptyRegionIsAnError) {
  const Heightmap map = surface(5, 5, 1.0, 1.0, [](double, double) { return 0.0; });
  EXPECT_THROW(compute_terrain_stats(map, Region{2.0, 3.0, 2.0, 3.0}), std::invalid_argument);
}

TEST(TerrainStats, QuantileInterpolatesBetweenRanks) {
  std::vector<float> v = {4, 1, 3, 2, 5};
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.9), 4.6);
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 5.0);
  std::vector<float> none;
  EXPECT_THROW(quantile(none, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace mechsim::physics
