// Physics::take_state_from: a world rebuilt with another set of robots goes on where the old one
// was (physics.hpp).
#include "physics/physics.hpp"
#include "physics/physics_data.hpp"

namespace mechsim::physics {
namespace {

int qpos_size(int type) { return type == mjJNT_FREE ? 7 : type == mjJNT_BALL ? 4 : 1; }
int dof_size(int type) { return type == mjJNT_FREE ? 6 : type == mjJNT_BALL ? 3 : 1; }

}  // namespace

void Physics::take_state_from(const Physics& old) {
  const mjModel* om = old.data_->m;
  const mjData* od = old.data_->d;
  mjModel* m = data_->m;
  mjData* d = data_->d;
  set_gravity(old.gravity());  // before the soil: it moves the gravity-off forces
  d->time = od->time;
  // Every body of both, by name: its joints in order.
  for (int b = 1; b < m->nbody; ++b) {
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    const int ob = name != nullptr ? mj_name2id(om, mjOBJ_BODY, name) : -1;
    if (ob < 1 || om->body_jntnum[ob] != m->body_jntnum[b]) continue;
    for (int k = 0; k < m->body_jntnum[b]; ++k) {
      const int j = m->body_jntadr[b] + k, oj = om->body_jntadr[ob] + k;
      if (m->jnt_type[j] != om->jnt_type[oj]) continue;
      const int nq = qpos_size(m->jnt_type[j]);
      detail::copy_n(d->qpos + m->jnt_qposadr[j], od->qpos + om->jnt_qposadr[oj], nq);
      // The spawn state too (set_spawn_pose moves a floating root's): where reset() returns.
      for (int q = 0; q < nq; ++q) {
        mjtNum& q0 = m->qpos0[m->jnt_qposadr[j] + q];
        if (q0 != om->qpos0[om->jnt_qposadr[oj] + q]) {
          q0 = om->qpos0[om->jnt_qposadr[oj] + q];
          data_->constants_stale = true;
        }
      }
      const int nv = dof_size(m->jnt_type[j]);
      detail::copy_n(d->qvel + m->jnt_dofadr[j], od->qvel + om->jnt_dofadr[oj], nv);
      detail::copy_n(d->qacc_warmstart + m->jnt_dofadr[j], od->qacc_warmstart + om->jnt_dofadr[oj], nv);
    }
  }
  // Every 1-DOF joint of both, by name: its drive as the old physics had it.
  const std::vector<JointInfo>& joints = model_->joints();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto oi = old.model_->joint_index(joints[i].name);
    if (!oi) continue;
    const JointInfo& nj = joints[i];
    const JointInfo& oj = old.model_->joints()[*oi];
    if (m->dof_armature[nj.dof_adr] != om->dof_armature[oj.dof_adr]) {
      m->dof_armature[nj.dof_adr] = om->dof_armature[oj.dof_adr];
      data_->constants_stale = true;
    }
    if (nj.actuator < 0 || oj.actuator < 0) continue;
    const int a = nj.actuator, oa = oj.actuator;
    m->actuator_forcelimited[a] = om->actuator_forcelimited[oa];
    detail::copy_n(m->actuator_forcerange + 2 * a, om->actuator_forcerange + 2 * oa, 2);
    detail::copy_n(m->actuator_gainprm + a * mjNGAIN, om->actuator_gainprm + oa * mjNGAIN, mjNGAIN);
    detail::copy_n(m->actuator_biasprm + a * mjNBIAS, om->actuator_biasprm + oa * mjNBIAS, mjNBIAS);
    d->ctrl[a] = od->ctrl[oa];
    data_->modes[i] = old.data_->modes[*oi];
    data_->gains[i] = old.data_->gains[*oi];
    data_->motor_integral[i] = old.data_->motor_integral[*oi];
  }
  // The soil and the world's word on wheels (those of a robot deleted since dropped), and every
  // wheel of both (by link) where it was in it.
  std::vector<WheelOverride> overrides;
  for (const WheelOverride& o : old.data_->soil_overrides)
    if (model_->link_index(o.link)) overrides.push_back(o);
  set_soil(old.data_->soil, std::move(overrides));
  const std::vector<SoilWheelInfo>& old_wheels = old.data_->soil_wheels;
  for (std::size_t w = 0; w < data_->soil_state.size(); ++w) {
    for (std::size_t o = 0; o < old.data_->soil_state.size() && o < old_wheels.size(); ++o) {
      if (old_wheels[o].link != data_->soil_wheels[w].link) continue;
      data_->soil_state[w] = old.data_->soil_state[o];
      data_->soil_readings[w] = old.data_->soil_readings[o];
    }
  }
  data_->ruts = old.data_->ruts;
  data_->stale = true;
  ensure_constants();
  forward();
}

}  // namespace mechsim::physics
