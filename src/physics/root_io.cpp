// The floating root link as a physics port (read in the tick, a velocity set before a step) and
// per-joint effort bounds that model plugins change at run time.
#include "physics/physics.hpp"
#include "physics/physics_data.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {
namespace {

using description::Pose;
using description::Quat;
using description::Vec3;

// Finds the root's free joint and the root link's frame in its body the first time.
void find_root(const PhysicsModel& model, const Physics::Data& data) {
  if (data.root_known) return;
  const auto link = model.link_index(model.root_link());
  data.root_free_joint = detail::robot_free_joint(model, data.m);
  data.X_BodyRoot = link ? model.links()[*link].X_BL : Pose{};
  data.root_known = true;
}

Vec3 cross(const Vec3& a, const Vec3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

}  // namespace

void Physics::set_effort_limit(std::size_t j, double limit) noexcept {
  const JointInfo& info = model_->joints()[j];
  if (info.actuator < 0) return;
  mjModel* m = data_->m;
  const double bound = limit > 0.0 ? limit : info.effort_limit;
  m->actuator_forcelimited[info.actuator] = bound > 0.0 ? 1 : 0;
  m->actuator_forcerange[2 * info.actuator] = -bound;
  m->actuator_forcerange[2 * info.actuator + 1] = bound;
}

namespace {

// The state of the link at X_BodyL in a body floating on free joint j.
void free_joint_state(const mjModel* m, const mjData* d, int j, const Pose& X_BodyL, Pose& X_WL, Twist& V_WL) {
  const mjtNum* q = d->qpos + m->jnt_qposadr[j];
  const mjtNum* v = d->qvel + m->jnt_dofadr[j];
  const Pose X_WBody{{q[0], q[1], q[2]}, quat_normalized(Quat{q[3], q[4], q[5], q[6]})};
  X_WL = compose(X_WBody, X_BodyL);
  // MuJoCo's free joint: the body origin's velocity in W, the angular velocity in the body frame.
  const Vec3 w = rotate(X_WBody.orientation, Vec3{v[3], v[4], v[5]});
  const Vec3 r = rotate(X_WBody.orientation, X_BodyL.position);  // body origin -> link origin, W
  const Vec3 wr = cross(w, r);
  V_WL.linear = {v[0] + wr.x, v[1] + wr.y, v[2] + wr.z};
  V_WL.angular = w;
}

}  // namespace

bool Physics::root_state(Pose& X_WB, Twist& V_WB) const noexcept {
  find_root(*model_, *data_);
  const int j = data_->root_free_joint;
  if (j < 0) return false;
  free_joint_state(data_->m, data_->d, j, data_->X_BodyRoot, X_WB, V_WB);
  return true;
}

bool Physics::free_link_state(std::size_t link, Pose& X_WL, Twist& V_WL) const noexcept {
  const int j = detail::free_joint_of_link(*model_, data_->m, link);
  if (j < 0) return false;
  free_joint_state(data_->m, data_->d, j, model_->links()[link].X_BL, X_WL, V_WL);
  return true;
}

namespace {

// Sets free joint j's velocity so that the link at X_BodyL in its body moves with V_WL.
void command_free_joint(const mjModel* m, mjData* d, int j, const Pose& X_BodyL, const Twist& V_WL) {
  const mjtNum* q = d->qpos + m->jnt_qposadr[j];
  mjtNum* v = d->qvel + m->jnt_dofadr[j];
  const Quat R_WBody = quat_normalized(Quat{q[3], q[4], q[5], q[6]});
  const Vec3 r = rotate(R_WBody, X_BodyL.position);
  const Vec3 wr = cross(V_WL.angular, r);
  const Vec3 w_body = rotate(quat_conjugate(R_WBody), V_WL.angular);
  const mjtNum values[6] = {V_WL.linear.x - wr.x, V_WL.linear.y - wr.y, V_WL.linear.z - wr.z, w_body.x, w_body.y, w_body.z};
  for (int i = 0; i < 6; ++i) v[i] = values[i];
}

}  // namespace

void Physics::command_root_velocity(const Twist& V_WB) noexcept {
  find_root(*model_, *data_);
  const int j = data_->root_free_joint;
  if (j < 0) return;
  command_free_joint(data_->m, data_->d, j, data_->X_BodyRoot, V_WB);
  data_->stale = true;
}

void Physics::command_free_link_velocity(std::size_t link, const Twist& V_WL) noexcept {
  const int j = detail::free_joint_of_link(*model_, data_->m, link);
  if (j < 0) return;
  command_free_joint(data_->m, data_->d, j, model_->links()[link].X_BL, V_WL);
  data_->stale = true;
}

}  // namespace mechsim::physics
