// Loading heightmap images: round trips through images written with libpng/libtiff directly,
// and the error messages for bad input.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "heightmap_image_util.hpp"
#include "physics/heightmap_io.hpp"

namespace mechsim::physics {
namespace {

using ::testing::HasSubstr;
using test::TiffSpec;

// Option sets (designated initializers that skip members trip -Wmissing-field-initializers).
HeightmapOptions footprint(double size_x, double size_y) {
  HeightmapOptions o;
  o.size_x = size_x;
  o.size_y = size_y;
  return o;
}
HeightmapOptions with_range(HeightmapOptions o, double z_min, double z_max) {
  o.z_min = z_min;
  o.z_max = z_max;
  return o;
}
HeightmapOptions full(double size_x, double size_y, double z_min, double z_max) {
  return with_range(footprint(size_x, size_y), z_min, z_max);
}
TiffSpec tiff(std::uint32_t width, std::uint32_t height, std::uint16_t bits = 32,
              std::uint16_t sample_format = 3) {
  TiffSpec spec;
  spec.width = width;
  spec.height = height;
  spec.bits = bits;
  spec.sample_format = sample_format;
  return spec;
}

// Expects load_heightmap to throw a HeightmapError whose message contains the file and `part`.
void expect_error(const std::filesystem::path& path, const HeightmapOptions& options,
                  const std::string& part) {
  try {
    load_heightmap(path, options);
    ADD_FAILURE() << "loading " << path << " did not fail (expected: " << part << ")";
  } catch (const HeightmapError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string()));
    EXPECT_THAT(e.what(), HasSubstr(part));
  }
}

TEST(HeightmapIo, EightBitPngMapsValuesToRangeAndFlipsRows) {
  const auto dir = test::temp_dir("png8");
  // 3 wide, 2 high; image row 0 is the north edge.
  test::write_gray_png(dir / "h.png", 3, 2, 8, {0, 51, 255, 102, 153, 204});
  const Heightmap map = load_heightmap(dir / "h.png", full(4.0, 2.0, -1.0, 4.0));
  ASSERT_EQ(map.cols, 3u);
  ASSERT_EQ(map.rows, 2u);
  EXPECT_DOUBLE_EQ(map.size_x, 4.0);
  EXPECT_DOUBLE_EQ(map.size_y, 2.0);
  // z = -1 + v / 255 * 5; Heightmap row 0 (south) is image row 1.
  EXPECT_FLOAT_EQ(map.at(0, 0), -1.0f + 102.0f / 51.0f);
  EXPECT_FLOAT_EQ(map.at(0, 2), -1.0f + 204.0f / 51.0f);
  EXPECT_FLOAT_EQ(map.at(1, 0), -1.0f);
  EXPECT_FLOAT_EQ(map.at(1, 1), 0.0f);
  EXPECT_FLOAT_EQ(map.at(1, 2), 4.0f);
  EXPECT_EQ(map.source, (dir / "h.png").string());
}

TEST(HeightmapIo, SixteenBitPngKeepsFullPrecision) {
  const auto dir = test::temp_dir("png16");
  std::vector<std::uint16_t> values;
  for (std::uint16_t i = 0; i < 16; ++i) values.push_back(static_cast<std::uint16_t>(i * 4369 + (i % 3)));
  test::write_gray_png(dir / "h.png", 4, 4, 16, values);
  const Heightmap map =
      load_heightmap(dir / "h.png", full(1.0, 1.0, 0.0, 65.535));
  for (std::size_t image_row = 0; image_row < 4; ++image_row) {
    for (std::size_t c = 0; c < 4; ++c) {
      const double expected = values[image_row * 4 + c] * 0.001;
      EXPECT_NEAR(map.at(3 - image_row, c), expected, 1e-5) << image_row << "," << c;
    }
  }
}

