#pragma once
// Private to src/physics: render-only copies of a height field, cut into square tiles at several
// levels of detail (BuildOptions::render_terrain). Level l of a tile has 2^l times coarser cells
// than the source grid. The renderer draws, per camera, each visible tile at the coarsest level
// whose cells still project to a few pixels; physics never sees the tiles (group 3, no contacts).
// A MuJoCo height field is drawn with side walls down to its base, and those walls close the
// cracks where neighbouring tiles meet at different levels.

#include <cstddef>
#include <string>
#include <vector>

#include "physics/heightmap.hpp"

namespace mechsim::physics {

inline constexpr std::size_t kTileCells = 32;  // source cells along a tile's side (level 0)
inline constexpr int kTileGroup = 3;           // MuJoCo geom group of the tiles
inline constexpr const char* kTilePrefix = "terrain_tile_";

struct TerrainTile {
  std::string name;              // hfield asset and geom name: terrain_tile_<level>_<row>_<col>
  int level = 0;
  std::size_t tile_row = 0, tile_col = 0;
  std::size_t row0 = 0, col0 = 0;          // first source sample
  std::size_t row_cells = 0, col_cells = 0;  // source cells covered
  std::size_t nrow = 0, ncol = 0;            // samples of this level's grid (>= 2)
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;  // world extent (m)
  double cell() const;  // this level's cell size along x (m)
};

// Every tile at every level, level-major. Levels go on while a tile still has 2 cells.
std::vector<TerrainTile> plan_terrain_tiles(const Heightmap& h);

// The tile's samples, row-major from its south-west corner, normalised as the physics height
// field's: (height - lo) / (hi - lo) with the whole map's lo and hi. Bilinear in the source grid.
void fill_terrain_tile(const Heightmap& h, const TerrainTile& tile, float lo, float hi, float* out);

}  // namespace mechsim::physics
