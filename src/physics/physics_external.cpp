// Physics: forces from outside the robot and the instance's gravity (physics.hpp).
#include <algorithm>

#include "physics/physics.hpp"
#include "physics/physics_data.hpp"

namespace mechsim::physics {

using description::Vec3;

void Physics::clear_external_forces() {
  const mjModel* m = data_->m;
  mjData* d = data_->d;
  std::fill(d->xfrc_applied, d->xfrc_applied + 6 * m->nbody, 0.0);
  for (int b : model_->gravity_off_bodies())
    for (int k = 0; k < 3; ++k) d->xfrc_applied[6 * b + k] = -m->body_mass[b] * m->opt.gravity[k];
  data_->xfrc_base.assign(d->xfrc_applied, d->xfrc_applied + 6 * m->nbody);
  std::fill(data_->external_effort.begin(), data_->external_effort.end(), 0.0);
  std::fill(d->qfrc_applied, d->qfrc_applied + m->nv, 0.0);
}

void Physics::add_link_wrench(std::size_t link, const Vec3& f, const Vec3& torque, const Vec3& r) {
  const int b = model_->links()[link].body;
  if (b <= 0) return;  // the world takes no force
  // The same wrench about the centre of mass, where MuJoCo applies xfrc_applied.
  const Vec3 t{torque.x + r.y * f.z - r.z * f.y, torque.y + r.z * f.x - r.x * f.z, torque.z + r.x * f.y - r.y * f.x};
  // Both the applied forces and the base the soil model starts from every step (wheel_soil.cpp).
  for (mjtNum* x : {data_->d->xfrc_applied + 6 * b, data_->xfrc_base.data() + 6 * b}) {
    x[0] += f.x;
    x[1] += f.y;
    x[2] += f.z;
    x[3] += t.x;
    x[4] += t.y;
    x[5] += t.z;
  }
}

void Physics::add_joint_effort(std::size_t joint, double effort) {
  const auto dof = static_cast<std::size_t>(model_->joints()[joint].dof_adr);
  data_->external_effort[dof] += effort;
  data_->d->qfrc_applied[dof] += effort;
}

Vec3 Physics::gravity() const {
  const mjtNum* g = data_->m->opt.gravity;
  return {g[0], g[1], g[2]};
}

void Physics::set_gravity(const Vec3& g_W) {
  mjModel* m = data_->m;
  mjData* d = data_->d;
  // The exempt links' compensation follows the change; other external forces stay.
  for (int b : model_->gravity_off_bodies()) {
    for (mjtNum* x : {d->xfrc_applied + 6 * b, data_->xfrc_base.data() + 6 * b}) {
      x[0] -= m->body_mass[b] * (g_W.x - m->opt.gravity[0]);
      x[1] -= m->body_mass[b] * (g_W.y - m->opt.gravity[1]);
      x[2] -= m->body_mass[b] * (g_W.z - m->opt.gravity[2]);
    }
  }
  m->opt.gravity[0] = g_W.x;
  m->opt.gravity[1] = g_W.y;
  m->opt.gravity[2] = g_W.z;
}

}  // namespace mechsim::physics
