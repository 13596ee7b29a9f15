#include "physics/arena_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "physics/collision_pairs.hpp"
#include "physics/wheel_terrain_contact.hpp"

namespace mechsim::physics {
namespace {

// A geom's axis-aligned bounds in the world frame at the model's reference configuration (qpos0:
// the spawn pose, every joint at 0).
struct GeomBox {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  double axis_z = 1.0;  // world z of the geom's z axis
};

std::vector<GeomBox> geom_bounds(const mjModel& m) {
  std::vector<mjtNum> pos(3 * static_cast<std::size_t>(m.nbody), 0.0), quat(4 * static_cast<std::size_t>(m.nbody), 0.0);
  quat[0] = 1.0;
  for (int b = 1; b < m.nbody; ++b) {  // parents come first
    const int p = m.body_parentid[b];
    mjtNum offset[3];
    mju_rotVecQuat(offset, m.body_pos + 3 * b, quat.data() + 4 * p);
    for (int k = 0; k < 3; ++k) pos[3 * b + k] = pos[3 * p + k] + offset[k];
    mju_mulQuat(quat.data() + 4 * b, quat.data() + 4 * p, m.body_quat + 4 * b);
  }
  std::vector<GeomBox> out(static_cast<std::size_t>(m.ngeom));
  for (int g = 0; g < m.ngeom; ++g) {
    const int b = m.geom_bodyid[g];
    mjtNum p[3], q[4], R[9];
    mju_rotVecQuat(p, m.geom_pos + 3 * g, quat.data() + 4 * b);
    for (int k = 0; k < 3; ++k) p[k] += pos[3 * b + k];
    mju_mulQuat(q, quat.data() + 4 * b, m.geom_quat + 4 * g);
    mju_quat2Mat(R, q);
    const mjtNum* s = m.geom_size + 3 * g;
    GeomBox& out_g = out[static_cast<std::size_t>(g)];
    out_g.axis_z = R[8];
    const int mesh = m.geom_dataid[g];
    if (m.geom_type[g] == mjGEOM_MESH && mesh >= 0 && m.mesh_vertnum[mesh] > 0) {  // exact, from the vertices
      for (int k = 0; k < 3; ++k) out_g.lo[k] = 1e300, out_g.hi[k] = -1e300;
      const float* v = m.mesh_vert + 3 * m.mesh_vertadr[mesh];
      for (int i = 0; i < m.mesh_vertnum[mesh]; ++i, v += 3)
        for (int k = 0; k < 3; ++k) {
          const double w = p[k] + R[3 * k] * v[0] + R[3 * k + 1] * v[1] + R[3 * k + 2] * v[2];
          out_g.lo[k] = std::min(out_g.lo[k], w);
          out_g.hi[k] = std::max(out_g.hi[k], w);
        }
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const double c = std::fabs(R[3 * k + 2]);  // world axis k along the geom's z axis
      double half = m.geom_rbound[g] > 0.0 ? m.geom_rbound[g] : 0.0;
      switch (m.geom_type[g]) {
        case mjGEOM_SPHERE: half = s[0]; break;
        case mjGEOM_CAPSULE: half = s[0] + s[1] * c; break;
        case mjGEOM_CYLINDER: half = s[0] * std::sqrt(std::max(0.0, 1.0 - c * c)) + s[1] * c; break;
        case mjGEOM_ELLIPSOID:
          half = std::sqrt(std::pow(R[3 * k] * s[0], 2) + std::pow(R[3 * k + 1] * s[1], 2) + std::pow(R[3 * k + 2] * s[2], 2));
          break;
        case mjGEOM_BOX: half = std::fabs(R[3 * k]) * s[0] + std::fabs(R[3 * k + 1]) * s[1] + c * s[2]; break;
        default: break;
      }
      out_g.lo[k] = p[k] - half;
      out_g.hi[k] = p[k] + half;
    }
  }
  return out;
}

bool is_ground(const mjModel& m, int g) {
  return m.body_weldid[m.geom_bodyid[g]] == 0 && (m.geom_type[g] == mjGEOM_PLANE || m.geom_type[g] == mjGEOM_HFIELD);
}

// Contacts of geom g resting on ground geom `ground`: MuJoCo 2.2.2's plane functions return up to
// 4 (box, cylinder, convex mesh), 2 (capsule) or 1 (sphere, ellipsoid). On a height field it tests
// the two prisms of every grid cell under the geom and adds a contact per penetrating prism (at
// most mjMAXCONPAIR per pair); a geom meets about half of them (the CC8's wheels on the Mars Yard:
// at most 14 of the 40 prisms under each over the 60 s route; 20 estimated).
int ground_contacts(const mjModel& m, int ground, int g, const GeomBox& b) {
  if (m.geom_type[ground] == mjGEOM_HFIELD && m.geom_type[g] == mjGEOM_CYLINDER &&
      std::fabs(b.axis_z) <= detail::kWheelMaxAxisZ) {
    // mechsim's wheel contact (wheel_terrain_contact.hpp): two rims, and up to two more where a
    // circle touches twice or the middle meets a bulge (the CC8 on the Mars Yard route: at most 3).
    return 4;
  }
  if (m.geom_type[ground] == mjGEOM_HFIELD) {
    const int f = m.geom_dataid[ground];
    if (f < 0) return mjMAXCONPAIR;
    const double dx = 2.0 * m.hfield_size[4 * f] / std::max(1, m.hfield_ncol[f] - 1);
    const double dy = 2.0 * m.hfield_size[4 * f + 1] / std::max(1, m.hfield_nrow[f] - 1);
    const double cells = (std::ceil((b.hi[0] - b.lo[0]) / dx) + 1.0) * (std::ceil((b.hi[1] - b.lo[1]) / dy) + 1.0);
    return static_cast<int>(std::min<double>(mjMAXCONPAIR, cells));
  }
  switch (m.geom_type[g]) {
    case mjGEOM_SPHERE:
    case mjGEOM_ELLIPSOID: return 1;
    case mjGEOM_CAPSULE: return 2;
    default: return 4;
  }
}

// Constraint rows of one contact of the pair: its dimensionality (that of the geom with the
// higher priority, else the larger) as the friction cone realises it.
int rows_per_contact(const mjModel& m, int g1, int g2) {
  const int p1 = m.geom_priority[g1], p2 = m.geom_priority[g2];
  const int condim = p1 > p2   ? m.geom_condim[g1]
                     : p2 > p1 ? m.geom_condim[g2]
                               : std::max(m.geom_condim[g1], m.geom_condim[g2]);
  if (condim <= 1) return 1;
  return m.opt.cone == mjCONE_ELLIPTIC ? condim : 2 * (condim - 1);
}

}  // namespace

ArenaEstimate estimate_arena(const mjModel& m) {
  ArenaEstimate e;
  if ((m.opt.disableflags & mjDSBL_CONTACT) == 0) {
    // A movable body tree (the robot, a free box) rests on the ground with its lowest geoms, those
    // within kSupportBand of its lowest point at the spawn pose: each makes what its shape makes on
    // the ground. Any other pair that can touch (an arm reaching down, the robot and the objects,
    // objects on each other, self-collision) counts one contact, and a movable geom touches at
    // most kTouchesPerGeom things at once (so that n free boxes count O(n), not O(n^2)).
    constexpr double kSupportBand = 0.02;  // m
    constexpr int kTouchesPerGeom = 8;
    const std::vector<GeomBox> bounds = geom_bounds(m);
    std::vector<double> lowest(static_cast<std::size_t>(m.nbody), 1e300);
    int movable = 0;
    for (int g = 0; g < m.ngeom; ++g) {
      const int b = m.geom_bodyid[g];
      if ((m.geom_contype[g] == 0 && m.geom_conaffinity[g] == 0) || m.body_weldid[b] == 0) continue;
      ++movable;
      double& low = lowest[static_cast<std::size_t>(m.body_rootid[b])];
      low = std::min(low, bounds[static_cast<std::size_t>(g)].lo[2]);
    }
    auto supports = [&](int g) {
      const int b = m.geom_bodyid[g];
      return m.body_weldid[b] != 0 &&
             bounds[static_cast<std::size_t>(g)].lo[2] <= lowest[static_cast<std::size_t>(m.body_rootid[b])] + kSupportBand;
    };
    int touches = 0, touch_rows = 0;
    auto add_pair = [&](int g1, int g2) {
      ++e.candidate_pairs;
      const int rows = rows_per_contact(m, g1, g2);
      if (is_ground(m, g2)) std::swap(g1, g2);
      if (is_ground(m, g1) && supports(g2)) {
        const int n = ground_contacts(m, g1, g2, bounds[static_cast<std::size_t>(g2)]);
        e.contacts += n;
        e.contact_rows += n * rows;
        ++e.support_geoms;
      } else {
        ++touches;
        touch_rows = std::max(touch_rows, rows);
      }
    };
    // MuJoCo's broad phase (collision "dynamic", or "all" with the predefined pairs too) and its
    // predefined pairs (collision "pair": mechsim's listed pairs, StepCost::listed_pairs).
    if (m.opt.collision != mjCOL_PAIR)
      for (int g1 = 0; g1 < m.ngeom; ++g1)
        for (int g2 = g1 + 1; g2 < m.ngeom; ++g2)
          if (filters_let_touch(m, g1, g2)) add_pair(g1, g2);
    if (m.opt.collision != mjCOL_DYNAMIC)
      for (int p = 0; p < m.npair; ++p) add_pair(m.pair_geom1[p], m.pair_geom2[p]);
    touches = std::min(touches, kTouchesPerGeom * movable / 2);
    e.contacts += touches;
    e.contact_rows += touches * touch_rows;
  }
  if ((m.opt.disableflags & mjDSBL_LIMIT) == 0) {
    for (int j = 0; j < m.njnt; ++j)
      if (m.jnt_limited[j]) e.other_rows += m.jnt_margin[j] > 0.0 ? 2 : 1;  // a margin can activate both sides
    for (int t = 0; t < m.ntendon; ++t)
      if (m.tendon_limited[t]) e.other_rows += 1;
  }
  if ((m.opt.disableflags & mjDSBL_FRICTIONLOSS) == 0) {
    for (int v = 0; v < m.nv; ++v)
      if (m.dof_frictionloss[v] > 0.0) e.other_rows += 1;
    for (int t = 0; t < m.ntendon; ++t)
      if (m.tendon_frictionloss[t] > 0.0) e.other_rows += 1;
  }
  if ((m.opt.disableflags & mjDSBL_EQUALITY) == 0) {
    for (int q = 0; q < m.neq; ++q)
      e.other_rows += m.eq_type[q] == mjEQ_CONNECT ? 3 : m.eq_type[q] == mjEQ_WELD ? 6 : 1;
  }
  // Margin: a quarter more, and a floor for small models. Memory, and the time to allocate it,
  // go with constraints^2 (page faults dominated start-up), and a run that needs more grows the
  // arena and recomputes the step (ArenaOverflow::Grow): the estimate aims at what a run uses,
  // not at everything touching at once.
  e.size.contacts = e.contacts + e.contacts / 4 + 8;
  const int rows = e.contact_rows + e.other_rows;
  e.size.constraints = rows + rows / 4 + 16;
  return e;
}

void set_arena(mjModel& m, const ArenaSize& size, long stack_residual) {
  m.nconmax = size.contacts;
  m.njmax = size.constraints;
  const long side = static_cast<long>(size.constraints) + m.nv;
  m.nstack = static_cast<int>(std::max(1000L, 5 * side * side + stack_residual));
}

}  // namespace mechsim::physics
