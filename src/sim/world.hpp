#pragma once
// The worlds mechsim ships, by name: `empty` (ground plane and gravity), `mars_yard_2024`
// (generated from a seed), `slope` (a plane rising along +x at slope_deg) and any heightmap file
// (8/16-bit PNG, float TIFF). Any of them may be soil instead of rigid ground for the robot's
// wheels (physics::Physics::set_soil).

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "physics/heightmap_io.hpp"
#include "physics/mars_yard.hpp"
#include "physics/physics_options.hpp"
#include "physics/soil.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::sim {

struct WorldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WorldConfig {
  std::string name = "empty";  // "empty", "mars_yard_2024", or a heightmap file's path
  std::uint64_t seed = physics::kMarsYardDefaultSeed;  // mars_yard_2024 only
  physics::HeightmapOptions heightmap;                 // heightmap files only
  std::optional<double> slope_deg;                     // slope only (default 10)
  // The wheels meet soil (physics/soil.hpp) instead of rigid ground; nullopt: rigid.
  std::optional<physics::SoilParameters> soil;
};

struct World {
  std::string name;
  physics::WorldSpec spec;                     // what the physics builds
  std::optional<physics::MarsYard> mars_yard;  // features, for route planning and reports
  // The ground a robot may use (m, W): the Mars Yard's usable ground inside its flat border, a
  // height field's footprint (past its edges there is no ground); none for the endless plane of
  // `empty`. `usable_what` names it in messages.
  std::optional<physics::Region> usable;
  std::string usable_what;
  std::optional<physics::SoilParameters> soil;  // WorldConfig::soil
};

// Throws WorldError (unknown name, unreadable heightmap: the message names the file).
World make_world(const WorldConfig& config);

}  // namespace mechsim::sim
