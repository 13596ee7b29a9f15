// The generated mars_yard_2024 world: determinism, size, relief, slope bands, features.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "physics/heightmap_sample.hpp"
#include "physics/mars_yard.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::physics {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

bool same_bytes(const Heightmap& a, const Heightmap& b) {
  return a.rows == b.rows && a.cols == b.cols && a.heights.size() == b.heights.size() &&
         std::memcmp(a.heights.data(), b.heights.data(), a.heights.size() * sizeof(float)) == 0;
}

TEST(MarsYard2024, SameSeedGivesIdenticalBytesAndFeatures) {
  const MarsYard a = generate_mars_yard(kMarsYardDefaultSeed);
  const MarsYard b = generate_mars_yard(kMarsYardDefaultSeed);
  EXPECT_TRUE(same_bytes(a.heightmap, b.heightmap));
  ASSERT_EQ(a.rocks.size(), b.rocks.size());
  for (std::size_t i = 0; i < a.rocks.size(); ++i) {
    EXPECT_EQ(a.rocks[i].x, b.rocks[i].x);
    EXPECT_EQ(a.rocks[i].height, b.rocks[i].height);
  }
  ASSERT_EQ(a.craters.size(), b.craters.size());
  EXPECT_EQ(a.start.y, b.start.y);
  EXPECT_EQ(a.heightmap.source, "mars_yard_2024 seed 2024");
  // The RNG overload with a freshly seeded engine is the same world.
  std::mt19937_64 rng(kMarsYardDefaultSeed);
  EXPECT_TRUE(same_bytes(generate_mars_yard(rng).heightmap, a.heightmap));
}

TEST(MarsYard2024, DifferentSeedsDiffer) {
  const MarsYard a = generate_mars_yard(1);
  const MarsYard b = generate_mars_yard(2);
  ASSERT_EQ(a.heightmap.heights.size(), b.heightmap.heights.size());
  EXPECT_FALSE(same_bytes(a.heightmap, b.heightmap));
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.heightmap.heights.size(); ++i) {
    differing += a.heightmap.heights[i] != b.heightmap.heights[i] ? 1 : 0;
  }
  EXPECT_GT(differing, a.heightmap.heights.size() / 2);
  EXPECT_NE(a.craters.front().x, b.craters.front().x);
}

TEST(MarsYard2024, SizeResolutionAndRelief) {
  const MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
  const Heightmap& map = yard.heightmap;
  EXPECT_NEAR(yard.usable.area(), 900.0, 1e-9);
  EXPECT_NEAR(yard.usable.x_max - yard.usable.x_min, 37.5, 1e-9);
  EXPECT_NEAR(yard.usable.y_max - yard.usable.y_min, 24.0, 1e-9);
  EXPECT_NEAR(map.size_x, 40.5, 1e-9);
  EXPECT_NEAR(map.size_y, 27.0, 1e-9);
  EXPECT_EQ(map.cols, 811u);
  EXPECT_EQ(map.rows, 541u);
  EXPECT_NEAR(map.cell_x(), 0.05, 1e-12);
  EXPECT_NO_THROW(validate_heightmap(map));
  const TerrainStats s = compute_terrain_stats(map, yard.usable);
  EXPECT_NEAR(s.usable_area, 900.0, 1e-9);
  EXPECT_GE(s.relief, 2.0);
  EXPECT_LE(s.relief, 5.0);
  const auto [lo, hi] = std::minmax_element(map.heights.begin(), map.heights.end());
  EXPECT_EQ(*lo, 0.0f);
  EXPECT_LE(*hi, 5.0f);
}

class MarsYardSeeds : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(MarsYardSeeds, SlopeStatisticsInsideThe2021And2022Bands) {
  const MarsYard yard = generate_mars_yard(GetParam());
  const TerrainStats s = compute_terrain_stats(yard.heightmap, yard.usable);
  EXPECT_GE(s.slope_median_deg, 10.0);
  EXPECT_LE(s.slope_median_deg, 13.0);
  EXPECT_GE(s.slope_p90_deg, 27.0);
  EXPECT_LE(s.slope_p90_deg, 32.0);
  EXPECT_GE(s.steep_share, 0.07);
  EXPECT_LE(s.steep_share, 0.14);
}

INSTANTIATE_TEST_SUITE_P(DefaultAndOthers, MarsYardSeeds,
                         ::testing::Values(kMarsYardDefaultSeed, 1, 7, 42, 31337));

bool inside(const Region& r, double x, double y, double reach) {
  return x - reach >= r.x_min && x + reach <= r.x_max && y - reach >= r.y_min && y + reach <= r.y_max;
}

