// Physics: the step with Cartesian body forces turned into joint forces in one pass over the body
// tree (StepCost::tree_external_forces).
//
// MuJoCo 2.2.2 applies xfrc_applied in mj_fwdAcceleration with mj_applyFT for every body whose
// wrench is non-zero: a dense 3 x nv Jacobian (zeroed, filled along the body's chain) and two dense
// transposed products each. The PR2's 40 gravity-off links cost a tenth of its step that way. The
// same generalised force is J^T F summed over bodies, which one backward pass gathers: each body's
// wrench moved to its tree's reference point (MuJoCo's com-based frame, subtree_com of the root),
// summed into its parent, and each DOF takes its motion axis (cdof) dotted with the wrench of the
// subtree it moves. The sums are the same up to rounding.
#include "physics/physics_data.hpp"

namespace mechsim::physics {

using detail::copy_n;

namespace detail {

void add_tree_forces(const mjModel* m, const mjData* d, mjtNum* qfrc, mjtNum* spatial) {
  // spatial[6 b]: the wrench on body b's subtree, [torque; force] about its tree's reference point.
  for (int b = 0; b < m->nbody; ++b) {
    const mjtNum* x = d->xfrc_applied + 6 * b;
    mjtNum* s = spatial + 6 * b;
    const mjtNum* c = d->subtree_com + 3 * m->body_rootid[b];
    const mjtNum r[3] = {d->xipos[3 * b] - c[0], d->xipos[3 * b + 1] - c[1], d->xipos[3 * b + 2] - c[2]};
    // xfrc_applied: force (0..2) and torque (3..5) at the body's centre of mass.
    s[0] = x[3] + r[1] * x[2] - r[2] * x[1];
    s[1] = x[4] + r[2] * x[0] - r[0] * x[2];
    s[2] = x[5] + r[0] * x[1] - r[1] * x[0];
    s[3] = x[0];
    s[4] = x[1];
    s[5] = x[2];
  }
  // Children come after their parents: gather from the leaves. A tree's root (its parent is the
  // world) keeps its own: the world's reference points differ per tree, and it has no DOFs.
  for (int b = m->nbody - 1; b > 0; --b) {
    const int p = m->body_parentid[b];
    if (p == 0) continue;
    for (int k = 0; k < 6; ++k) spatial[6 * p + k] += spatial[6 * b + k];
  }
  // cdof: [angular; linear] motion of the DOF at the tree's reference point.
  for (int v = 0; v < m->nv; ++v) {
    const mjtNum* a = d->cdof + 6 * v;
    const mjtNum* s = spatial + 6 * m->dof_bodyid[v];
    qfrc[v] += a[0] * s[0] + a[1] * s[1] + a[2] * s[2] + a[3] * s[3] + a[4] * s[4] + a[5] * s[5];
  }
}

}  // namespace detail

void Physics::step2_with_tree_forces() {
  const mjModel* m = data_->m;
  mjData* d = data_->d;
  const int n6 = 6 * m->nbody;
  bool any = false;
  for (int i = 0; i < n6 && !any; ++i) any = d->xfrc_applied[i] != 0.0;
  if (!any) {
    mj_step2(m, d);
    return;
  }
  // MuJoCo sees them as joint forces for this step only: the caller's xfrc_applied and
  // qfrc_applied are back as they were afterwards (the sensors' Newton-Euler pass reads
  // xfrc_applied, and outside forces persist across steps).
  copy_n(data_->saved_xfrc.data(), d->xfrc_applied, n6);
  copy_n(data_->saved_qfrc_applied.data(), d->qfrc_applied, m->nv);
  detail::add_tree_forces(m, d, d->qfrc_applied, data_->tree_spatial.data());
  std::fill(d->xfrc_applied, d->xfrc_applied + n6, 0.0);
  mj_step2(m, d);
  copy_n(d->xfrc_applied, data_->saved_xfrc.data(), n6);
  copy_n(d->qfrc_applied, data_->saved_qfrc_applied.data(), m->nv);
}

}  // namespace mechsim::physics
