#include "physics/physics.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/physics_data.hpp"
#include "physics/sensing_internal.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {

using description::Pose;
using detail::copy_n;
using detail::joint_of_dof;
using detail::start_arena_warning_counts;

namespace {

const char* code_text(StepCode c) {
  switch (c) {
    case StepCode::Ok: return "ok";
    case StepCode::NonFiniteCommand: return "non-finite command";
    case StepCode::NonFiniteState: return "non-finite state";
    case StepCode::RunawayAcceleration: return "runaway acceleration";
    case StepCode::SolverFailure: return "MuJoCo flagged an unstable state";
    case StepCode::ArenaFull: return "MuJoCo's arena is full";
  }
  return "?";
}

std::string_view joint_of_qpos(const mjModel* m, int qpos) {
  for (int j = m->njnt - 1; j >= 0; --j)
    if (m->jnt_qposadr[j] <= qpos) return joint_of_dof(m, m->jnt_dofadr[j]);
  return "?";
}

}  // namespace

std::string StepStatus::message() const {
  if (ok()) return "ok";
  if (code == StepCode::ArenaFull)
    return std::string(code_text(code)) + ": the step needs more than " + std::to_string(static_cast<long>(value)) + " " +
           std::string(element) + " (BuildOptions::max_arena; MuJoCo would drop the rest, changing the physics)";
  return std::string(code_text(code)) + " at '" + std::string(element) + "' (value " + std::to_string(value) + ")";
}

Physics::Physics(std::shared_ptr<const PhysicsModel> model) : model_(std::move(model)), data_(std::make_unique<Data>()) {
  const mjModel* shared = model_->impl().model;
  data_->m = mj_copyModel(nullptr, shared);
  data_->d = mj_makeData(data_->m);
  start_arena_warning_counts(data_->d);
  const std::size_t nj = model_->joints().size();
  data_->modes.assign(nj, JointMode::Effort);
  data_->gains.assign(nj, ServoGains{});
  data_->motor_integral.assign(nj, std::nan(""));
  data_->saved_qpos.resize(static_cast<std::size_t>(shared->nq));
  data_->saved_qvel.resize(static_cast<std::size_t>(shared->nv));
  data_->saved_act.resize(static_cast<std::size_t>(std::max(shared->na, 1)));
  data_->saved_warm.resize(static_cast<std::size_t>(shared->nv));
  data_->external_effort.assign(static_cast<std::size_t>(shared->nv), 0.0);
  data_->tree_spatial.assign(6 * static_cast<std::size_t>(shared->nbody), 0.0);
  data_->saved_xfrc.assign(6 * static_cast<std::size_t>(shared->nbody), 0.0);
  data_->saved_qfrc_applied.assign(static_cast<std::size_t>(shared->nv), 0.0);
  for (int g = 0; g < shared->ngeom; ++g) {
    const char* n = mj_id2name(shared, mjOBJ_GEOM, g);
    // Geom names are "<link>/collision/<i>" or "<link>/visual/<i>" (link names may hold '/').
    std::string name = n != nullptr ? n : "";
    auto cut = name.rfind("/collision/");
    if (cut != std::string::npos) data_->robot_collision_geoms.push_back(g);
    if (cut == std::string::npos) cut = name.rfind("/visual/");
    data_->geom_links.push_back(cut == std::string::npos ? (name.empty() ? "world" : name) : name.substr(0, cut));
  }
  spawn_state();  // mj_makeData has reset the data already
}

Physics::~Physics() = default;

void Physics::reset() {
  mjModel* m = data_->m;
  const mjModel* shared = model_->impl().model;
  copy_n(m->actuator_gainprm, shared->actuator_gainprm, shared->nu * mjNGAIN);
  copy_n(m->actuator_biasprm, shared->actuator_biasprm, shared->nu * mjNBIAS);
  std::fill(data_->motor_integral.begin(), data_->motor_integral.end(), std::nan(""));
  std::fill(data_->modes.begin(), data_->modes.end(), JointMode::Effort);
  std::fill(data_->gains.begin(), data_->gains.end(), ServoGains{});
  const ArenaUse use = arena_use();
  data_->peak = use.peak;
  mj_resetData(m, data_->d);
  start_arena_warning_counts(data_->d);
  spawn_state();
}

