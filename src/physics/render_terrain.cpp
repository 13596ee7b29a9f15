#include "physics/render_terrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "physics/terrain_tiles.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {

TerrainLod::TerrainLod(const mjModel* m) {
  by_geom_.assign(static_cast<std::size_t>(m->ngeom), Entry{});
  std::map<std::pair<int, int>, int> index;  // (tile row, tile col) -> tile
  const std::size_t prefix = std::strlen(kTilePrefix);
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] != mjGEOM_HFIELD || m->geom_group[g] != kTileGroup) continue;
    const char* name = mj_id2name(m, mjOBJ_GEOM, g);
    int level = 0, row = 0, col = 0;
    if (name == nullptr || std::strncmp(name, kTilePrefix, prefix) != 0 ||
        std::sscanf(name + prefix, "%d_%d_%d", &level, &row, &col) != 3)
      continue;
    const int hf = m->geom_dataid[g];
    const mjtNum* size = m->hfield_size + 4 * hf;
    const mjtNum* pos = m->geom_pos + 3 * g;
    auto [it, added] = index.emplace(std::make_pair(row, col), static_cast<int>(tiles_.size()));
    if (added) {
      Tile t;
      t.lo[0] = pos[0] - size[0];
      t.hi[0] = pos[0] + size[0];
      t.lo[1] = pos[1] - size[1];
      t.hi[1] = pos[1] + size[1];
      t.lo[2] = 1e300;
      t.hi[2] = -1e300;
      tiles_.push_back(t);
    }
    Tile& t = tiles_[static_cast<std::size_t>(it->second)];
    const int nrow = m->hfield_nrow[hf], ncol = m->hfield_ncol[hf];
    const float* data = m->hfield_data + m->hfield_adr[hf];
    const auto [dlo, dhi] = std::minmax_element(data, data + nrow * ncol);
    t.lo[2] = std::min(t.lo[2], pos[2] + static_cast<double>(*dlo) * size[2]);
    t.hi[2] = std::max(t.hi[2], pos[2] + static_cast<double>(*dhi) * size[2]);
    if (static_cast<int>(t.levels.size()) <= level) t.levels.resize(static_cast<std::size_t>(level) + 1);
    t.levels[static_cast<std::size_t>(level)] = {2.0 * size[0] / (ncol - 1), static_cast<long>(nrow - 1) * (ncol - 1)};
    by_geom_[static_cast<std::size_t>(g)] = {it->second, level};
  }
}

ViewFrustum::ViewFrustum(const CameraView& v) {
  const description::Quat& q = v.X_WC.orientation;
  const description::Vec3 ax[3] = {rotate(q, {1, 0, 0}), rotate(q, {0, 1, 0}), rotate(q, {0, 0, 1})};
  const double o[3] = {v.X_WC.position.x, v.X_WC.position.y, v.X_WC.position.z};
  // The planes in the camera's optical frame (x right, y down, z forward).
  const double xl = (-0.5 - v.cx) / v.fx, xr = (v.width - 0.5 - v.cx) / v.fx;
  const double yt = (-0.5 - v.cy) / v.fy, yb = (v.height - 0.5 - v.cy) / v.fy;
  const double planes_c[6][4] = {{1, 0, -xl, 0}, {-1, 0, xr, 0}, {0, 1, -yt, 0},
                                 {0, -1, yb, 0}, {0, 0, 1, -v.near}, {0, 0, -1, v.far}};
  for (int p = 0; p < 6; ++p) {
    double nw[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a) {
      const double c = planes_c[p][a];
      nw[0] += c * ax[a].x;
      nw[1] += c * ax[a].y;
      nw[2] += c * ax[a].z;
    }
    // Unit normals, so that a plane's value at a point is its distance.
    const double len = std::sqrt(nw[0] * nw[0] + nw[1] * nw[1] + nw[2] * nw[2]);
    for (int a = 0; a < 3; ++a) planes_[p][a] = nw[a] / len;
    planes_[p][3] = planes_c[p][3] / len - (planes_[p][0] * o[0] + planes_[p][1] * o[1] + planes_[p][2] * o[2]);
  }
}

