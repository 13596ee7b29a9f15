#include "physics/terrain_world.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace mechsim::physics {

Heightmap make_slope(double slope_deg) {
  if (!(slope_deg >= 0.0 && slope_deg < 60.0))
    throw std::invalid_argument("world 'slope': slope_deg must be in [0, 60), got " + std::to_string(slope_deg));
  Heightmap map;
  map.size_x = 40.0;
  map.size_y = 12.0;
  map.cols = 801;
  map.rows = 241;
  map.heights.resize(map.rows * map.cols);
  const double rise = std::tan(slope_deg * M_PI / 180.0);
  for (std::size_t r = 0; r < map.rows; ++r)
    for (std::size_t c = 0; c < map.cols; ++c)
      map.heights[r * map.cols + c] = static_cast<float>(rise * static_cast<double>(c) * map.cell_x());
  map.source = "slope " + std::to_string(slope_deg) + " deg";
  return map;
}

WorldTerrain load_world_terrain(const std::string& world, const WorldTerrainOptions& options) {
  const HeightmapOptions& h = options.heightmap;
  const bool file_options = h.size_x || h.size_y || h.z_min || h.z_max;
  WorldTerrain terrain;
  terrain.name = world;
  if (world == "empty" || world == "mars_yard_2024") {
    if (file_options) {
      throw std::invalid_argument("world '" + world +
                                  "': size and height range options apply to heightmap files only");
    }
  }
  if (world != "slope" && options.slope_deg)
    throw std::invalid_argument("world '" + world + "': slope_deg applies to the world 'slope' only");
  if (world == "empty") {
    if (options.seed) throw std::invalid_argument("world 'empty': --seed applies to mars_yard_2024 only");
    return terrain;
  }
  if (world == "slope") {
    if (options.seed || file_options)
      throw std::invalid_argument("world 'slope': only slope_deg applies to it");
    terrain.heightmap = make_slope(options.slope_deg.value_or(10.0));
    return terrain;
  }
  if (world == "mars_yard_2024") {
    terrain.yard = generate_mars_yard(options.seed.value_or(kMarsYardDefaultSeed));
    terrain.heightmap = std::move(terrain.yard->heightmap);  // one copy of 1.8 MB, not two
    terrain.usable = terrain.yard->usable;
    return terrain;
  }
  std::error_code ec;
  if (!std::filesystem::exists(world, ec)) {
    throw std::invalid_argument("unknown world '" + world +
                                "': not a built-in world (empty, mars_yard_2024) and no such file");
  }
  if (options.seed) throw std::invalid_argument("world '" + world + "': --seed applies to mars_yard_2024 only");
  terrain.heightmap = load_heightmap(world, h);
  return terrain;
}

}  // namespace mechsim::physics
