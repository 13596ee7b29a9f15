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
  // The lowest and highest source samples of the tile's area, its edges included (m): every
  // level's samples lie between them, and so does any neighbour's edge along a shared side.
  float lo = 0.0f, hi = 0.0f;
  double cell() const;  // this level's cell size along x (m)
};

// How far a tile's walls reach below its lowest sample (m). MuJoCo draws a height field with side
// walls down to its base and a bottom there; the walls close the cracks where neighbouring tiles
// meet at different levels of detail. A crack lies between the two tiles' edges, and both edges
// lie at or above the lowest sample of either tile's area, so walls down to each tile's own lowest
// sample close every crack. Walls down to the whole map's lowest point (as the tiles once had)
// closed the same cracks with walls metres tall, which llvmpipe rasterised under the ground.
inline constexpr double kTileBase = 0.01;

// Every tile at every level, level-major. Levels go on while a tile still has 2 cells.
std::vector<TerrainTile> plan_terrain_tiles(const Heightmap& h);

// The tile's samples, row-major from its south-west corner, normalised to its own range:
// (height - tile.lo) / (tile.hi - tile.lo). Bilinear in the source grid.
void fill_terrain_tile(const Heightmap& h, const TerrainTile& tile, float* out);

}  // namespace mechsim::physics
