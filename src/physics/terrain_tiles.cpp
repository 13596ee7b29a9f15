#include "physics/terrain_tiles.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mechsim::physics {

double TerrainTile::cell() const { return (x1 - x0) / static_cast<double>(ncol - 1); }

std::vector<TerrainTile> plan_terrain_tiles(const Heightmap& h) {
  std::vector<TerrainTile> out;
  if (h.rows < 2 || h.cols < 2) return out;
  const std::size_t cells_r = h.rows - 1, cells_c = h.cols - 1;
  const std::size_t tiles_r = (cells_r + kTileCells - 1) / kTileCells, tiles_c = (cells_c + kTileCells - 1) / kTileCells;
  const double x_west = -h.size_x / 2, y_south = -h.size_y / 2;
  // Each tile area's lowest and highest source samples, edges included (the same at every level).
  std::vector<std::pair<float, float>> range(tiles_r * tiles_c);
  for (std::size_t tr = 0; tr < tiles_r; ++tr)
    for (std::size_t tc = 0; tc < tiles_c; ++tc) {
      const std::size_t r0 = tr * kTileCells, c0 = tc * kTileCells;
      const std::size_t r1 = std::min(r0 + kTileCells, cells_r), c1 = std::min(c0 + kTileCells, cells_c);
      float lo = h.at(r0, c0), hi = lo;
      for (std::size_t r = r0; r <= r1; ++r)
        for (std::size_t c = c0; c <= c1; ++c) {
          lo = std::min(lo, h.at(r, c));
          hi = std::max(hi, h.at(r, c));
        }
      range[tr * tiles_c + tc] = {lo, hi};
    }
  for (int level = 0; (kTileCells >> level) >= 2; ++level) {
    const std::size_t stride = std::size_t{1} << level;
    for (std::size_t tr = 0; tr < tiles_r; ++tr)
      for (std::size_t tc = 0; tc < tiles_c; ++tc) {
        TerrainTile t;
        t.level = level;
        t.tile_row = tr;
        t.tile_col = tc;
        t.row0 = tr * kTileCells;
        t.col0 = tc * kTileCells;
        t.row_cells = std::min(kTileCells, cells_r - t.row0);
        t.col_cells = std::min(kTileCells, cells_c - t.col0);
        t.nrow = std::max<std::size_t>(1, (t.row_cells + stride - 1) / stride) + 1;
        t.ncol = std::max<std::size_t>(1, (t.col_cells + stride - 1) / stride) + 1;
        t.x0 = x_west + static_cast<double>(t.col0) * h.cell_x();
        t.x1 = x_west + static_cast<double>(t.col0 + t.col_cells) * h.cell_x();
        t.y0 = y_south + static_cast<double>(t.row0) * h.cell_y();
        t.y1 = y_south + static_cast<double>(t.row0 + t.row_cells) * h.cell_y();
        t.lo = range[tr * tiles_c + tc].first;
        t.hi = range[tr * tiles_c + tc].second;
        t.name = std::string(kTilePrefix) + std::to_string(level) + "_" + std::to_string(tr) + "_" + std::to_string(tc);
        out.push_back(std::move(t));
      }
  }
  return out;
}

void fill_terrain_tile(const Heightmap& h, const TerrainTile& t, float* out) {
  const float lo = t.lo;
  const double range = static_cast<double>(t.hi - t.lo);
  auto sample = [&](double r, double c) {
    const auto r0 = std::min(static_cast<std::size_t>(r), h.rows - 2), c0 = std::min(static_cast<std::size_t>(c), h.cols - 2);
    const double fr = r - static_cast<double>(r0), fc = c - static_cast<double>(c0);
    const double z = (1 - fr) * ((1 - fc) * h.at(r0, c0) + fc * h.at(r0, c0 + 1)) +
                     fr * ((1 - fc) * h.at(r0 + 1, c0) + fc * h.at(r0 + 1, c0 + 1));
    return range > 0.0 ? static_cast<float>((z - lo) / range) : 0.0f;
  };
  for (std::size_t i = 0; i < t.nrow; ++i) {
    const double r = static_cast<double>(t.row0) + static_cast<double>(t.row_cells) * static_cast<double>(i) / static_cast<double>(t.nrow - 1);
    for (std::size_t j = 0; j < t.ncol; ++j) {
      const double c = static_cast<double>(t.col0) + static_cast<double>(t.col_cells) * static_cast<double>(j) / static_cast<double>(t.ncol - 1);
      out[i * t.ncol + j] = sample(r, c);
    }
  }
}

}  // namespace mechsim::physics
