// Ray casting: the exact height-field intersection, the per-sensor shape filter, and the cast
// over MuJoCo's geoms (Physics::cast_rays forwards here).
#include "physics/ray_cast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

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
  std::map<int, std::shared_ptr<const MeshBvh>> bvh_of_mesh;
  for (int g = 0; g < m->ngeom; ++g) {
    const int body = m->geom_bodyid[g];
    const int group = m->geom_group[g];
    if (exclude_body >= 0 && group != 2 && m->body_weldid[body] == m->body_weldid[exclude_body]) continue;
    if (group != 2 && group != robot_group) continue;
    if (m->geom_type[g] == mjGEOM_HFIELD) {
      f.hfields.push_back(g);
    } else if (m->geom_type[g] == mjGEOM_MESH) {
      const int mesh = m->geom_dataid[g];
      std::shared_ptr<const MeshBvh>& bvh = bvh_of_mesh[mesh];
      if (!bvh) {
        bvh = std::make_shared<const MeshBvh>(m->mesh_vert + 3 * m->mesh_vertadr[mesh], m->mesh_vertnum[mesh],
                                              m->mesh_face + 3 * m->mesh_faceadr[mesh], m->mesh_facenum[mesh]);
      }
      f.meshes.push_back(g);
      f.mesh_bvhs.push_back(bvh);
    } else {
      f.geoms.push_back(g);
    }
  }
  return f;
}

namespace detail {

HfieldGrid hfield_grid(const mjModel* m, int geom) {
  const int h = m->geom_dataid[geom];
  const mjtNum* size = m->hfield_size + 4 * h;
  return {m->hfield_nrow[h], m->hfield_ncol[h], size[0], size[1], size[2], size[3], m->hfield_data + m->hfield_adr[h]};
}

namespace {

// The ray in geom g's frame.
void to_geom_frame(const mjData* d, int geom, const mjtNum pnt[3], const mjtNum vec[3], double lp[3], double lv[3]) {
  const mjtNum* pos = d->geom_xpos + 3 * geom;
  const mjtNum* mat = d->geom_xmat + 9 * geom;  // row-major: world axis i . geom axis j at [3 i + j]
  const double dif[3] = {pnt[0] - pos[0], pnt[1] - pos[1], pnt[2] - pos[2]};
  for (int j = 0; j < 3; ++j) {
    lp[j] = mat[j] * dif[0] + mat[3 + j] * dif[1] + mat[6 + j] * dif[2];
    lv[j] = mat[j] * vec[0] + mat[3 + j] * vec[1] + mat[6 + j] * vec[2];
  }
}

// Whether the ray can reach geom g's bounding sphere before `best` (planes: always).
bool may_hit(const mjModel* m, const mjData* d, int g, const mjtNum pnt[3], const mjtNum vec[3], double best) {
  if (m->geom_type[g] == mjGEOM_PLANE) return true;
  const mjtNum* pos = d->geom_xpos + 3 * g;
  const double wx = pos[0] - pnt[0], wy = pos[1] - pnt[1], wz = pos[2] - pnt[2];
  const double tc = wx * vec[0] + wy * vec[1] + wz * vec[2];
  const double rb = m->geom_rbound[g];
  if (tc + rb < 0.0 || tc - rb > best) return false;
  return wx * wx + wy * wy + wz * wz - tc * tc <= rb * rb;
}

}  // namespace

double ray_hfield_geom(const mjModel* m, const mjData* d, int geom, const mjtNum pnt[3], const mjtNum vec[3]) {
  double lp[3], lv[3];
  to_geom_frame(d, geom, pnt, vec, lp, lv);
  return ray_hfield(hfield_grid(m, geom), lp, lv);
}


namespace {

// The unit normal of the plane through the origin that holds every direction (a one-row scan),
// or false when there is none.
bool scan_plane(const description::Vec3* dirs, std::size_t count, double n[3]) {
  if (count < 2) return false;
  const description::Vec3& a = dirs[0];
  // The direction farthest from parallel to the first one spans the plane with it.
  double best = 0.0;
  for (std::size_t i = 1; i < count; ++i) {
    const description::Vec3& b = dirs[i];
    const double c[3] = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (len > best) {
      best = len;
      for (int k = 0; k < 3; ++k) n[k] = c[k] / len;
    }
  }
  if (best < 1e-6) return false;
  for (std::size_t i = 0; i < count; ++i) {
    if (std::abs(dirs[i].x * n[0] + dirs[i].y * n[1] + dirs[i].z * n[2]) > 1e-9) return false;
  }
  return true;
}

// Whether any ray of the call may reach geom g: its bounding sphere within `far` of the origin
// and, for a one-row scan, within its radius of the scan's plane.
bool may_reach(const mjModel* m, const mjData* d, int g, const description::Vec3& origin, double far, const double* plane) {
  if (m->geom_type[g] == mjGEOM_PLANE || m->geom_type[g] == mjGEOM_HFIELD) return true;
  const mjtNum* c = d->geom_xpos + 3 * g;
  const double w[3] = {c[0] - origin.x, c[1] - origin.y, c[2] - origin.z};
  const double rb = m->geom_rbound[g];
  if (std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) - rb > far) return false;
  return plane == nullptr || std::abs(w[0] * plane[0] + w[1] * plane[1] + w[2] * plane[2]) <= rb;
}

}  // namespace

