#include "sim/world.hpp"

#include "physics/terrain_world.hpp"

namespace mechsim::sim {

World make_world(const WorldConfig& config) {
  physics::WorldTerrainOptions options;
  if (config.name == "mars_yard_2024") options.seed = config.seed;
  if (config.name != "empty" && config.name != "mars_yard_2024") options.heightmap = config.heightmap;
  physics::WorldTerrain terrain;
  try {
    terrain = physics::load_world_terrain(config.name, options);
  } catch (const std::exception& e) {
    throw WorldError("world '" + config.name + "': " + e.what());
  }
  World world;
  world.name = config.name;
  world.mars_yard = std::move(terrain.yard);
  if (terrain.heightmap) {
    world.spec.kind = physics::WorldSpec::Kind::Heightmap;
    world.spec.terrain = std::move(terrain.heightmap);
    world.spec.ground_plane = false;
  }
  return world;
}

}  // namespace mechsim::sim