void Physics::spawn_state() {
  mjModel* m = data_->m;
  // Cancel gravity on the links Gazebo exempts from it: a constant world-frame force at the
  // body's centre of mass (xfrc_applied persists across steps).
  std::fill(data_->external_effort.begin(), data_->external_effort.end(), 0.0);
  for (int b : model_->gravity_off_bodies())
    for (int k = 0; k < 3; ++k) data_->d->xfrc_applied[6 * b + k] = -m->body_mass[b] * m->opt.gravity[k];
  // What the soil model adds its wheel forces to, every step (physics_external.cpp keeps it in
  // step with the outside forces).
  data_->xfrc_base.assign(data_->d->xfrc_applied, data_->d->xfrc_applied + 6 * m->nbody);
  std::fill(data_->soil_state.begin(), data_->soil_state.end(), Data::SoilWheel{});
  std::fill(data_->soil_readings.begin(), data_->soil_readings.end(), WheelSoilReading{});
  data_->ruts.clear();
  forward();
  diff_tau_a_ = diff_tau_b_ = 0.0;
}

double Physics::time() const { return data_->d->time; }

StepStatus Physics::step() {
  ensure_constants();
  const std::vector<JointInfo>& joints = model_->joints();
  {
    const mjModel* m = data_->m;
    const mjData* d = data_->d;
    for (const JointInfo& j : joints)
      if (j.actuator >= 0 && !std::isfinite(d->ctrl[j.actuator]))
        return {StepCode::NonFiniteCommand, j.name, d->ctrl[j.actuator]};

    // A non-finite state (e.g. written as an initial condition) is reported before MuJoCo sees
    // it: MuJoCo would reset the data and append to MUJOCO_LOG.TXT in the working directory.
    for (int i = 0; i < m->nq; ++i)
      if (!std::isfinite(d->qpos[i])) return {StepCode::NonFiniteState, joint_of_qpos(m, i), d->qpos[i]};
    for (int i = 0; i < m->nv; ++i)
      if (!std::isfinite(d->qvel[i])) return {StepCode::NonFiniteState, joint_of_dof(m, i), d->qvel[i]};
  }

  const auto& diff = model_->differential();
  if (diff && diff->active) {
    const JointInfo& a = joints[diff->joint_a];
    const JointInfo& b = joints[diff->joint_b];
    mjData* d = data_->d;
    const double spread = d->qpos[a.qpos_adr] - d->qpos[b.qpos_adr];
    diff_tau_a_ = -diff->force_constant * spread;
    diff_tau_b_ = diff->force_constant * spread;
    d->qfrc_applied[a.dof_adr] = diff_tau_a_ + data_->external_effort[static_cast<std::size_t>(a.dof_adr)];
    d->qfrc_applied[b.dof_adr] = diff_tau_b_ + data_->external_effort[static_cast<std::size_t>(b.dof_adr)];
  }

  save_state();
  StepStatus status;
  if (!compute_in_arena(true)) {
    const bool contacts = data_->d->warning[mjWARN_CONTACTFULL].number != data_->saved_warnings[mjWARN_CONTACTFULL];
    status = contacts ? StepStatus{StepCode::ArenaFull, "contacts", static_cast<double>(data_->m->nconmax)}
                      : StepStatus{StepCode::ArenaFull, "constraints", static_cast<double>(data_->m->njmax)};
  }
  data_->stale = true;

  mjModel* m = data_->m;
  mjData* d = data_->d;
  for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC}) {
    if (!status.ok() || d->warning[w].number == data_->saved_warnings[w]) continue;
    const int info = d->warning[w].lastinfo;
    status = {StepCode::SolverFailure, w == mjWARN_BADQPOS ? joint_of_qpos(m, info) : joint_of_dof(m, info), 0.0};
  }
  if (status.ok()) {
    for (int i = 0; i < m->nq && status.ok(); ++i)
      if (!std::isfinite(d->qpos[i])) status = {StepCode::NonFiniteState, joint_of_qpos(m, i), d->qpos[i]};
    const double limit = model_->options().max_joint_acceleration;
    for (int i = 0; i < m->nv && status.ok(); ++i) {
      if (!std::isfinite(d->qvel[i])) status = {StepCode::NonFiniteState, joint_of_dof(m, i), d->qvel[i]};
      else if (!std::isfinite(d->qacc[i])) status = {StepCode::NonFiniteState, joint_of_dof(m, i), d->qacc[i]};
      else if (std::fabs(d->qacc[i]) > limit) status = {StepCode::RunawayAcceleration, joint_of_dof(m, i), d->qacc[i]};
    }
  }
  if (status.ok()) {
    note_mujoco_warnings();
    commit_soil();
  } else {
    restore_saved_state();
    forward();
  }
  return status;
}

