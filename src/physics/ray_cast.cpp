// Ray casting: the exact height-field intersection, the per-sensor shape filter, and the cast
// over MuJoCo's geoms (Physics::cast_rays forwards here).
#include "physics/ray_cast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/mujoco_internal.hpp"
#include "physics/sensing_internal.hpp"

namespace mechsim::physics {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Cell {
  const HfieldGrid& g;
  double dx, dy;
  // Heights of the cell (c, r) at its corners: 00 = (c, r), 10 = (c + 1, r), 01 = (c, r + 1).
  double h00, h10, h01, h11, xc, yr;

  Cell(const HfieldGrid& grid, double cell_x, double cell_y, int c, int r)
      : g(grid), dx(cell_x), dy(cell_y) {
    const auto at = [&](int row, int col) {
      return static_cast<double>(g.data[static_cast<std::size_t>(row) * static_cast<std::size_t>(g.cols) +
                                        static_cast<std::size_t>(col)]) * g.top;
    };
    h00 = at(r, c);
    h10 = at(r, c + 1);
    h01 = at(r + 1, c);
    h11 = at(r + 1, c + 1);
    xc = -g.half_x + c * dx;
    yr = -g.half_y + r * dy;
  }

  // Surface height at cell coordinates (u, w) in [0, 1]^2 on the triangle `lower` (u >= w: the
  // triangle (c, r), (c + 1, r + 1), (c + 1, r)) or the other one.
  double height(double u, double w, bool lower) const {
    return lower ? h00 + u * (h10 - h00) + w * (h11 - h10) : h00 + w * (h01 - h00) + u * (h11 - h01);
  }
};

// The first t in [ta, tb] where the ray meets the surface over cell (c, r), or -1.
double cross_cell(const Cell& cell, const double p[3], const double v[3], double ta, double tb) {
  const auto u = [&](double t) { return (p[0] + t * v[0] - cell.xc) / cell.dx; };
  const auto w = [&](double t) { return (p[1] + t * v[1] - cell.yr) / cell.dy; };
  // u - w is linear in t; it changes sign where the ray crosses the cell's diagonal.
  const double g0 = u(0.0) - w(0.0);
  const double gv = v[0] / cell.dx - v[1] / cell.dy;
  double split[3] = {ta, tb, tb};
  int pieces = 1;
  if (gv != 0.0) {
    const double td = -g0 / gv;
    if (td > ta && td < tb) {
      split[1] = td;
      pieces = 2;
    }
  }
  for (int k = 0; k < pieces; ++k) {
    const double s = split[k], e = split[k + 1];
    const bool lower = g0 + gv * 0.5 * (s + e) >= 0.0;
    const double fs = p[2] + s * v[2] - cell.height(u(s), w(s), lower);
    if (fs <= 0.0) return s;
    const double fe = p[2] + e * v[2] - cell.height(u(e), w(e), lower);
    if (fe <= 0.0) return s + (e - s) * fs / (fs - fe);
  }
  return -1.0;
}

}  // namespace

