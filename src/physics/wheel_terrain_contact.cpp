// The wheel-height field contact (wheel_terrain_contact.hpp).
#include "physics/wheel_terrain_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "physics/hfield_surface.hpp"
#include "physics/mujoco_internal.hpp"
#include "physics/sensing_internal.hpp"

namespace mechsim::physics::detail {
namespace {

constexpr int kSamples = 9;                   // along the lower arc
constexpr double kStep = 20.0 * M_PI / 180.0;  // rad between samples: 3.1 cm of a 9 cm wheel's rim
constexpr double kFirst = -0.5 * (kSamples - 1) * kStep;
constexpr double kNone = -std::numeric_limits<double>::infinity();
// How much deeper than the rims' average (m) the middle circle must reach to count.
constexpr double kBulge = 0.001;

struct Arc {
  const double* c;
  double d[3], f[3];  // unit: straight down in the circle's plane, and forward (a x d)
  double r;
  void point(double cs, double sn, double p[3]) const {
    for (int i = 0; i < 3; ++i) p[i] = c[i] + r * (cs * d[i] + sn * f[i]);
  }
};

// The (cos, sin) of each sample's angle from straight down.
struct ArcAngles {
  double cs[kSamples], sn[kSamples];
  ArcAngles() {
    for (int k = 0; k < kSamples; ++k) {
      cs[k] = std::cos(kFirst + k * kStep);
      sn[k] = std::sin(kFirst + k * kStep);
    }
  }
};

const ArcAngles& arc_angles() {
  static const ArcAngles angles;
  return angles;
}

// The face contact of the circle with the triangle under surface point s: the circle's point
// deepest along the triangle's normal, when that point lies over the same triangle.
bool face_contact(const HfieldSurface& surface, const Arc& arc, const double a[3], const SurfacePoint& s, RimContact& rc) {
  const double* n = s.normal;
  const double na = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
  const double e[3] = {n[0] - na * a[0], n[1] - na * a[1], n[2] - na * a[2]};
  const double en = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  if (en < 1e-9) return false;
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = arc.c[i] - arc.r * e[i] / en;
  SurfacePoint sq;
  if (!surface.at(q[0], q[1], sq) || sq.triangle != s.triangle) return false;
  for (int i = 0; i < 3; ++i) rc.point[i] = q[i];
  for (int i = 0; i < 3; ++i) rc.normal[i] = sq.normal[i];
  rc.gap = sq.height - q[2];
  rc.depth = rc.gap * sq.normal[2];
  return true;
}

// The contact at the circle's point p, `gap` below the surface vertically, with the wheel's own
// normal there: radial, from p towards the centre (a ridge or corner against the rim, anything
// against the tread's middle, whose surface normal is radial).
RimContact radial_contact(const Arc& arc, const double p[3], double gap) {
  RimContact rc;
  for (int i = 0; i < 3; ++i) {
    rc.point[i] = p[i];
    rc.normal[i] = (arc.c[i] - p[i]) / arc.r;
  }
  rc.gap = gap;
  rc.depth = gap * rc.normal[2];
  return rc;
}

}  // namespace

int rim_contacts(const HfieldSurface& surface, const double c[3], const double a[3], double r, double margin,
                 bool tread, RimContact out[2]) {
  Arc arc{c, {a[2] * a[0], a[2] * a[1], a[2] * a[2] - 1.0}, {0, 0, 0}, r};
  const double dn = std::sqrt(arc.d[0] * arc.d[0] + arc.d[1] * arc.d[1] + arc.d[2] * arc.d[2]);
  if (dn < 1e-9) return 0;
  for (double& v : arc.d) v /= dn;
  arc.f[0] = a[1] * arc.d[2] - a[2] * arc.d[1];
  arc.f[1] = a[2] * arc.d[0] - a[0] * arc.d[2];
  arc.f[2] = a[0] * arc.d[1] - a[1] * arc.d[0];

  const ArcAngles& ang = arc_angles();
  double gap[kSamples];
  for (int k = 0; k < kSamples; ++k) {
    double p[3], h;
    arc.point(ang.cs[k], ang.sn[k], p);
    gap[k] = surface.height(p[0], p[1], h) ? h - p[2] : kNone;
  }

  // Local maxima of the vertical gap that may come within the margin once refined: the samples
  // miss a plane's deepest point by at most r (1 - cos(step / 2)), and the penetration along a
  // surface's normal is the vertical gap times the normal's z (up to 80 degree slopes here).
  const double slack = (margin + r * (1.0 - std::cos(0.5 * kStep)) + 0.005) / 0.17;
  int best[2] = {-1, -1};
  for (int k = 0; k < kSamples; ++k) {
    if (gap[k] < -slack) continue;  // kNone too
    if (k > 0 && gap[k - 1] > gap[k]) continue;
    if (k + 1 < kSamples && gap[k + 1] >= gap[k]) continue;
    if (best[0] < 0 || gap[k] > gap[best[0]]) {
      best[1] = best[0];
      best[0] = k;
    } else if (best[1] < 0 || gap[k] > gap[best[1]]) {
      best[1] = k;
    }
  }

  int n = 0;
  for (const int k : best) {
    if (k < 0) continue;
    double p[3];
    SurfacePoint s;
    arc.point(ang.cs[k], ang.sn[k], p);
    surface.at(p[0], p[1], s);
    RimContact rc;
    if (tread || !face_contact(surface, arc, a, s, rc)) {
      // Across a triangle edge (or the tread's middle): the vertex of the parabola through the
      // neighbouring samples, with the wheel's normal.
      rc = radial_contact(arc, p, gap[k]);
      if (k > 0 && k + 1 < kSamples && gap[k - 1] != kNone && gap[k + 1] != kNone) {
        const double den = gap[k - 1] - 2.0 * gap[k] + gap[k + 1];
        if (den < -1e-12) {
          const double phi = kFirst + kStep * (k + 0.5 * std::fmax(-1.0, std::fmin(1.0, (gap[k - 1] - gap[k + 1]) / den)));
          double pr[3], h;
          arc.point(std::cos(phi), std::sin(phi), pr);
          if (surface.height(pr[0], pr[1], h) && h - pr[2] > gap[k]) {
            const RimContact refined = radial_contact(arc, pr, h - pr[2]);
            if (refined.depth > rc.depth) rc = refined;
          }
        }
      }
    }
    if (rc.depth <= -margin) continue;
    if (n == 1 && std::fabs(rc.point[0] - out[0].point[0]) + std::fabs(rc.point[1] - out[0].point[1]) < 1e-9)
      continue;  // both maxima led to the same face contact
    if (n == 1 && rc.depth > out[0].depth) {
      out[1] = out[0];
      out[0] = rc;
    } else {
      out[n] = rc;
    }
    ++n;
  }
  return n;
}

namespace {

// MuJoCo's own routine for a geom of type1 against one of type2, kept by install below (the
// height field-cylinder one for cylinders standing on a flat end).
template <int type1, int type2>
mjfCollision mujoco_routine() {
  static const mjfCollision original = mjCOLLISIONFUNC[type1][type2];
  return original;
}

template <int type>
mjfCollision mujoco_hfield_routine() {
  return mujoco_routine<mjGEOM_HFIELD, type>();
}

// The depth (m) below the ground where geom g's rigid contact with it starts: a soil wheel's
// bedrock (Physics::set_soil writes it into the geom's user number), 0 on rigid ground.
double bedrock(const mjModel* m, int g) { return m->nuser_geom > 0 ? m->geom_user[g * m->nuser_geom] : 0.0; }

// Contacts con[0, n) of geom g with the ground moved down to its bedrock (a soil wheel's; none
// for any other geom): those not that deep are dropped. Returns how many are left.
int to_bedrock(const mjModel* m, int g, mjContact* con, int n, mjtNum margin) {
  const double depth = bedrock(m, g);
  if (depth <= 0.0) return n;
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    if (con[i].dist + depth >= margin) continue;
    con[kept] = con[i];
    con[kept].dist += depth;
    ++kept;
  }
  return kept;
}

// MuJoCo's plane routine for a geom of `type`, its contacts moved down to a soil wheel's bedrock
// (a wide wheel is a cylinder, a narrow one an ellipsoid, a wheel the world names may be any shape).
template <int type>
int collide_plane_bedrock(const mjModel* m, const mjData* d, mjContact* con, int g1, int g2, mjtNum margin) {
  return to_bedrock(m, g2, con, mujoco_routine<mjGEOM_PLANE, type>()(m, d, con, g1, g2, margin), margin);
}

// The geom's centre c and the half extents of its box aligned with the height field's frame.
void box_in_hfield(const mjModel* m, const mjData* d, int g1, int g2, mjtNum margin, double c[3], double half[3]) {
  const mjtNum* pos1 = d->geom_xpos + 3 * g1;
  const mjtNum* mat1 = d->geom_xmat + 9 * g1;  // row-major: world = mat1 * local
  const mjtNum* pos2 = d->geom_xpos + 3 * g2;
  const mjtNum* mat2 = d->geom_xmat + 9 * g2;
  const double dif[3] = {pos2[0] - pos1[0], pos2[1] - pos1[1], pos2[2] - pos1[2]};
  double R[9];  // the geom's axes in the height field's frame, row-major
  for (int i = 0; i < 3; ++i) {
    c[i] = mat1[i] * dif[0] + mat1[3 + i] * dif[1] + mat1[6 + i] * dif[2];
    for (int j = 0; j < 3; ++j) R[3 * i + j] = mat1[i] * mat2[j] + mat1[3 + i] * mat2[3 + j] + mat1[6 + i] * mat2[6 + j];
  }
  const mjtNum* s = m->geom_size + 3 * g2;
  for (int i = 0; i < 3; ++i) {
    const double* Ri = R + 3 * i;
    const double az = std::fabs(Ri[2]);
    switch (m->geom_type[g2]) {
      case mjGEOM_SPHERE: half[i] = s[0]; break;
      case mjGEOM_CAPSULE: half[i] = az * s[1] + s[0]; break;
      case mjGEOM_CYLINDER: half[i] = az * s[1] + s[0] * std::sqrt(std::fmax(0.0, 1.0 - az * az)); break;
      case mjGEOM_ELLIPSOID:
        half[i] = std::sqrt(Ri[0] * Ri[0] * s[0] * s[0] + Ri[1] * Ri[1] * s[1] * s[1] + Ri[2] * Ri[2] * s[2] * s[2]);
        break;
      case mjGEOM_BOX: half[i] = std::fabs(Ri[0]) * s[0] + std::fabs(Ri[1]) * s[1] + az * s[2]; break;
      default: half[i] = m->geom_rbound[g2]; break;
    }
    half[i] += margin;
  }
}

// Whether the box (centre c, half extents `half`; height-field frame) is clear of the surface:
// above every sample under its footprint (the surface's highest points over a region are
// samples), or beyond the footprint altogether.
bool clear_of_surface(const HfieldSurface& surface, const double c[3], const double half[3]) {
  const HfieldGrid& g = surface.g;
  const double z_low = c[2] - half[2];
  if (z_low > g.top) return true;
  const int c0 = std::max(0, static_cast<int>(std::floor((c[0] - half[0] + g.half_x) * surface.inv_dx)));
  const int c1 = std::min(g.cols - 1, static_cast<int>(std::ceil((c[0] + half[0] + g.half_x) * surface.inv_dx)));
  const int r0 = std::max(0, static_cast<int>(std::floor((c[1] - half[1] + g.half_y) * surface.inv_dy)));
  const int r1 = std::min(g.rows - 1, static_cast<int>(std::ceil((c[1] + half[1] + g.half_y) * surface.inv_dy)));
  if (c0 > c1 || r0 > r1) return true;
  const float limit = static_cast<float>(z_low / g.top);
  for (int r = r0; r <= r1; ++r) {
    const float* row = g.data + static_cast<long>(r) * g.cols;
    for (int col = c0; col <= c1; ++col)
      if (row[col] >= limit) return false;
  }
  return true;
}

// MuJoCo's routine for other convex geoms, after a cheap test: MuJoCo 2.2.2 walks every prism
// under the geom's box even when the geom is far above them (the CC8's chassis and forks: half of
// the step went into walking prisms under geoms that touched nothing).
template <int type>
int collide_hfield_convex(const mjModel* m, const mjData* d, mjContact* con, int g1, int g2, mjtNum margin) {
  double c[3], half[3];
  box_in_hfield(m, d, g1, g2, margin, c, half);
  if (clear_of_surface(HfieldSurface(hfield_grid(m, g1)), c, half)) return 0;
  return to_bedrock(m, g2, con, mujoco_hfield_routine<type>()(m, d, con, g1, g2, margin), margin);
}

// mjCOLLISIONFUNC's signature: geom g1 is the height field, g2 the cylinder; fills con[] with
// contacts whose normal points from g1 to g2, at the middle of the overlap. Returns their number.
int collide_hfield_cylinder(const mjModel* m, const mjData* d, mjContact* con, int g1, int g2, mjtNum margin) {
  const mjtNum* pos1 = d->geom_xpos + 3 * g1;
  const mjtNum* mat1 = d->geom_xmat + 9 * g1;  // row-major: world = mat1 * local
  const mjtNum* mat2 = d->geom_xmat + 9 * g2;
  double c[3], extent[3], a[3];  // centre, box half extents and axis in the height field's frame
  box_in_hfield(m, d, g1, g2, margin, c, extent);
  for (int j = 0; j < 3; ++j) a[j] = mat1[j] * mat2[2] + mat1[3 + j] * mat2[5] + mat1[6 + j] * mat2[8];
  const HfieldSurface surface(hfield_grid(m, g1));
  if (clear_of_surface(surface, c, extent)) return 0;
  if (std::fabs(a[2]) > kWheelMaxAxisZ) return mujoco_hfield_routine<mjGEOM_CYLINDER>()(m, d, con, g1, g2, margin);
  const double r = m->geom_size[3 * g2], half = m->geom_size[3 * g2 + 1];

  // The two rims, then the middle circle. The middle's contacts count only where the surface
  // bulges between the rims (a rock narrower than the tread): on a plane they would only repeat
  // what the rims hold, at the constraint solver's cost.
  RimContact rc[3][2];
  int count[3];
  const double offset[3] = {-half, half, 0.0};
  for (int i = 0; i < 3; ++i) {
    const double cs[3] = {c[0] + offset[i] * a[0], c[1] + offset[i] * a[1], c[2] + offset[i] * a[2]};
    count[i] = rim_contacts(surface, cs, a, r, r, i == 2, rc[i]);  // every maximum within r, filtered below
  }
  const auto deepest = [&](int i) { return count[i] > 0 ? rc[i][0].gap : -r; };
  const double between = 0.5 * (deepest(0) + deepest(1)) + kBulge;

  const double soil = bedrock(m, g2);
  int n = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < count[i] && n < mjMAXCONPAIR; ++k) {
      const RimContact& h = rc[i][k];
      if (h.depth - soil <= -margin || (i == 2 && h.gap <= between)) continue;
      mjContact& out = con[n++];
      out.dist = soil - h.depth;
      const double mid[3] = {h.point[0] + 0.5 * h.depth * h.normal[0], h.point[1] + 0.5 * h.depth * h.normal[1],
                             h.point[2] + 0.5 * h.depth * h.normal[2]};
      for (int j = 0; j < 3; ++j) {
        out.pos[j] = pos1[j] + mat1[3 * j] * mid[0] + mat1[3 * j + 1] * mid[1] + mat1[3 * j + 2] * mid[2];
        out.frame[j] = mat1[3 * j] * h.normal[0] + mat1[3 * j + 1] * h.normal[1] + mat1[3 * j + 2] * h.normal[2];
        out.frame[3 + j] = 0.0;  // MuJoCo completes the tangent frame
      }
    }
  return n;
}

}  // namespace