double Physics::position(std::size_t j) const { return data_->d->qpos[model_->joints()[j].qpos_adr]; }
double Physics::velocity(std::size_t j) const { return data_->d->qvel[model_->joints()[j].dof_adr]; }
double Physics::actuator_effort(std::size_t j) const { return data_->d->qfrc_actuator[model_->joints()[j].dof_adr]; }
double Physics::constraint_effort(std::size_t j) const { return data_->d->qfrc_constraint[model_->joints()[j].dof_adr]; }
double Physics::applied_effort(std::size_t j) const { return data_->d->qfrc_applied[model_->joints()[j].dof_adr]; }
double Physics::effort(std::size_t j) const { return actuator_effort(j) + applied_effort(j) + constraint_effort(j); }

void Physics::set_effort(std::size_t j, double effort) {
  const JointInfo& info = model_->joints()[j];
  if (info.actuator >= 0 && data_->modes[j] == JointMode::Effort) data_->d->ctrl[info.actuator] = effort;
}

void Physics::set_position_command(std::size_t j, double position) {
  const JointInfo& info = model_->joints()[j];
  if (info.actuator >= 0 && data_->modes[j] == JointMode::Position) data_->d->ctrl[info.actuator] = position;
}

void Physics::set_velocity_command(std::size_t j, double velocity) {
  const JointInfo& info = model_->joints()[j];
  if (info.actuator < 0 || data_->modes[j] != JointMode::Velocity) return;
  double& integral = data_->motor_integral[j];
  if (!std::isnan(integral) && std::isfinite(velocity)) {
    // The motor: the set point's integral correction, bounded by what the effort bound lets the
    // servo use (none without a bound).
    const mjModel* m = data_->m;
    integral += (velocity - data_->d->qvel[info.dof_adr]) * m->opt.timestep / kMotorIntegralTime;
    const double kv = data_->gains[j].kv;
    if (m->actuator_forcelimited[info.actuator] && kv > 0.0) {
      const double most = m->actuator_forcerange[2 * info.actuator + 1] / kv;
      integral = std::clamp(integral, -most, most);
    }
    velocity += integral;
  }
  data_->d->ctrl[info.actuator] = velocity;
}

void Physics::set_armature(std::size_t j, double armature) {
  const JointInfo& info = model_->joints()[j];
  if (!std::isfinite(armature) || armature < 0.0) {
    throw std::invalid_argument("armature of joint '" + info.name + "' must be finite and >= 0, got " +
                                std::to_string(armature));
  }
  data_->m->dof_armature[info.dof_adr] = armature;
  // The constraint solver scales its softness by the inverse inertias at qpos0 (dof_invweight0 and
  // friends): they are recomputed before they are next used (ensure_constants), once for any
  // number of armatures set in a row (the PR2 sets several at start-up).
  data_->constants_stale = true;
  data_->stale = true;
}