TEST(HeightmapIo, FloatTiffHoldsAbsoluteHeightsAndFootprint) {
  const auto dir = test::temp_dir("tiff32");
  std::vector<double> values = {0.5, -1.25, 3.0, 7.5, 0.0, 2.25};
  TiffSpec spec = tiff(3, 2, 32, 3);
  spec.pixel_scale = std::vector<double>{2.0, 1.5, 0.0};
  test::write_tiff(dir / "h.tif", spec, values);
  const Heightmap map = load_heightmap(dir / "h.tif");
  ASSERT_EQ(map.cols, 3u);
  ASSERT_EQ(map.rows, 2u);
  EXPECT_DOUBLE_EQ(map.size_x, 6.0);  // pixel-is-area: 3 samples * 2 m
  EXPECT_DOUBLE_EQ(map.size_y, 3.0);
  EXPECT_FLOAT_EQ(map.at(1, 0), 0.5f);
  EXPECT_FLOAT_EQ(map.at(1, 1), -1.25f);
  EXPECT_FLOAT_EQ(map.at(0, 0), 7.5f);
  EXPECT_FLOAT_EQ(map.at(0, 2), 2.25f);
}

TEST(HeightmapIo, PixelIsPointTiffSpansSamplesMinusOne) {
  const auto dir = test::temp_dir("tiffpoint");
  TiffSpec spec = tiff(5, 3, 64, 3);
  spec.pixel_scale = std::vector<double>{0.5, 0.25, 0.0};
  spec.pixel_is_point = true;
  test::write_tiff(dir / "h.tif", spec, std::vector<double>(15, 1.0));
  const Heightmap map = load_heightmap(dir / "h.tif");
  EXPECT_DOUBLE_EQ(map.size_x, 2.0);
  EXPECT_DOUBLE_EQ(map.size_y, 0.5);
}

TEST(HeightmapIo, OptionsOverrideTheFileFootprint) {
  const auto dir = test::temp_dir("override");
  TiffSpec spec = tiff(2, 2, 32, 3);
  spec.pixel_scale = std::vector<double>{1.0, 1.0, 0.0};
  test::write_tiff(dir / "h.tif", spec, {1, 2, 3, 4});
  const Heightmap map = load_heightmap(dir / "h.tif", footprint(10.0, 20.0));
  EXPECT_DOUBLE_EQ(map.size_x, 10.0);
  EXPECT_DOUBLE_EQ(map.size_y, 20.0);
}

TEST(HeightmapIo, TiledDoubleTiffRoundTrips) {
  const auto dir = test::temp_dir("tiled");
  TiffSpec spec = tiff(37, 21, 64, 3);
  spec.tiled = true;
  std::vector<double> values(37 * 21);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::sin(0.1 * static_cast<double>(i));
  test::write_tiff(dir / "h.tif", spec, values);
  const Heightmap map = load_heightmap(dir / "h.tif", footprint(3.6, 2.0));
  ASSERT_EQ(map.cols, 37u);
  ASSERT_EQ(map.rows, 21u);
  for (std::size_t image_row = 0; image_row < 21; ++image_row) {
    for (std::size_t c = 0; c < 37; ++c) {
      ASSERT_FLOAT_EQ(map.at(20 - image_row, c), static_cast<float>(values[image_row * 37 + c]));
    }
  }
}

TEST(HeightmapIo, SixteenBitIntegerTiffUsesTheRange) {
  const auto dir = test::temp_dir("tiff16");
  TiffSpec spec = tiff(2, 2, 16, 1);
  test::write_tiff(dir / "h.tif", spec, {0, 65535, 13107, 52428});
  const Heightmap map =
      load_heightmap(dir / "h.tif", full(1.0, 1.0, 1.0, 6.0));
  EXPECT_FLOAT_EQ(map.at(1, 0), 1.0f);
  EXPECT_FLOAT_EQ(map.at(1, 1), 6.0f);
  EXPECT_FLOAT_EQ(map.at(0, 0), 2.0f);
  EXPECT_FLOAT_EQ(map.at(0, 1), 5.0f);
}

