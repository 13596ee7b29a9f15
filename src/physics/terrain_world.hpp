#pragma once
// The terrain of a named world, as `mechsim world` and the simulation look it up:
//   "empty"           flat ground plane at z = 0, no heightmap;
//   "mars_yard_2024"  generated from a seed (mars_yard.hpp);
//   "slope"           a plane rising along +x at slope_deg (default 10 deg): 40 m x 12 m, 5 cm
//                     cells, z = tan(slope) (x + 20) (0 at the west edge), for climbing and
//                     standing tests;
//   anything else     a heightmap image file (heightmap_io.hpp).

#include <cstdint>
#include <optional>
#include <string>

#include "physics/heightmap_io.hpp"
#include "physics/mars_yard.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::physics {

struct WorldTerrainOptions {
  std::optional<std::uint64_t> seed;  // mars_yard_2024 only; default kMarsYardDefaultSeed
  std::optional<double> slope_deg;    // slope only; default 10, in [0, 60)
  HeightmapOptions heightmap;         // heightmap files only
};

struct WorldTerrain {
  std::string name;                  // as asked for
  std::optional<Heightmap> heightmap;  // none for "empty"
  std::optional<MarsYard> yard;        // the generated yard's features (its heights are in `heightmap`)
  std::optional<Region> usable;        // region to take statistics over (the yard's usable ground)
};

// The "slope" world's plane (see above).
Heightmap make_slope(double slope_deg);

// Throws std::invalid_argument for an unknown world or options that do not apply to it, and
// HeightmapError for a bad heightmap file.
WorldTerrain load_world_terrain(const std::string& world, const WorldTerrainOptions& options = {});

}  // namespace mechsim::physics