void Physics::ensure_constants() {
  if (!data_->constants_stale) return;
  mjModel* m = data_->m;
  mjData* d = data_->d;
  // mj_setConst works on d at qpos0: keep the state around it.
  const std::vector<mjtNum> qpos(d->qpos, d->qpos + m->nq), qvel(d->qvel, d->qvel + m->nv),
      act(d->act, d->act + m->na), ctrl(d->ctrl, d->ctrl + m->nu), warm(d->qacc_warmstart, d->qacc_warmstart + m->nv);
  const mjtNum time = d->time;
  mj_setConst(m, d);
  copy_n(d->qpos, qpos.data(), m->nq);
  copy_n(d->qvel, qvel.data(), m->nv);
  copy_n(d->act, act.data(), m->na);
  copy_n(d->ctrl, ctrl.data(), m->nu);
  copy_n(d->qacc_warmstart, warm.data(), m->nv);
  d->time = time;
  data_->constants_stale = false;
  data_->stale = true;
}

double Physics::armature(std::size_t j) const { return data_->m->dof_armature[model_->joints()[j].dof_adr]; }

double Physics::effective_inertia(std::size_t j) const {
  const mjModel* m = data_->m;
  mjData* d = data_->d;
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_crb(m, d);      // the mass matrix qM (armature included)
  mj_factorM(m, d);  // its LDL' factors, for mj_solveM
  std::vector<mjtNum> unit(static_cast<std::size_t>(m->nv), 0.0), column(static_cast<std::size_t>(m->nv), 0.0);
  const int dof = model_->joints()[j].dof_adr;
  unit[static_cast<std::size_t>(dof)] = 1.0;
  mj_solveM(m, d, column.data(), unit.data(), 1);
  data_->stale = true;
  return 1.0 / column[static_cast<std::size_t>(dof)];
}

double Physics::joint_damping(std::size_t j) const { return data_->m->dof_damping[model_->joints()[j].dof_adr]; }

void Physics::set_mode(std::size_t j, JointMode mode, ServoGains gains) {
  const JointInfo& info = model_->joints()[j];
  if (info.actuator < 0) return;
  mjModel* m = data_->m;
  data_->motor_integral[j] = mode == JointMode::Velocity && gains.motor ? 0.0 : std::nan("");
  if (mode == JointMode::Velocity && gains.motor && gains.kv <= 0.0) {
    ensure_constants();  // dof_M0
    gains.kv = 0.5 * (m->dof_M0[info.dof_adr] + m->dof_armature[info.dof_adr]) / m->opt.timestep;
  }
  if (gains.kp <= 0.0 && gains.kv <= 0.0 && mode != JointMode::Effort) {
    ensure_constants();  // dof_M0
    // Critically damped 10 Hz servo on the joint's inertia at the spawn configuration.
    const double inertia = m->dof_M0[info.dof_adr] + m->dof_armature[info.dof_adr];
    const double wn = 2.0 * M_PI * 10.0;
    gains = mode == JointMode::Position ? ServoGains{inertia * wn * wn, 2.0 * inertia * wn} : ServoGains{0.0, inertia * wn};
  }
  mjtNum* gain = m->actuator_gainprm + info.actuator * mjNGAIN;
  mjtNum* bias = m->actuator_biasprm + info.actuator * mjNBIAS;
  std::fill(gain, gain + mjNGAIN, 0.0);
  std::fill(bias, bias + mjNBIAS, 0.0);
  mjtNum& ctrl = data_->d->ctrl[info.actuator];
  switch (mode) {
    case JointMode::Effort:
      gain[0] = 1.0;
      ctrl = 0.0;
      break;
    case JointMode::Position:  // force = kp (ctrl - q) - kv qdot
      gain[0] = gains.kp;
      bias[1] = -gains.kp;
      bias[2] = -gains.kv;
      ctrl = position(j);  // hold where it is until commanded
      break;
    case JointMode::Velocity:  // force = kv (ctrl - qdot)
      gain[0] = gains.kv;
      bias[2] = -gains.kv;
      ctrl = 0.0;
      break;
  }
  data_->modes[j] = mode;
  data_->gains[j] = gains;
}

JointMode Physics::mode(std::size_t j) const { return data_->modes[j]; }
ServoGains Physics::gains(std::size_t j) const { return data_->gains[j]; }

void Physics::set_joint_state(std::size_t j, double position, double velocity) {
  const JointInfo& info = model_->joints()[j];
  data_->d->qpos[info.qpos_adr] = position;
  data_->d->qvel[info.dof_adr] = velocity;
  data_->stale = true;
}

