// The Mars Yard generator's fast paths against the sample-by-sample functions they replace: the
// generated world must not change by a bit (its figures and every report over it depend on it).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "physics/mars_yard_shapes.hpp"

namespace mechsim::physics::detail {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(MarsYardShapes, FractalNoiseRowsAreTheSamplesBitForBit) {
  std::mt19937_64 rng(7);
  const double size_x = 43.0, size_y = 27.0;
  const FractalNoise noise(rng, 6.4, 0.2, 0.8, size_x, size_y);
  // Grid points, points off the grid, and points beyond the rectangle (clamped to its lattice).
  std::vector<double> xs;
  for (double x = -0.5 * size_x - 1.0; x <= 0.5 * size_x + 1.0; x += 0.0537) xs.push_back(x);
  const FractalNoise::Columns columns = noise.columns(xs);
  std::vector<double> row(xs.size());
  std::size_t compared = 0, nonzero = 0;
  for (double y = -0.5 * size_y - 1.0; y <= 0.5 * size_y + 1.0; y += 0.731) {
    noise.row(columns, y, row);
    for (std::size_t c = 0; c < xs.size(); ++c) {
      const double expected = noise(xs[c], y);
      ASSERT_TRUE(same_bits(row[c], expected)) << "x " << xs[c] << " y " << y << ": " << row[c] << " vs " << expected;
      ++compared;
      nonzero += expected != 0.0;
    }
  }
  EXPECT_GT(compared, 20000u);
  EXPECT_GT(nonzero, compared / 2);  // the noise is not flat: the comparison means something
}

TEST(MarsYardShapes, PolylineNearestFindsTheSameHitsAsTheFullSearch) {
  // A winding line with a zero-length segment and a point where two segments are equally close.
  const std::vector<std::array<double, 2>> line{{-20.0, 0.0}, {-10.0, 4.0}, {-10.0, 4.0}, {0.0, -3.0},
                                                {5.0, 5.0},   {12.0, 5.0},  {20.0, -6.0}};
  const PolylineNearest nearest(line);
  std::size_t compared = 0;
  for (double y = -15.0; y <= 15.0; y += 0.173) {
    for (double x = -25.0; x <= 25.0; x += 0.119) {
      const PolylineHit fast = nearest(x, y), full = closest_on_polyline(line, x, y);
      ASSERT_TRUE(same_bits(fast.distance, full.distance)) << x << ", " << y;
      ASSERT_TRUE(same_bits(fast.arc, full.arc)) << x << ", " << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 70000u);
  // Equidistant from the two halves of a V: the first segment's hit, as closest_on_polyline.
  const std::vector<std::array<double, 2>> vee{{-1.0, 1.0}, {0.0, 0.0}, {1.0, 1.0}};
  const PolylineHit hit = PolylineNearest(vee)(0.0, 1.0);
  EXPECT_TRUE(same_bits(hit.arc, closest_on_polyline(vee, 0.0, 1.0).arc));
  EXPECT_LT(hit.arc, std::sqrt(2.0));
}

}  // namespace
}  // namespace mechsim::physics::detail