void cast_rays(const mjModel* m, const mjData* d, const RayFilter& filter, const description::Vec3& origin,
               const description::Vec3* directions, std::size_t count, double near, double far, double* ranges,
               int* hit_geoms) {
  // Shape by shape over all rays: a shape no ray can reach is dropped once for the whole call
  // (a planar scan passes by most of a robot). ranges[i] holds ray i's nearest hit so far,
  // measured from its start at `near`; `none` (just beyond far - near) means no hit yet.
  const double reach = far - near;
  const double none = std::nextafter(reach, kInf);
  for (std::size_t i = 0; i < count; ++i) ranges[i] = none;
  if (hit_geoms != nullptr) std::fill(hit_geoms, hit_geoms + count, -1);
  double normal[3];
  const double* plane = scan_plane(directions, count, normal) ? normal : nullptr;
  // Gazebo's rays start at the sensor's minimum range: nothing nearer is seen.
  const auto ray = [&](std::size_t i, mjtNum pnt[3], mjtNum vec[3]) {
    const description::Vec3& u = directions[i];
    vec[0] = u.x;
    vec[1] = u.y;
    vec[2] = u.z;
    pnt[0] = origin.x + near * u.x;
    pnt[1] = origin.y + near * u.y;
    pnt[2] = origin.z + near * u.z;
  };
  const auto keep = [&](std::size_t i, double x, int g) {
    if (x >= 0.0 && x <= reach && x < ranges[i]) {
      ranges[i] = x;
      if (hit_geoms != nullptr) hit_geoms[i] = g;
    }
  };
  mjtNum pnt[3], vec[3];
  for (const int g : filter.geoms) {
    if (!may_reach(m, d, g, origin, far, plane)) continue;
    for (std::size_t i = 0; i < count; ++i) {
      ray(i, pnt, vec);
      if (!may_hit(m, d, g, pnt, vec, std::min(ranges[i], reach))) continue;
      keep(i, mju_rayGeom(d->geom_xpos + 3 * g, d->geom_xmat + 9 * g, m->geom_size + 3 * g, pnt, vec, m->geom_type[g]), g);
    }
  }
  for (std::size_t k = 0; k < filter.meshes.size(); ++k) {
    const int g = filter.meshes[k];
    if (!may_reach(m, d, g, origin, far, plane)) continue;
    for (std::size_t i = 0; i < count; ++i) {
      ray(i, pnt, vec);
      const double best = std::min(ranges[i], reach);
      if (!may_hit(m, d, g, pnt, vec, best)) continue;
      double lp[3], lv[3];
      to_geom_frame(d, g, pnt, vec, lp, lv);
      keep(i, filter.mesh_bvhs[k]->intersect(lp, lv, best), g);
    }
  }
  for (const int g : filter.hfields) {
    for (std::size_t i = 0; i < count; ++i) {
      ray(i, pnt, vec);
      keep(i, ray_hfield_geom(m, d, g, pnt, vec), g);
    }
  }
  for (std::size_t i = 0; i < count; ++i) ranges[i] = ranges[i] <= reach ? near + ranges[i] : kInf;
}

}  // namespace detail
}  // namespace mechsim::physics
