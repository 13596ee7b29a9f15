// Physics: MuJoCo's per-instance arena (growing it exactly on overflow, or failing) and the
// warnings MuJoCo raises in a step (physics/README.md, "Arena").
#include <algorithm>
#include <string>

#include "physics/arena_estimate.hpp"
#include "physics/physics_data.hpp"

namespace mechsim::physics {

using detail::copy_n;
using detail::joint_of_dof;

void Physics::save_state() {
  const mjModel* m = data_->m;
  const mjData* d = data_->d;
  data_->saved_time = d->time;
  copy_n(data_->saved_qpos.data(), d->qpos, m->nq);
  copy_n(data_->saved_qvel.data(), d->qvel, m->nv);
  copy_n(data_->saved_act.data(), d->act, m->na);
  copy_n(data_->saved_warm.data(), d->qacc_warmstart, m->nv);
  for (int w = 0; w < mjNWARNING; ++w) data_->saved_warnings[w] = d->warning[w].number;
}

bool Physics::compute_in_arena(bool step) {
  for (;;) {
    if (step) mujoco_step();
    else mj_forward(data_->m, data_->d);
    const mjData* d = data_->d;
    const bool contacts_full = d->warning[mjWARN_CONTACTFULL].number != data_->saved_warnings[mjWARN_CONTACTFULL];
    const bool constraints_full = d->warning[mjWARN_CNSTRFULL].number != data_->saved_warnings[mjWARN_CNSTRFULL];
    if (!contacts_full && !constraints_full) return true;
    // MuJoCo dropped contacts or constraints: that is not the physics. Grow and compute again
    // from the saved state, or fail.
    if (model_->options().arena_overflow == ArenaOverflow::Fail || !grow_arena(contacts_full, constraints_full, step ? "step" : "state"))
      return false;
  }
}

void Physics::forward() {
  ensure_constants();
  // mj_forward also leaves the solver's warm start for the next step (qacc_warmstart): computed
  // with dropped contacts, it would start that step elsewhere. So it too grows the arena.
  save_state();
  compute_in_arena(false);
  data_->stale = false;
}

void Physics::restore_saved_state() {
  const mjModel* m = data_->m;
  mjData* d = data_->d;
  d->time = data_->saved_time;
  copy_n(d->qpos, data_->saved_qpos.data(), m->nq);
  copy_n(d->qvel, data_->saved_qvel.data(), m->nv);
  copy_n(d->act, data_->saved_act.data(), m->na);
  copy_n(d->qacc_warmstart, data_->saved_warm.data(), m->nv);
}

bool Physics::grow_arena(bool contacts_full, bool constraints_full, const char* what) {
  mjModel* m = data_->m;
  const ArenaSize before = arena_of(*m);
  const ArenaSize most = model_->options().max_arena;
  ArenaSize next = before;
  if (contacts_full) next.contacts = std::min(most.contacts, 2 * before.contacts);
  if (constraints_full) next.constraints = std::min(most.constraints, 2 * before.constraints);
  if ((contacts_full && next.contacts == before.contacts) || (constraints_full && next.constraints == before.constraints))
    return false;

  // A new mjData of the new size (MuJoCo 2.2.2 sizes its arrays from the model's nconmax/njmax at
  // mj_makeData), holding the state from before the step: what mj_step reads.
  mjData* old = data_->d;
  const ArenaUse use = arena_use();
  set_arena(*m, next, model_->impl().stack_residual);
  mjData* d = mj_makeData(m);
  data_->d = d;
  restore_saved_state();
  copy_n(d->ctrl, old->ctrl, m->nu);
  copy_n(d->qfrc_applied, old->qfrc_applied, m->nv);
  copy_n(d->xfrc_applied, old->xfrc_applied, 6 * m->nbody);
  copy_n(d->mocap_pos, old->mocap_pos, 3 * m->nmocap);
  copy_n(d->mocap_quat, old->mocap_quat, 4 * m->nmocap);
  copy_n(d->userdata, old->userdata, m->nuserdata);
  for (int w = 0; w < mjNWARNING; ++w) {
    d->warning[w] = old->warning[w];
    d->warning[w].number = data_->saved_warnings[w];
  }
  mj_deleteData(old);
  data_->peak = use.peak;
  ++data_->growths;

  PhysicsNotice n;
  n.kind = PhysicsNotice::Kind::ArenaGrown;
  n.time = data_->saved_time;
  n.text = std::string("MuJoCo's ") + (contacts_full ? "contact list" : "constraint arena") + " was full (" +
           std::to_string(contacts_full ? before.contacts : before.constraints) +
           (contacts_full ? " contacts" : " constraint rows") + "): the arena grew from " +
           std::to_string(before.contacts) + " contacts / " + std::to_string(before.constraints) + " rows to " +
           std::to_string(next.contacts) + " / " + std::to_string(next.constraints) + " and the " + what +
           " was computed again";
  notices_.push_back(std::move(n));
  return true;
}

void Physics::note_mujoco_warnings() {
  const mjModel* m = data_->m;
  const mjData* d = data_->d;
  for (int w = 0; w < mjNWARNING; ++w) {
    // Bad state fails the step and a full arena grows it (above); the rest are reported.
    if (w == mjWARN_BADQPOS || w == mjWARN_BADQVEL || w == mjWARN_BADQACC || w == mjWARN_CONTACTFULL ||
        w == mjWARN_CNSTRFULL || d->warning[w].number == data_->saved_warnings[w])
      continue;
    int& index = data_->warning_notice[w];
    if (index > 0) {
      ++notices_[static_cast<std::size_t>(index - 1)].count;
      continue;
    }
    PhysicsNotice n;
    n.time = data_->saved_time;
    n.text = std::string("MuJoCo warning: ") + mju_warningText(w, d->warning[w].lastinfo);
    if (w == mjWARN_INERTIA) n.text += " (joint '" + std::string(joint_of_dof(m, d->warning[w].lastinfo)) + "')";
    notices_.push_back(std::move(n));
    index = static_cast<int>(notices_.size());
  }
}

ArenaUse Physics::arena_use() const {
  const mjData* d = data_->d;
  ArenaUse u;
  u.size = arena_of(*data_->m);
  u.peak = {std::max(data_->peak.contacts, d->maxuse_con), std::max(data_->peak.constraints, d->maxuse_efc)};
  u.growths = data_->growths;
  return u;
}

}  // namespace mechsim::physics