void install_wheel_terrain_contact() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Keep MuJoCo's routines before replacing them.
    (void)mujoco_hfield_routine<mjGEOM_SPHERE>();
    (void)mujoco_hfield_routine<mjGEOM_CAPSULE>();
    (void)mujoco_hfield_routine<mjGEOM_ELLIPSOID>();
    (void)mujoco_hfield_routine<mjGEOM_CYLINDER>();
    (void)mujoco_hfield_routine<mjGEOM_BOX>();
    (void)mujoco_hfield_routine<mjGEOM_MESH>();
    mjCOLLISIONFUNC[mjGEOM_HFIELD][mjGEOM_SPHERE] = collide_hfield_convex<mjGEOM_SPHERE>;
    mjCOLLISIONFUNC[mjGEOM_HFIELD][mjGEOM_CAPSULE] = collide_hfield_convex<mjGEOM_CAPSULE>;
    mjCOLLISIONFUNC[mjGEOM_HFIELD][mjGEOM_ELLIPSOID] = collide_hfield_convex<mjGEOM_ELLIPSOID>;
    mjCOLLISIONFUNC[mjGEOM_HFIELD][mjGEOM_CYLINDER] = collide_hfield_cylinder;
    mjCOLLISIONFUNC[mjGEOM_HFIELD][mjGEOM_BOX] = collide_hfield_convex<mjGEOM_BOX>;
    mjCOLLISIONFUNC[mjGEOM_HFIELD][mjGEOM_MESH] = collide_hfield_convex<mjGEOM_MESH>;
    (void)mujoco_routine<mjGEOM_PLANE, mjGEOM_SPHERE>();
    (void)mujoco_routine<mjGEOM_PLANE, mjGEOM_CAPSULE>();
    (void)mujoco_routine<mjGEOM_PLANE, mjGEOM_ELLIPSOID>();
    (void)mujoco_routine<mjGEOM_PLANE, mjGEOM_CYLINDER>();
    (void)mujoco_routine<mjGEOM_PLANE, mjGEOM_BOX>();
    (void)mujoco_routine<mjGEOM_PLANE, mjGEOM_MESH>();
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_SPHERE] = collide_plane_bedrock<mjGEOM_SPHERE>;
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CAPSULE] = collide_plane_bedrock<mjGEOM_CAPSULE>;
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_ELLIPSOID] = collide_plane_bedrock<mjGEOM_ELLIPSOID>;
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER] = collide_plane_bedrock<mjGEOM_CYLINDER>;
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_BOX] = collide_plane_bedrock<mjGEOM_BOX>;
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_MESH] = collide_plane_bedrock<mjGEOM_MESH>;
  });
}

}  // namespace mechsim::physics::detail