void Physics::set_base_pose(const Pose& X_WB) {
  const int j = detail::robot_free_joint(*model_, data_->m);
  if (j < 0) return;
  mjtNum* q = data_->d->qpos + data_->m->jnt_qposadr[j];
  const Quat r = quat_normalized(X_WB.orientation);
  const mjtNum values[7] = {X_WB.position.x, X_WB.position.y, X_WB.position.z, r.w, r.x, r.y, r.z};
  std::copy(values, values + 7, q);
  data_->stale = true;
}

void Physics::set_free_joint_spawn(int joint, const Pose& X_WBody) {
  mjModel* m = data_->m;
  const Quat r = quat_normalized(X_WBody.orientation);
  const mjtNum values[7] = {X_WBody.position.x, X_WBody.position.y, X_WBody.position.z, r.w, r.x, r.y, r.z};
  std::copy(values, values + 7, m->qpos0 + m->jnt_qposadr[joint]);
  // The constants the compiler derives at qpos0 (inverse inertias that scale constraint
  // softness), as if the model had been compiled at this pose.
  mj_resetData(m, data_->d);
  mj_setConst(m, data_->d);
  data_->constants_stale = false;
  reset();
}

void Physics::set_spawn_pose(const Pose& X_WB) {
  const int j = detail::robot_free_joint(*model_, data_->m);
  if (j >= 0) set_free_joint_spawn(j, X_WB);
}

bool Physics::set_free_link_spawn_pose(std::size_t link, const Pose& X_WL) {
  const int j = detail::free_joint_of_link(*model_, data_->m, link);
  if (j < 0) return false;
  set_free_joint_spawn(j, compose(X_WL, inverse(model_->links()[link].X_BL)));
  return true;
}

void Physics::set_base_twist(const Twist& V) {
  const int j = detail::robot_free_joint(*model_, data_->m);
  if (j < 0) return;
  mjtNum* v = data_->d->qvel + data_->m->jnt_dofadr[j];
  // MuJoCo free joint: linear velocity in the world frame, angular velocity in the body frame.
  const mjtNum* xq = data_->d->qpos + data_->m->jnt_qposadr[j] + 3;
  const Vec3 w_body = rotate(quat_conjugate(Quat{xq[0], xq[1], xq[2], xq[3]}), V.angular);
  const mjtNum values[6] = {V.linear.x, V.linear.y, V.linear.z, w_body.x, w_body.y, w_body.z};
  std::copy(values, values + 6, v);
  data_->stale = true;
}

void Physics::refresh_kinematics() const {
  if (!data_->stale) return;
  mj_kinematics(data_->m, data_->d);
  mj_comPos(data_->m, data_->d);
  mj_comVel(data_->m, data_->d);
  data_->stale = false;
}

Pose Physics::link_pose(std::size_t link) const {
  const LinkInfo& info = model_->links()[link];
  return compose(body_pose(info.body), info.X_BL);
}

Twist Physics::link_twist(std::size_t link) const {
  return point_twist(model_->links()[link].body, link_pose(link).position);
}

Pose Physics::body_pose(int b) const {
  refresh_kinematics();
  const mjData* d = data_->d;
  return {{d->xpos[3 * b], d->xpos[3 * b + 1], d->xpos[3 * b + 2]},
          {d->xquat[4 * b], d->xquat[4 * b + 1], d->xquat[4 * b + 2], d->xquat[4 * b + 3]}};
}

Vec3 Physics::body_com(int b) const {
  refresh_kinematics();
  const mjData* d = data_->d;
  return {d->xipos[3 * b], d->xipos[3 * b + 1], d->xipos[3 * b + 2]};
}

Twist Physics::body_twist(int b) const { return point_twist(b, body_pose(b).position); }

