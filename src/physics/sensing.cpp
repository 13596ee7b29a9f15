// Accelerations and joint wrenches for sensors, from MuJoCo's post-constraint recursive
// Newton-Euler pass (mj_rnePostConstraint: body accelerations with the constraint forces of the
// last step, and the forces bodies exchange with their parents).
#include "physics/sensing_internal.hpp"

namespace mechsim::physics::detail {

namespace {

void cross(const mjtNum a[3], const mjtNum b[3], mjtNum out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

Acceleration point_acceleration(const mjModel* m, mjData* d, int body, const description::Vec3& p_W) {
  mj_rnePostConstraint(m, d);
  // cacc and cvel are spatial (angular; linear) at the root subtree's centre of mass. MuJoCo
  // starts the recursion from the world at -gravity, so cacc's linear part is the specific force
  // (acceleration minus gravity): what an accelerometer measures.
  const mjtNum p[3] = {p_W.x, p_W.y, p_W.z};
  const mjtNum* com = d->subtree_com + 3 * m->body_rootid[body];
  mjtNum acc[6], vel[6], coriolis[3];
  mju_transformSpatial(acc, d->cacc + 6 * body, 0, p, com, nullptr);
  mju_transformSpatial(vel, d->cvel + 6 * body, 0, p, com, nullptr);
  // Spatial to classical acceleration of the point: + omega x v.
  cross(vel, vel + 3, coriolis);
  return {{acc[0], acc[1], acc[2]}, {acc[3] + coriolis[0], acc[4] + coriolis[1], acc[5] + coriolis[2]}};
}

Wrench wrench_from_parent(const mjModel* m, mjData* d, int body, const description::Vec3& p_W) {
  mj_rnePostConstraint(m, d);
  // cfrc_int: the spatial force (torque; force) the parent applies on the body's subtree, at the
  // root subtree's centre of mass; moved to p.
  const mjtNum p[3] = {p_W.x, p_W.y, p_W.z};
  mjtNum f[6];
  mju_transformSpatial(f, d->cfrc_int + 6 * body, 1, p, d->subtree_com + 3 * m->body_rootid[body], nullptr);
  return {{f[3], f[4], f[5]}, {f[0], f[1], f[2]}};
}

}  // namespace mechsim::physics::detail
