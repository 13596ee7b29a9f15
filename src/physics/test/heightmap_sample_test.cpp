// Bilinear sampling of a Heightmap: known values, gradient, slope, normal, clamping, checks.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/heightmap_sample.hpp"

namespace mechsim::physics {
namespace {

Heightmap grid(std::size_t rows, std::size_t cols, double size_x, double size_y,
               std::vector<float> heights) {
  Heightmap map;
  map.rows = rows;
  map.cols = cols;
  map.size_x = size_x;
  map.size_y = size_y;
  map.heights = std::move(heights);
  return map;
}

TEST(HeightmapSample, BilinearKnownValues) {
  // 2 x 2 cell of 2 m x 4 m: SW 0, SE 1, NW 2, NE 4.
  const Heightmap map = grid(2, 2, 2.0, 4.0, {0.f, 1.f, 2.f, 4.f});
  EXPECT_DOUBLE_EQ(height_at(map, -1.0, -2.0), 0.0);
  EXPECT_DOUBLE_EQ(height_at(map, 1.0, -2.0), 1.0);
  EXPECT_DOUBLE_EQ(height_at(map, -1.0, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(height_at(map, 1.0, 2.0), 4.0);
  EXPECT_DOUBLE_EQ(height_at(map, 0.0, 0.0), 1.75);
  // x at 3/4 of the way east, y at 1/4 north: south 0.75, north 3.5 -> 0.75 + 0.25 * 2.75.
  EXPECT_DOUBLE_EQ(height_at(map, 0.5, -1.0), 0.75 + 0.25 * 2.75);
  const auto g = gradient_at(map, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(g[0], (1.0 + 2.0) / 2.0 / 2.0);  // mean east rise 1.5 m over 2 m
  EXPECT_DOUBLE_EQ(g[1], (2.0 + 3.0) / 2.0 / 4.0);  // mean north rise 2.5 m over 4 m
}

TEST(HeightmapSample, OutsideTheFootprintClampsToTheEdge) {
  const Heightmap map = grid(2, 2, 2.0, 2.0, {0.f, 1.f, 2.f, 3.f});
  EXPECT_DOUBLE_EQ(height_at(map, -5.0, -5.0), 0.0);
  EXPECT_DOUBLE_EQ(height_at(map, 5.0, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(height_at(map, NAN, 1.0), 2.0);  // NaN takes the west edge, never crashes
  const auto g = gradient_at(map, 5.0, 0.0);
  EXPECT_DOUBLE_EQ(g[0], 0.0);
  EXPECT_DOUBLE_EQ(g[1], 1.0);
}

TEST(HeightmapSample, PlaneIsReproducedWithItsSlopeAndNormal) {
  const double tilt = 20.0 * std::numbers::pi / 180.0;
  const std::size_t rows = 11, cols = 21;
  Heightmap map = grid(rows, cols, 4.0, 2.0, {});
  // Rising along the direction (cos 30, sin 30) by tan(20 deg).
  const double dx = std::cos(std::numbers::pi / 6), dy = std::sin(std::numbers::pi / 6);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      map.heights.push_back(static_cast<float>(
          std::tan(tilt) * (dx * sample_x(map, c) + dy * sample_y(map, r))));
    }
  }
  for (const auto& [x, y] : {std::pair{0.13, -0.71}, {1.9, 0.99}, {-1.5, 0.2}}) {
    EXPECT_NEAR(height_at(map, x, y), std::tan(tilt) * (dx * x + dy * y), 1e-6);
    EXPECT_NEAR(slope_at(map, x, y), tilt, 1e-6);
    const auto n = normal_at(map, x, y);
    EXPECT_NEAR(n[2], std::cos(tilt), 1e-6);
    EXPECT_NEAR(n[0], -std::sin(tilt) * dx, 1e-6);
    EXPECT_NEAR(n[1], -std::sin(tilt) * dy, 1e-6);
  }
}

TEST(HeightmapSample, ValidationNamesTheProblem) {
  using ::testing::HasSubstr;
  auto message = [](const Heightmap& map) {
    try {
      validate_heightmap(map, "my_map");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_THAT(message(grid(1, 2, 1, 1, {0, 0})), HasSubstr("my_map: grid of 2 x 1 samples"));
  EXPECT_THAT(message(grid(2, 2, 1, 1, {0, 0, 0})), HasSubstr("holds 3 heights for a 2 x 2 grid"));
  EXPECT_THAT(message(grid(2, 2, 0, 1, {0, 0, 0, 0})), HasSubstr("must be positive"));
  EXPECT_THAT(message(grid(2, 2, 1, 1, {0, 0, NAN, 0})), HasSubstr("row 1, column 0 is not finite"));
  EXPECT_EQ(message(grid(2, 2, 1, 1, {0, 0, 0, 0})), "(no error)");
}

}  // namespace
}  // namespace mechsim::physics