TEST(MarsYard2024, FeaturesAreListedInsideTheYardAndShapeTheGround) {
  const MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
  const Heightmap& map = yard.heightmap;
  const MarsYardParams defaults;
  EXPECT_EQ(yard.craters.size(), static_cast<std::size_t>(defaults.craters));
  EXPECT_GE(yard.mounds.size(), 2u);
  EXPECT_GT(yard.mounds.front().caldera_radius, 0.0);
  std::size_t large = 0, medium = 0, small = 0;
  for (const Rock& r : yard.rocks) {
    EXPECT_TRUE(inside(yard.usable, r.x, r.y, 0.5 * r.length));
    (r.size == RockSize::kLarge ? large : r.size == RockSize::kMedium ? medium : small)++;
    // The rock stands out of the ground around it.
    const double c = std::cos(r.yaw), s = std::sin(r.yaw);
    const double beside = 0.5 * (height_at(map, r.x + r.length * c, r.y + r.length * s) +
                                 height_at(map, r.x - r.length * c, r.y - r.length * s));
    if (r.size == RockSize::kLarge) {
      EXPECT_GT(height_at(map, r.x, r.y), beside + 0.5 * r.height);
    }
  }
  EXPECT_EQ(large, static_cast<std::size_t>(defaults.large_rocks));
  EXPECT_GE(medium, static_cast<std::size_t>(defaults.medium_rocks) * 9 / 10);
  EXPECT_GE(small, static_cast<std::size_t>(defaults.small_rocks) * 9 / 10);
  for (const Crater& c : yard.craters) {
    EXPECT_TRUE(inside(yard.usable, c.x, c.y, c.radius));
    double rim = 0.0;
    for (int k = 0; k < 8; ++k) {
      rim += height_at(map, c.x + c.radius * std::cos(k * std::numbers::pi / 4),
                       c.y + c.radius * std::sin(k * std::numbers::pi / 4)) / 8.0;
    }
    EXPECT_LT(height_at(map, c.x, c.y), rim - 0.5 * (c.depth + c.rim_height)) << "crater at " << c.x << ", " << c.y;
  }
  for (const Mound& m : yard.mounds) {
    EXPECT_TRUE(inside(yard.usable, m.x, m.y, 0.0));
    const double foot = 0.5 * (height_at(map, m.x + m.radius, m.y) + height_at(map, m.x - m.radius, m.y));
    const double shoulder = height_at(map, m.x + 0.3 * m.radius, m.y);
    EXPECT_GT(shoulder, foot + 0.4 * m.height) << "mound at " << m.x << ", " << m.y;
  }
  // Canyon bed below both rims, halfway along.
  const auto& mid = yard.canyon.centre[yard.canyon.centre.size() / 2];
  const double half = 0.5 * yard.canyon.top_width;
  EXPECT_LT(height_at(map, mid[0], mid[1]), height_at(map, mid[0], mid[1] - half) - 0.5 * yard.canyon.depth);
  EXPECT_LT(height_at(map, mid[0], mid[1]), height_at(map, mid[0], mid[1] + half) - 0.5 * yard.canyon.depth);
  EXPECT_GT(yard.dunes.height, 0.1);
  EXPECT_TRUE(inside(yard.usable, yard.dunes.x, yard.dunes.y, 0.0));
}

TEST(MarsYard2024, StartPadIsLevelNearTheWestEnd) {
  for (std::uint64_t seed : {kMarsYardDefaultSeed, std::uint64_t{5}}) {
    const MarsYard yard = generate_mars_yard(seed);
    const StartArea& start = yard.start;
    EXPECT_LT(start.x, yard.usable.x_min + 4.0);
    EXPECT_TRUE(inside(yard.usable, start.x, start.y, start.radius));
    EXPECT_NEAR(height_at(yard.heightmap, start.x, start.y), start.z, 1e-6);
    for (double r : {0.0, 0.5, 1.0, 0.9 * start.radius}) {
      for (int k = 0; k < 8; ++k) {
        const double x = start.x + r * std::cos(k * std::numbers::pi / 4);
        const double y = start.y + r * std::sin(k * std::numbers::pi / 4);
        EXPECT_LT(slope_at(yard.heightmap, x, y), 2.0 * kDeg) << "seed " << seed << " at " << x << ", " << y;
        EXPECT_NEAR(height_at(yard.heightmap, x, y), start.z, 0.01);
      }
    }
    for (const Rock& rock : yard.rocks) {
      EXPECT_GT(std::hypot(rock.x - start.x, rock.y - start.y), start.radius + 0.5 * rock.length);
    }
  }
}

TEST(MarsYard2024, MarginLevelsOffWithoutACliff) {
  const MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
  const Heightmap& map = yard.heightmap;
  // The outermost 0.3 m all round: no wall where the yard meets the margin.
  double worst = 0.0;
  for (std::size_t r = 1; r + 1 < map.rows; ++r) {
    for (std::size_t c = 1; c + 1 < map.cols; ++c) {
      const double x = sample_x(map, c), y = sample_y(map, r);
      if (std::abs(x) < 0.5 * map.size_x - 0.3 && std::abs(y) < 0.5 * map.size_y - 0.3) continue;
      worst = std::max(worst, slope_at(map, x, y));
    }
  }
  EXPECT_LT(worst, 25.0 * kDeg);  // the plateau scarp (<= ~22 deg) runs out into the margin
}

TEST(MarsYard2024, BadParametersAreRejected) {
  MarsYardParams p;
  p.cell = 0.0;
  EXPECT_THROW(generate_mars_yard(1, p), std::invalid_argument);
  p = MarsYardParams{};
  p.usable_x = -3.0;
  EXPECT_THROW(generate_mars_yard(1, p), std::invalid_argument);
  p = MarsYardParams{};
  p.craters = -1;
  EXPECT_THROW(generate_mars_yard(1, p), std::invalid_argument);
}

}  // namespace
}  // namespace mechsim::physics
