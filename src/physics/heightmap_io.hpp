#pragma once
// Reading and writing heightmap images.
//
// Formats (detected from the file's signature, not its name):
//  - PNG, 8- or 16-bit grayscale: sample value v maps to z_min + v / vmax * (z_max - z_min).
//  - TIFF, 32- or 64-bit IEEE float: samples are absolute heights (m); with z_min and z_max
//    both given, the lowest and highest samples map to them (the relief rescaled linearly).
//  - TIFF, 8- or 16-bit unsigned integer: mapped like PNG.
// Image row 0 is the north edge (largest y), as in Gazebo heightmaps and GeoTIFF rasters, so
// loading flips rows into Heightmap order (row 0 south).
//
// Footprint: HeightmapOptions::size_x/size_y if given; else a GeoTIFF ModelPixelScaleTag
// (33550): size = scale * samples for pixel-is-area rasters (the GeoTIFF default), scale *
// (samples - 1) when the GeoKeyDirectory says pixel-is-point; else the mechsim text chunks of
// a PNG written by save_heightmap_png. Height range of integer images: options, else the PNG
// text chunks. The footprint is always centred on the origin (model tie points are ignored).
//
// Every error is a HeightmapError whose message names the file and what is wrong.

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "physics/heightmap.hpp"

namespace mechsim::physics {

struct HeightmapError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct HeightmapOptions {
  std::optional<double> size_x, size_y;  // footprint along x and y (m), > 0
  std::optional<double> z_min, z_max;    // heights (m) of the lowest and highest integer sample
                                         // values (0 and 255 or 65535); of a float image's lowest
                                         // and highest samples (both or neither)
};

Heightmap load_heightmap(const std::filesystem::path& path, const HeightmapOptions& options = {});

// Height range (m) that a 16-bit PNG's 0 and 65535 stand for.
struct HeightRange {
  double z_min = 0.0, z_max = 0.0;
};

// 16-bit grayscale PNG spanning the map's own min..max (a flat map gets z_max = z_min + 1 m),
// with the footprint and range in text chunks so load_heightmap reads it back unaided.
// Quantisation: (z_max - z_min) / 65535 per step. Returns the range written.
HeightRange save_heightmap_png(const Heightmap& map, const std::filesystem::path& path);

// 32-bit float TIFF of absolute heights with GeoTIFF ModelPixelScaleTag and ModelTiepointTag
// (pixel-is-area: scale = size / samples), so load_heightmap recovers the footprint.
void save_heightmap_tiff(const Heightmap& map, const std::filesystem::path& path);

}  // namespace mechsim::physics
