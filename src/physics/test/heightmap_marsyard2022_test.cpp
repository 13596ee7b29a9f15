// The 2022 European Rover Challenge Mars Yard elevation model (../shared/terrain): loads with
// the dimensions its TIFF tags and README give, and our slope statistics match the README's.

#include <gtest/gtest.h>
#include <tiffio.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "physics/heightmap_io.hpp"
#include "physics/heightmap_sample.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::physics {
namespace {

const std::filesystem::path kModel =
    std::filesystem::path(MECHSIM_SHARED_DIR) / "terrain" / "marsyard2022_heightmap.tif";

class MarsYard2022 : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kModel)) {
      GTEST_SKIP() << "shared terrain data absent: " << kModel;
    }
  }
};

TEST_F(MarsYard2022, LoadsWithTheDocumentedGridFootprintAndRelief) {
  const Heightmap map = load_heightmap(kModel);
  EXPECT_EQ(map.rows, 257u);
  EXPECT_EQ(map.cols, 257u);
  // Pixel scale 50/257 m (tag 33550) over 257 pixel-is-area samples: 50 m.
  EXPECT_NEAR(map.size_x, 50.0, 1e-3);
  EXPECT_NEAR(map.size_y, 50.0, 1e-3);
  EXPECT_NEAR(map.cell_x(), 50.0 / 256.0, 1e-5);
  const auto [lo, hi] = std::minmax_element(map.heights.begin(), map.heights.end());
  EXPECT_NEAR(*lo, 0.0144, 5e-4);
  EXPECT_NEAR(*hi, 4.8208, 5e-4);
}

// Reads the first sample of image rows 0 and 256 straight from the file's strips (uncompressed
// little-endian doubles) and checks that they land on the north and south edges.
TEST_F(MarsYard2022, ImageRowZeroIsTheNorthEdge) {
  TIFF* tif = TIFFOpen(kModel.c_str(), "r");
  ASSERT_NE(tif, nullptr);
  std::uint64_t* offsets = nullptr;
  ASSERT_EQ(TIFFGetField(tif, TIFFTAG_STRIPOFFSETS, &offsets), 1);
  std::uint32_t rows_per_strip = 0;
  TIFFGetField(tif, TIFFTAG_ROWSPERSTRIP, &rows_per_strip);
  const std::uint64_t first = offsets[0];
  const std::uint32_t last_strip = 256 / rows_per_strip;
  const std::uint64_t last = offsets[last_strip] + (256 % rows_per_strip) * 257 * 8;
  TIFFClose(tif);
  std::ifstream in(kModel, std::ios::binary);
  auto read_at = [&](std::uint64_t offset) {
    char bytes[8];
    in.seekg(static_cast<std::streamoff>(offset));
    in.read(bytes, 8);
    double v;
    std::memcpy(&v, bytes, 8);
    return v;
  };
  const double north_west = read_at(first), south_west = read_at(last);
  const Heightmap map = load_heightmap(kModel);
  EXPECT_FLOAT_EQ(map.at(256, 0), static_cast<float>(north_west));
  EXPECT_FLOAT_EQ(map.at(0, 0), static_cast<float>(south_west));
  EXPECT_NEAR(height_at(map, -25.0, 25.0), north_west, 1e-6);
  EXPECT_NEAR(height_at(map, -25.0, -25.0), south_west, 1e-6);
}

// README: central differences give median 10.7 deg, p90 26.8, p95 32.7, 7.2 % above 30 deg.
// Our statistics take the 255 x 255 interior samples at 50/256 m spacing.
TEST_F(MarsYard2022, SlopeStatisticsMatchTheIndependentMeasurement) {
  const TerrainStats s = compute_terrain_stats(load_heightmap(kModel));
  EXPECT_EQ(s.samples, 255u * 255u);
  EXPECT_NEAR(s.usable_area, 2500.0, 0.1);
  EXPECT_NEAR(s.relief, 4.8208 - 0.0144, 1e-3);
  EXPECT_NEAR(s.slope_median_deg, 10.7, 0.1);
  EXPECT_NEAR(s.slope_p90_deg, 26.8, 0.15);
  EXPECT_NEAR(s.slope_p95_deg, 32.7, 0.1);
  EXPECT_NEAR(s.steep_share, 0.072, 0.001);
}

}  // namespace
}  // namespace mechsim::physics
