#include "sim/world.hpp"

#include <cstdio>

#include "physics/terrain_world.hpp"

namespace mechsim::sim {

World make_world(const WorldConfig& config) {
  physics::WorldTerrainOptions options;
  if (config.name == "mars_yard_2024") options.seed = config.seed;
  if (config.name != "empty" && config.name != "mars_yard_2024" && config.name != "slope") options.heightmap = config.heightmap;
  options.slope_deg = config.slope_deg;
  physics::WorldTerrain terrain;
  try {
    terrain = physics::load_world_terrain(config.name, options);
  } catch (const std::exception& e) {
    throw WorldError("world '" + config.name + "': " + e.what());
  }
  World world;
  world.name = config.name;
  world.soil = config.soil;
  world.mars_yard = std::move(terrain.yard);
  if (terrain.usable) {
    world.usable = terrain.usable;
    const double border = terrain.heightmap ? (terrain.heightmap->size_x - (terrain.usable->x_max - terrain.usable->x_min)) / 2 : 0.0;
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", border);
    world.usable_what = config.name + "'s usable ground (inside its " + text + " m border)";
  } else if (terrain.heightmap) {
    const double hx = terrain.heightmap->size_x / 2, hy = terrain.heightmap->size_y / 2;
    world.usable = physics::Region{-hx, hx, -hy, hy};
    world.usable_what = "the height field of " + config.name + " (no ground past its edges)";
  }
  if (terrain.heightmap) {
    world.spec.kind = physics::WorldSpec::Kind::Heightmap;
    world.spec.terrain = std::move(terrain.heightmap);
    world.spec.ground_plane = false;
  }
  return world;
}

}  // namespace mechsim::sim
