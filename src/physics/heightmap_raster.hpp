#pragma once
// Internal to heightmap loading: one decoded single-channel image before it becomes a
// Heightmap, plus what the file said about its footprint and height range.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mechsim::physics::detail {

struct Raster {
  std::size_t width = 0, height = 0;  // samples per image row, image rows
  std::vector<double> samples;        // width*height, image order (row 0 = north edge)
  bool is_float = false;              // float samples are heights (m); integer ones are mapped
  double max_value = 0.0;             // largest integer sample value (255 or 65535)
  std::string format;                 // e.g. "16-bit grayscale PNG", for messages
  std::optional<double> size_x, size_y;  // footprint the file holds (m)
  std::optional<double> z_min, z_max;    // height range the file holds (m)
  std::optional<double> nodata;          // GDAL no-data value, if the file declares one
};

// Largest image loaded, in samples: 2^28 (1 GiB as doubles) keeps a bad header from
// exhausting memory.
inline constexpr std::size_t kMaxSamples = std::size_t{1} << 28;

// Both throw HeightmapError naming the file.
Raster read_png_raster(const std::filesystem::path& path);
Raster read_tiff_raster(const std::filesystem::path& path);

}  // namespace mechsim::physics::detail