TEST(HeightmapIo, SavedPngAndTiffLoadBackUnaided) {
  const auto dir = test::temp_dir("save");
  Heightmap map;
  map.rows = 4;
  map.cols = 5;
  map.size_x = 2.0;
  map.size_y = 1.5;
  for (std::size_t i = 0; i < 20; ++i) map.heights.push_back(0.37f * static_cast<float>(i) - 2.0f);
  const HeightRange range = save_heightmap_png(map, dir / "m.png");
  EXPECT_FLOAT_EQ(static_cast<float>(range.z_min), -2.0f);
  EXPECT_FLOAT_EQ(static_cast<float>(range.z_max), 0.37f * 19 - 2.0f);
  save_heightmap_tiff(map, dir / "m.tif");
  for (const char* name : {"m.png", "m.tif"}) {
    const Heightmap back = load_heightmap(dir / name);
    ASSERT_EQ(back.rows, 4u) << name;
    ASSERT_EQ(back.cols, 5u) << name;
    EXPECT_NEAR(back.size_x, 2.0, 1e-9) << name;
    EXPECT_NEAR(back.size_y, 1.5, 1e-9) << name;
    const double tolerance = std::string(name) == "m.png" ? (range.z_max - range.z_min) / 65535.0 : 0.0;
    for (std::size_t i = 0; i < 20; ++i) {
      EXPECT_NEAR(back.heights[i], map.heights[i], tolerance + 1e-6) << name << " sample " << i;
    }
  }
}

TEST(HeightmapIoErrors, MissingFileAndDirectory) {
  const auto dir = test::temp_dir("errors_missing");
  expect_error(dir / "nope.png", {}, "no such file");
  expect_error(dir, {}, "is a directory");
}

TEST(HeightmapIoErrors, NotAnImage) {
  const auto dir = test::temp_dir("errors_text");
  std::ofstream(dir / "h.png") << "hello, this is text\n";
  expect_error(dir / "h.png", {}, "not a PNG or TIFF image");
}

TEST(HeightmapIoErrors, TruncatedPng) {
  const auto dir = test::temp_dir("errors_trunc");
  // Noisy samples so that the image data, not the header, makes up most of the file.
  std::vector<std::uint16_t> values(64 * 64);
  std::uint32_t state = 12345;
  for (auto& v : values) v = static_cast<std::uint16_t>((state = state * 1664525u + 1013904223u) >> 16);
  test::write_gray_png(dir / "h.png", 64, 64, 16, values);
  const auto size = std::filesystem::file_size(dir / "h.png");
  std::filesystem::resize_file(dir / "h.png", size * 3 / 4);
  expect_error(dir / "h.png", full(1, 1, 0, 1), "corrupt PNG data");
  std::filesystem::resize_file(dir / "h.png", 20);
  expect_error(dir / "h.png", full(1, 1, 0, 1), "not a readable PNG (corrupt or truncated header)");
}

TEST(HeightmapIoErrors, ColourPng) {
  const auto dir = test::temp_dir("errors_rgb");
  test::write_rgb_png(dir / "h.png", 4, 4);
  expect_error(dir / "h.png", full(1, 1, 0, 1),
               "PNG is RGB; a heightmap must be single-channel grayscale");
}

TEST(HeightmapIoErrors, LowBitDepthPng) {
  const auto dir = test::temp_dir("errors_depth");
  test::write_low_depth_png(dir / "h.png", 8, 8, 4);
  expect_error(dir / "h.png", full(1, 1, 0, 1), "unsupported bit depth 4 of a grayscale PNG");
}