Twist Physics::point_twist(int b, const Vec3& p_W) const {
  refresh_kinematics();
  const mjData* d = data_->d;
  mjtNum v[6];  // [angular; linear] at the body's centre of mass, world orientation
  mj_objectVelocity(data_->m, d, mjOBJ_BODY, b, v, 0);
  const Vec3 w{v[0], v[1], v[2]};
  const Vec3 r{p_W.x - d->xipos[3 * b], p_W.y - d->xipos[3 * b + 1], p_W.z - d->xipos[3 * b + 2]};  // centre of mass -> point
  return {{v[3] + w.y * r.z - w.z * r.y, v[4] + w.z * r.x - w.x * r.z, v[5] + w.x * r.y - w.y * r.x}, w};
}

bool Physics::set_free_body_state(int body, const Pose& X_WB, const Twist& V) {
  const mjModel* m = data_->m;
  if (body < 1 || body >= m->nbody || m->body_jntnum[body] < 1) return false;
  const int j = m->body_jntadr[body];
  if (m->jnt_type[j] != mjJNT_FREE) return false;
  const Quat r = quat_normalized(X_WB.orientation);
  const mjtNum q[7] = {X_WB.position.x, X_WB.position.y, X_WB.position.z, r.w, r.x, r.y, r.z};
  std::copy(q, q + 7, data_->d->qpos + m->jnt_qposadr[j]);
  // MuJoCo's free joint: the body origin's velocity in W, the angular velocity in the body frame.
  const Vec3 w_body = rotate(quat_conjugate(r), V.angular);
  const mjtNum v[6] = {V.linear.x, V.linear.y, V.linear.z, w_body.x, w_body.y, w_body.z};
  std::copy(v, v + 6, data_->d->qvel + m->jnt_dofadr[j]);
  data_->stale = true;
  return true;
}

Pose Physics::base_pose() const { return link_pose(*model_->link_index(model_->root_link())); }
Twist Physics::base_twist() const { return link_twist(*model_->link_index(model_->root_link())); }

std::size_t Physics::contacts(std::vector<Contact>& out) const {
  out.clear();
  const mjModel* m = data_->m;
  const mjData* d = data_->d;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    Contact k;
    k.link_a = data_->geom_links[static_cast<std::size_t>(c.geom1)];
    k.link_b = data_->geom_links[static_cast<std::size_t>(c.geom2)];
    k.position = {c.pos[0], c.pos[1], c.pos[2]};
    k.normal = {c.frame[0], c.frame[1], c.frame[2]};
    k.depth = -c.dist;
    mjtNum f[6] = {};
    if (c.efc_address >= 0) mj_contactForce(m, d, i, f);
    k.normal_force = f[0];
    k.friction_force[0] = f[1];
    k.friction_force[1] = f[2];
    // The contact frame's rows: normal, then the two tangents (world frame).
    const mjtNum* R = c.frame;
    k.force = {f[0] * R[0] + f[1] * R[3] + f[2] * R[6], f[0] * R[1] + f[1] * R[4] + f[2] * R[7],
               f[0] * R[2] + f[1] * R[5] + f[2] * R[8]};
    k.geom_a = c.geom1;
    k.geom_b = c.geom2;
    out.push_back(k);
  }
  return out.size();
}

namespace {

// The box around collision geoms `geoms` in the current pose (meshes by their bounding spheres).
template <class Geoms>
Bounds geom_bounds(const mjModel* m, const mjData* d, const Geoms& geoms) {
  Bounds b;
  for (const int g : geoms) {
    const mjtNum* p = d->geom_xpos + 3 * g;
    const mjtNum* R = d->geom_xmat + 9 * g;  // row-major: R[3 i + j] = world axis i . geom axis j
    const mjtNum* s = m->geom_size + 3 * g;
    double half[3];
    for (int i = 0; i < 3; ++i) {
      const double rx = std::abs(R[3 * i]), ry = std::abs(R[3 * i + 1]), rz = std::abs(R[3 * i + 2]);
      switch (m->geom_type[g]) {
        case mjGEOM_SPHERE: half[i] = s[0]; break;
        case mjGEOM_CAPSULE: half[i] = rz * s[1] + s[0]; break;
        case mjGEOM_CYLINDER: half[i] = rz * s[1] + s[0] * std::sqrt(std::max(0.0, 1.0 - rz * rz)); break;
        case mjGEOM_ELLIPSOID: half[i] = std::sqrt(rx * rx * s[0] * s[0] + ry * ry * s[1] * s[1] + rz * rz * s[2] * s[2]); break;
        case mjGEOM_BOX: half[i] = rx * s[0] + ry * s[1] + rz * s[2]; break;
        default: half[i] = m->geom_rbound[g]; break;
      }
    }
    b.min = {std::min(b.min.x, p[0] - half[0]), std::min(b.min.y, p[1] - half[1]), std::min(b.min.z, p[2] - half[2])};
    b.max = {std::max(b.max.x, p[0] + half[0]), std::max(b.max.y, p[1] + half[1]), std::max(b.max.z, p[2] + half[2])};
  }
  return b;
}

}  // namespace