double ray_hfield(const HfieldGrid& g, const double p[3], const double v[3]) {
  if (g.rows < 2 || g.cols < 2 || g.data == nullptr) return -1.0;
  // Clip the ray to the field's box.
  const double lo[3] = {-g.half_x, -g.half_y, -g.base};
  const double hi[3] = {g.half_x, g.half_y, g.top};
  double t0 = 0.0, t1 = kInf;
  for (int i = 0; i < 3; ++i) {
    if (v[i] == 0.0) {
      if (p[i] < lo[i] || p[i] > hi[i]) return -1.0;
      continue;
    }
    double ta = (lo[i] - p[i]) / v[i], tb = (hi[i] - p[i]) / v[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return -1.0;
  }
  const double dx = 2.0 * g.half_x / (g.cols - 1), dy = 2.0 * g.half_y / (g.rows - 1);
  const double x0 = p[0] + t0 * v[0], y0 = p[1] + t0 * v[1];
  int c = std::clamp(static_cast<int>(std::floor((x0 + g.half_x) / dx)), 0, g.cols - 2);
  int r = std::clamp(static_cast<int>(std::floor((y0 + g.half_y) / dy)), 0, g.rows - 2);
  // Entering through a side wall or the bottom below the surface, or starting inside the solid.
  {
    const Cell cell(g, dx, dy, c, r);
    const double u = (x0 - cell.xc) / dx, w = (y0 - cell.yr) / dy;
    if (p[2] + t0 * v[2] <= cell.height(u, w, u >= w)) return t0;
  }
  // Walk the cells the ray's footprint crosses (Amanatides & Woo), nearest first.
  const int step_x = v[0] > 0.0 ? 1 : (v[0] < 0.0 ? -1 : 0);
  const int step_y = v[1] > 0.0 ? 1 : (v[1] < 0.0 ? -1 : 0);
  const auto next_x = [&]() {
    return step_x == 0 ? kInf : (-g.half_x + (c + (step_x > 0 ? 1 : 0)) * dx - p[0]) / v[0];
  };
  const auto next_y = [&]() {
    return step_y == 0 ? kInf : (-g.half_y + (r + (step_y > 0 ? 1 : 0)) * dy - p[1]) / v[1];
  };
  double t_max_x = next_x(), t_max_y = next_y();
  double ta = t0;
  for (;;) {
    const double tb = std::min({t_max_x, t_max_y, t1});
    if (tb >= ta) {
      const double t = cross_cell(Cell(g, dx, dy, c, r), p, v, ta, tb);
      if (t >= 0.0) return t;
      ta = tb;
    }
    if (tb >= t1) return -1.0;
    if (t_max_x <= t_max_y) {
      c += step_x;
      if (c < 0 || c > g.cols - 2) return -1.0;
      t_max_x = next_x();
    } else {
      r += step_y;
      if (r < 0 || r > g.rows - 2) return -1.0;
      t_max_y = next_y();
    }
  }
}

RayFilter make_ray_filter(const PhysicsModel& model, int exclude_body, RayTargets targets) {
  const mjModel* m = model.impl().model;
  RayFilter f;
  // Groups as the MJCF writer assigns them: 0 robot collision, 1 robot visual, 2 world.
  const int robot_group = targets == RayTargets::Collision ? 0 : 1;
  for (int g = 0; g < m->ngeom; ++g) {
    const int body = m->geom_bodyid[g];
    if (body == exclude_body && body != 0) continue;
    const int group = m->geom_group[g];
    if (group != 2 && group != robot_group) continue;
    (m->geom_type[g] == mjGEOM_HFIELD ? f.hfields : f.geoms).push_back(g);
  }
  return f;
}

namespace detail {

HfieldGrid hfield_grid(const mjModel* m, int geom) {
  const int h = m->geom_dataid[geom];
  const mjtNum* size = m->hfield_size + 4 * h;
  return {m->hfield_nrow[h], m->hfield_ncol[h], size[0], size[1], size[2], size[3], m->hfield_data + m->hfield_adr[h]};
}

double ray_hfield_geom(const mjModel* m, const mjData* d, int geom, const mjtNum pnt[3], const mjtNum vec[3]) {
  const mjtNum* pos = d->geom_xpos + 3 * geom;
  const mjtNum* mat = d->geom_xmat + 9 * geom;  // row-major: world axis i . geom axis j at [3 i + j]
  const double dif[3] = {pnt[0] - pos[0], pnt[1] - pos[1], pnt[2] - pos[2]};
  double lp[3], lv[3];
  for (int j = 0; j < 3; ++j) {
    lp[j] = mat[j] * dif[0] + mat[3 + j] * dif[1] + mat[6 + j] * dif[2];
    lv[j] = mat[j] * vec[0] + mat[3 + j] * vec[1] + mat[6 + j] * vec[2];
  }
  return ray_hfield(hfield_grid(m, geom), lp, lv);
}

void cast_rays(const mjModel* m, const mjData* d, const RayFilter& filter, const description::Vec3& origin,
               const description::Vec3* directions, std::size_t count, double near, double far, double* ranges) {
  for (std::size_t i = 0; i < count; ++i) {
    const description::Vec3& u = directions[i];
    const mjtNum vec[3] = {u.x, u.y, u.z};
    // Gazebo's rays start at the sensor's minimum range: nothing nearer is seen.
    const mjtNum pnt[3] = {origin.x + near * u.x, origin.y + near * u.y, origin.z + near * u.z};
    double best = far - near;
    bool hit = false;
    for (const int g : filter.geoms) {
      const int type = m->geom_type[g];
      const mjtNum* pos = d->geom_xpos + 3 * g;
      if (type != mjGEOM_PLANE) {
        // Bounding sphere: skip shapes the ray passes by, lies behind or cannot reach.
        const double wx = pos[0] - pnt[0], wy = pos[1] - pnt[1], wz = pos[2] - pnt[2];
        const double tc = wx * vec[0] + wy * vec[1] + wz * vec[2];
        const double rb = m->geom_rbound[g];
        if (tc + rb < 0.0 || tc - rb > best) continue;
        if (wx * wx + wy * wy + wz * wz - tc * tc > rb * rb) continue;
      }
      const double x = type == mjGEOM_MESH ? mj_rayMesh(m, d, g, pnt, vec)
                                           : mju_rayGeom(pos, d->geom_xmat + 9 * g, m->geom_size + 3 * g, pnt, vec, type);
      if (x >= 0.0 && x <= best) {
        best = x;
        hit = true;
      }
    }
    for (const int g : filter.hfields) {
      const double x = ray_hfield_geom(m, d, g, pnt, vec);
      if (x >= 0.0 && x <= best) {
        best = x;
        hit = true;
      }
    }
    ranges[i] = hit ? near + best : kInf;
  }
}

}  // namespace detail
}  // namespace mechsim::physics
