#include "physics/heightmap_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "physics/heightmap_raster.hpp"

namespace mechsim::physics {
namespace {

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

enum class Format { kPng, kTiff, kUnknown };

Format sniff(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HeightmapError(path.string() + ": cannot open file");
  unsigned char head[8] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  const auto got = in.gcount();
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got == 8 && std::equal(head, head + 8, kPng)) return Format::kPng;
  if (got >= 4 && ((head[0] == 'I' && head[1] == 'I' && (head[2] == 42 || head[2] == 43) &&
                    head[3] == 0) ||
                   (head[0] == 'M' && head[1] == 'M' && head[2] == 0 &&
                    (head[3] == 42 || head[3] == 43)))) {
    return Format::kTiff;
  }
  return Format::kUnknown;
}

void check_option(const std::string& where, const char* name, const std::optional<double>& v) {
  if (v && !std::isfinite(*v)) throw HeightmapError(where + ": " + name + " is not finite");
}

}  // namespace

Heightmap load_heightmap(const std::filesystem::path& path, const HeightmapOptions& options) {
  const std::string where = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw HeightmapError(where + ": no such file");
  if (std::filesystem::is_directory(path, ec)) {
    throw HeightmapError(where + ": is a directory, not an image");
  }
  for (auto [name, v] : {std::pair{"size_x", options.size_x}, {"size_y", options.size_y},
                         {"z_min", options.z_min}, {"z_max", options.z_max}}) {
    check_option(where, name, v);
  }
  detail::Raster raster;
  switch (sniff(path)) {
    case Format::kPng: raster = detail::read_png_raster(path); break;
    case Format::kTiff: raster = detail::read_tiff_raster(path); break;
    case Format::kUnknown:
      throw HeightmapError(where + ": not a PNG or TIFF image (unrecognised file signature)");
  }
  if (raster.width < 2 || raster.height < 2) {
    throw HeightmapError(where + ": image of " + std::to_string(raster.width) + " x " +
                         std::to_string(raster.height) + " samples; a heightmap needs at least 2 x 2");
  }

  Heightmap map;
  map.source = where;
  map.cols = raster.width;
  map.rows = raster.height;
  const auto size_x = options.size_x ? options.size_x : raster.size_x;
  const auto size_y = options.size_y ? options.size_y : raster.size_y;
  if (!size_x || !size_y) {
    throw HeightmapError(where + ": missing footprint: the " + raster.format +
                         " holds no GeoTIFF pixel scale (tag 33550); give size_x and size_y (m)");
  }
  if (!(*size_x > 0.0) || !(*size_y > 0.0)) {
    throw HeightmapError(where + ": footprint " + number(*size_x) + " m x " + number(*size_y) +
                         " m must be positive");
  }
  map.size_x = *size_x;
  map.size_y = *size_y;

  double z0 = 0.0, dz = 1.0;
  if (raster.is_float) {
    // Absolute heights, kept as they are unless both z_min and z_max are given: then the DEM's
    // lowest and highest samples become z_min and z_max (its relief rescaled, as Gazebo's <size>
    // z does for a DEM), e.g. to lay a survey of kilometres onto a yard of tens of metres.
    if (options.z_min.has_value() != options.z_max.has_value()) {
      throw HeightmapError(where + ": give both z_min and z_max to rescale the heights of a " + raster.format +
                           " (its lowest and highest samples become them), or neither to keep them");
    }
    if (options.z_min) {
      if (!(*options.z_max >= *options.z_min)) {
        throw HeightmapError(where + ": height range z_min " + number(*options.z_min) + " m > z_max " +
                             number(*options.z_max) + " m");
      }
      double lo = INFINITY, hi = -INFINITY;
      for (const double v : raster.samples) {
        if (!std::isfinite(v) || (raster.nodata && v == *raster.nodata)) continue;  // refused below
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      if (lo <= hi) {
        dz = hi > lo ? (*options.z_max - *options.z_min) / (hi - lo) : 0.0;
        z0 = *options.z_min - lo * dz;
      }
    }
  } else {
    const auto z_min = options.z_min ? options.z_min : raster.z_min;
    const auto z_max = options.z_max ? options.z_max : raster.z_max;
    if (!z_min || !z_max) {
      throw HeightmapError(where + ": missing height range: a " + raster.format +
                           " holds sample values, not heights; give z_min and z_max (m)");
    }
    if (!(*z_max >= *z_min)) {
      throw HeightmapError(where + ": height range z_min " + number(*z_min) + " m > z_max " +
                           number(*z_max) + " m");
    }
    z0 = *z_min;
    dz = (*z_max - *z_min) / raster.max_value;
  }

  map.heights.resize(map.rows * map.cols);
  std::size_t bad = 0, first_bad = 0, nodata = 0, first_nodata = 0;
  for (std::size_t r = 0; r < map.rows; ++r) {
    const std::size_t image_row = map.rows - 1 - r;  // image row 0 is the north edge
    for (std::size_t c = 0; c < map.cols; ++c) {
      const std::size_t i = image_row * map.cols + c;
      const double v = raster.samples[i];
      const auto z = static_cast<float>(z0 + v * dz);
      if (!std::isfinite(v) || !std::isfinite(z)) {
        if (bad++ == 0) first_bad = i;
      } else if (raster.nodata && v == *raster.nodata) {
        if (nodata++ == 0) first_nodata = i;
      }
      map.heights[r * map.cols + c] = z;
    }
  }
  auto at = [&](std::size_t i) {
    return "image row " + std::to_string(i / map.cols) + ", column " + std::to_string(i % map.cols);
  };
  if (bad > 0) {
    throw HeightmapError(where + ": " + std::to_string(bad) +
                         " samples are NaN or infinite as heights (first at " + at(first_bad) + ")");
  }
  if (nodata > 0) {
    throw HeightmapError(where + ": " + std::to_string(nodata) +
                         " samples hold the GDAL no-data value " + number(*raster.nodata) +
                         " (first at " + at(first_nodata) + "); fill the holes first");
  }
  return map;
}

}  // namespace mechsim::physics