bool ViewFrustum::outside_box(const double lo[3], const double hi[3]) const {
  for (const auto& pl : planes_) {
    // The box corner farthest along the plane's normal.
    double best = pl[3];
    for (int a = 0; a < 3; ++a) best += pl[a] * (pl[a] >= 0 ? hi[a] : lo[a]);
    if (best < 0.0) return true;
  }
  return false;
}

bool ViewFrustum::outside_sphere(const float c[3], double r) const {
  for (const auto& pl : planes_)
    if (pl[0] * c[0] + pl[1] * c[1] + pl[2] * c[2] + pl[3] < -r) return true;
  return false;
}

bool ViewFrustum::outside_oriented_box(const float pos[3], const float mat[9], const float lo[3], const float hi[3]) const {
  for (const auto& pl : planes_) {
    // The plane's normal in the box's frame; the box corner farthest along it.
    double best = pl[3] + pl[0] * pos[0] + pl[1] * pos[1] + pl[2] * pos[2];
    for (int a = 0; a < 3; ++a) {
      const double n = pl[0] * mat[a] + pl[1] * mat[3 + a] + pl[2] * mat[6 + a];
      best += n * (n >= 0 ? hi[a] : lo[a]);
    }
    if (best < 0.0) return true;
  }
  return false;
}

bool ViewFrustum::outside_points(const float pos[3], const float mat[9], const float* v, int n) const {
  for (const auto& pl : planes_) {
    // The plane in the points' frame: n_local . v + d_local < 0 for every point.
    const float nx = static_cast<float>(pl[0] * mat[0] + pl[1] * mat[3] + pl[2] * mat[6]);
    const float ny = static_cast<float>(pl[0] * mat[1] + pl[1] * mat[4] + pl[2] * mat[7]);
    const float nz = static_cast<float>(pl[0] * mat[2] + pl[1] * mat[5] + pl[2] * mat[8]);
    // A margin of a micrometre over float rounding: a point on the plane counts as inside.
    const float d = static_cast<float>(pl[3] + pl[0] * pos[0] + pl[1] * pos[1] + pl[2] * pos[2]) + 1e-6f;
    bool all_outside = true;
    for (int i = 0; i < n && all_outside; ++i) all_outside = nx * v[3 * i] + ny * v[3 * i + 1] + nz * v[3 * i + 2] + d < 0.0f;
    if (all_outside) return true;
  }
  return false;
}

std::vector<int> TerrainLod::choose(const CameraView& v, double pixels_per_cell, RenderStats& stats) const {
  std::vector<int> out(tiles_.size(), -1);
  const ViewFrustum frustum(v);
  const double o[3] = {v.X_WC.position.x, v.X_WC.position.y, v.X_WC.position.z};
  const double focal = std::max(v.fx, v.fy);
  for (std::size_t i = 0; i < tiles_.size(); ++i) {
    const Tile& t = tiles_[i];
    if (frustum.outside_box(t.lo, t.hi)) continue;
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double c = std::clamp(o[a], t.lo[a], t.hi[a]);
      d2 += (o[a] - c) * (o[a] - c);
    }
    const double dist = std::max(std::sqrt(d2), 1e-3);
    int level = 0;
    for (int l = static_cast<int>(t.levels.size()) - 1; l > 0; --l) {
      const Level& lv = t.levels[static_cast<std::size_t>(l)];
      if (lv.cells > 0 && lv.cell * focal / dist <= pixels_per_cell) {
        level = l;
        break;
      }
    }
    out[i] = level;
    stats.terrain_tiles += 1;
    stats.terrain_cells += t.levels[static_cast<std::size_t>(level)].cells;
  }
  return out;
}

}  // namespace mechsim::physics