TEST(HeightmapIoErrors, UnsupportedTiffSampleFormats) {
  const auto dir = test::temp_dir("errors_format");
  test::write_tiff(dir / "s16.tif", tiff(2, 2, 16, 2),
                   {1, 2, 3, 4});
  expect_error(dir / "s16.tif", full(1, 1, 0, 1),
               "unsupported TIFF sample format 16-bit signed integer");
  TiffSpec rgb = tiff(2, 2, 8, 1);
  rgb.channels = 3;
  test::write_tiff(dir / "rgb.tif", rgb, {1, 2, 3, 4});
  expect_error(dir / "rgb.tif", full(1, 1, 0, 1),
               "3 samples per pixel");
}

TEST(HeightmapIoErrors, MissingFootprintAndRange) {
  const auto dir = test::temp_dir("errors_footprint");
  test::write_gray_png(dir / "h.png", 2, 2, 8, {1, 2, 3, 4});
  expect_error(dir / "h.png", with_range({}, 0, 1), "missing footprint");
  expect_error(dir / "h.png", footprint(1, 1), "missing height range");
  expect_error(dir / "h.png", full(-1, 1, 0, 1),
               "must be positive");
  expect_error(dir / "h.png", full(1, 1, 2, 1),
               "z_min 2 m > z_max 1 m");
  test::write_tiff(dir / "f.tif", tiff(2, 2), {1, 2, 3, 4});
  expect_error(dir / "f.tif", with_range({}, 0, 1), "missing footprint");
  HeightmapOptions only_min = footprint(1, 1);
  only_min.z_min = 0.0;
  expect_error(dir / "f.tif", only_min, "give both z_min and z_max to rescale the heights");
  expect_error(dir / "f.tif", full(1, 1, 2, 1), "z_min 2 m > z_max 1 m");
}

// A DEM of kilometres laid onto a yard: z_min/z_max rescale a float image's relief linearly, its
// lowest sample to z_min and its highest to z_max (Gazebo's <size> z for a DEM); without them the
// heights stay absolute.
TEST(HeightmapIo, AFloatDemsReliefIsRescaledToTheGivenRange) {
  const auto dir = test::temp_dir("float_rescale");
  test::write_tiff(dir / "dem.tif", tiff(2, 3), {10, 20, 40, 60, 85, 110});
  const Heightmap kept = load_heightmap(dir / "dem.tif", footprint(45, 30));
  EXPECT_FLOAT_EQ(*std::min_element(kept.heights.begin(), kept.heights.end()), 10.0f);
  EXPECT_FLOAT_EQ(*std::max_element(kept.heights.begin(), kept.heights.end()), 110.0f);
  const Heightmap yard = load_heightmap(dir / "dem.tif", full(45, 30, -0.5, 2.5));
  EXPECT_DOUBLE_EQ(yard.size_x, 45.0);
  EXPECT_FLOAT_EQ(*std::min_element(yard.heights.begin(), yard.heights.end()), -0.5f);
  EXPECT_FLOAT_EQ(*std::max_element(yard.heights.begin(), yard.heights.end()), 2.5f);
  // Linear: 60 m is half-way between 10 and 110, so it lands half-way between -0.5 and 2.5.
  for (std::size_t i = 0; i < kept.heights.size(); ++i) {
    EXPECT_NEAR(yard.heights[i], -0.5 + (kept.heights[i] - 10.0) * 0.03, 1e-5) << i;
  }
}

TEST(HeightmapIoErrors, NanSamplesAreNamed) {
  const auto dir = test::temp_dir("errors_nan");
  test::write_tiff(dir / "h.tif", tiff(3, 2), {1, 2, 3, 4, NAN, NAN});
  expect_error(dir / "h.tif", footprint(1, 1),
               "2 samples are NaN or infinite as heights (first at image row 1, column 1)");
}

TEST(HeightmapIoErrors, TooSmallImage) {
  const auto dir = test::temp_dir("errors_small");
  test::write_tiff(dir / "h.tif", tiff(1, 5), {1, 2, 3, 4, 5});
  expect_error(dir / "h.tif", footprint(1, 1), "at least 2 x 2");
}

}  // namespace
}  // namespace mechsim::physics
