#include "sim/world.hpp"

#include <filesystem>

namespace mechsim::sim {

World make_world(const WorldConfig& config) {
  World world;
  world.name = config.name;
  if (config.name == "empty") {
    world.spec.kind = physics::WorldSpec::Kind::Empty;
    return world;
  }
  if (config.name == "mars_yard_2024") {
    world.mars_yard = physics::generate_mars_yard(config.seed);
    world.spec.kind = physics::WorldSpec::Kind::Heightmap;
    world.spec.terrain = world.mars_yard->heightmap;
    world.spec.ground_plane = false;
    return world;
  }
  if (!std::filesystem::exists(config.name)) {
    throw WorldError("unknown world '" + config.name +
                     "': expected 'empty', 'mars_yard_2024' or an existing heightmap file (.png, .tif)");
  }
  try {
    world.spec.terrain = physics::load_heightmap(config.name, config.heightmap);
  } catch (const physics::HeightmapError& e) {
    throw WorldError(e.what());
  }
  world.spec.kind = physics::WorldSpec::Kind::Heightmap;
  world.spec.ground_plane = false;
  return world;
}

}  // namespace mechsim::sim