Bounds Physics::robot_bounds() const {
  refresh_kinematics();
  return geom_bounds(data_->m, data_->d, data_->robot_collision_geoms);
}

Bounds Physics::collision_bounds(const std::string& link_prefix) const {
  refresh_kinematics();
  std::vector<int> geoms;
  for (const int g : data_->robot_collision_geoms) {
    const std::string& link = data_->geom_links[static_cast<std::size_t>(g)];
    if (link_prefix.empty() ? link.find("::") == std::string::npos : link.rfind(link_prefix, 0) == 0) geoms.push_back(g);
  }
  return geom_bounds(data_->m, data_->d, geoms);
}

double Physics::ground_height(double x, double y) const {
  refresh_kinematics();
  constexpr double kTop = 1e4;
  const mjtNum from[3] = {x, y, kTop};
  const mjtNum down[3] = {0.0, 0.0, -1.0};
  const mjtByte groups[mjNGROUP] = {0, 0, 1, 0, 0, 0};  // world geoms sit in group 2
  int geom = -1;
  mjtNum distance = mj_ray(data_->m, data_->d, from, down, groups, 1, -1, &geom);
  // mj_ray can pass between a height field's triangles on a grid line and report the bottom of
  // the terrain block (ray_cast.hpp): the exact intersection decides for height fields.
  const mjModel* m = data_->m;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] != mjGEOM_HFIELD || m->geom_group[g] != 2) continue;
    const double hit = detail::ray_hfield_geom(m, data_->d, g, from, down);
    if (hit >= 0.0 && (distance < 0.0 || hit < distance)) distance = hit;
  }
  return distance < 0.0 ? std::nan("") : kTop - distance;
}

void Physics::cast_rays(const RayFilter& filter, const Vec3& origin, const Vec3* directions, std::size_t count,
                        double near, double far, double* ranges, int* hit_geoms) const {
  refresh_kinematics();
  detail::cast_rays(data_->m, data_->d, filter, origin, directions, count, near, far, ranges, hit_geoms);
}

Acceleration Physics::link_acceleration(std::size_t link, const Vec3& p_L) const {
  const Pose X_WL = link_pose(link);  // refreshes the kinematics
  const Vec3 r = rotate(X_WL.orientation, p_L);
  const Vec3 p_W{X_WL.position.x + r.x, X_WL.position.y + r.y, X_WL.position.z + r.z};
  return detail::point_acceleration(data_->m, data_->d, model_->links()[link].body, p_W);
}

Wrench Physics::joint_wrench(std::size_t link, const Vec3& p_L) const {
  const Pose X_WL = link_pose(link);
  const Vec3 r = rotate(X_WL.orientation, p_L);
  const Vec3 p_W{X_WL.position.x + r.x, X_WL.position.y + r.y, X_WL.position.z + r.z};
  return detail::wrench_from_parent(data_->m, data_->d, model_->links()[link].body, p_W);
}

double Physics::energy() const {
  mjModel* m = data_->m;
  mjData* d = data_->d;
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_crb(m, d);
  // MuJoCo 2.2.2 computes energy only while the energy flag is on.
  const int flags = m->opt.enableflags;
  m->opt.enableflags |= mjENBL_ENERGY;
  mj_energyPos(m, d);
  mj_energyVel(m, d);
  m->opt.enableflags = flags;
  data_->stale = true;  // mj_comVel not refreshed
  return d->energy[0] + d->energy[1];
}

}  // namespace mechsim::physics
