#include "physics/terrain_world.hpp"

#include <filesystem>
#include <stdexcept>

namespace mechsim::physics {

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
  if (world == "empty") {
    if (options.seed) throw std::invalid_argument("world 'empty': --seed applies to mars_yard_2024 only");
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
