#pragma once
// Private to src/physics/*.cpp: the MuJoCo objects behind one Physics instance, and helpers its
// files share (physics.cpp: state, I/O, queries; physics_arena.cpp: the arena and MuJoCo's warnings).

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/mujoco_internal.hpp"
#include "physics/physics.hpp"
#include "physics/soil_ruts.hpp"

namespace mechsim::physics {

struct Physics::Data {
  mjModel* m = nullptr;  // private copy: actuator gains are per instance
  mjData* d = nullptr;
  mutable bool stale = true;  // kinematics lag the state (after a step or a state write)
  bool constants_stale = false;  // the model changed (armature): mj_setConst is due
  std::vector<JointMode> modes;
  std::vector<ServoGains> gains;
  // Velocity motors (ServoGains::motor), per joint: the integral correction of the set point
  // (rad/s or m/s); NaN: not a motor.
  std::vector<double> motor_integral;
  std::vector<std::string> geom_links;  // URDF link (or world geom) per MuJoCo geom
  std::vector<int> robot_collision_geoms;
  // State before the current step, restored when a step fails.
  double saved_time = 0.0;
  std::vector<mjtNum> saved_qpos, saved_qvel, saved_act, saved_warm;
  int saved_warnings[mjNWARNING] = {};
  // Arena use before the last reset or growth (mj_resetData and a new mjData start from 0).
  ArenaSize peak;
  int growths = 0;
  int warning_notice[mjNWARNING] = {};  // index + 1 into Physics::notices_ of each MuJoCo warning
  // Per DOF: the generalised forces of add_joint_effort (the differential law adds its own).
  std::vector<mjtNum> external_effort;

  // Wheel-soil (wheel_soil.cpp): the soil, each wheel's state as of the state and as the running
  // step would leave it; the readings; the world geom the soil lies on (plane or height field, -1:
  // none); xfrc_applied as spawn_state() leaves it (the gravity-off forces), under the soil's.
  struct SoilWheel {
    double shear_x = 0.0, shear_y = 0.0;  // m: soil shear at the rim's exit, along heading and axle
    double rolling = 0.0;   // [-1, 1]: how far into rolling forward (+) or backward (-) the wheel is
    double pushing = 0.0;   // [-1, 1]: the same for the compaction ahead of it (travel only)
  };
  std::optional<SoilParameters> soil;
  std::vector<WheelOverride> soil_overrides;  // as set_soil was given them (a rebuild sets them again)
  std::vector<SoilWheelInfo> soil_wheels;
  std::vector<std::string> soil_wheel_notes;
  std::vector<SoilWheel> soil_state, soil_pending;
  std::vector<WheelSoilReading> soil_readings, soil_pending_readings;
  int soil_ground = -1;
  // The ruts (multi-pass), and where each wheel pressed the soil in the running step: the
  // bottom point, the axle and the sinkage (NaN: not in the soil), pressed in when it succeeds.
  detail::RutMap ruts;
  struct Press {
    double low[3] = {0.0, 0.0, 0.0}, axle[3] = {0.0, 0.0, 0.0};
    double sinkage = 0.0;
  };
  std::vector<Press> soil_press;
  std::vector<mjtNum> xfrc_base;
  // StepCost::tree_external_forces (tree_forces.cpp): the wrench gathered per body, and the
  // caller's xfrc_applied and qfrc_applied while a step holds them as joint forces.
  std::vector<mjtNum> tree_spatial, saved_xfrc, saved_qfrc_applied;
  // The root's free joint and the root link's frame in its body (root_io.cpp), found once.
  mutable bool root_known = false;
  mutable int root_free_joint = -1;
  mutable description::Pose X_BodyRoot;

  ~Data() {
    if (d != nullptr) mj_deleteData(d);
    if (m != nullptr) mj_deleteModel(m);
  }
};

namespace detail {

// Adds to qfrc (nv) the joint forces of the wrenches in d->xfrc_applied (force and torque at each
// body's centre of mass), as MuJoCo's mj_applyFT per body would, in one pass over the tree; the
// kinematics (xipos, subtree_com, cdof) must be current. `spatial`: scratch of 6 nbody.
void add_tree_forces(const mjModel* m, const mjData* d, mjtNum* qfrc, mjtNum* spatial);

// The free joint of the robot's root link's body, or -1 (a robot fixed to the world; the world's
// free objects and passive models have free joints of their own, after the robot's).
inline int robot_free_joint(const PhysicsModel& model, const mjModel* m) {
  const auto link = model.link_index(model.root_link());
  if (!link) return -1;
  const int body = model.links()[*link].body;
  for (int j = 0; j < m->njnt; ++j)
    if (m->jnt_type[j] == mjJNT_FREE && m->jnt_bodyid[j] == body) return j;
  return -1;
}

// The free joint of link `link`'s own body (another robot's root), or -1 for a link whose body
// does not float on one.
inline int free_joint_of_link(const PhysicsModel& model, const mjModel* m, std::size_t link) {
  if (link >= model.links().size()) return -1;
  const int body = model.links()[link].body;
  if (body < 1 || m->body_jntnum[body] < 1) return -1;
  const int j = m->body_jntadr[body];
  return m->jnt_type[j] == mjJNT_FREE ? j : -1;
}

inline std::string_view joint_of_dof(const mjModel* m, int dof) {
  if (dof < 0 || dof >= m->nv) return "?";
  const int j = m->dof_jntid[dof];
  const char* n = mj_id2name(m, mjOBJ_JOINT, j);
  if (n != nullptr && m->jnt_type[j] != mjJNT_FREE) return n;
  const char* b = mj_id2name(m, mjOBJ_BODY, m->jnt_bodyid[j]);
  return b != nullptr ? b : "?";
}

// MuJoCo prints a warning, and appends it to MUJOCO_LOG.TXT in the working directory, the first
// time its count leaves 0. Physics reports every arena overflow itself (it grows or fails the
// step), so these two counts start at 1: the steps compare counts, never read them as totals.
inline void start_arena_warning_counts(mjData* d) {
  for (int w : {mjWARN_CONTACTFULL, mjWARN_CNSTRFULL}) d->warning[w].number = std::max(d->warning[w].number, 1);
}

template <typename T>
inline void copy_n(T* dst, const T* src, int n) {
  if (n > 0) std::memcpy(dst, src, sizeof(T) * static_cast<std::size_t>(n));
}

}  // namespace detail
}  // namespace mechsim::physics
