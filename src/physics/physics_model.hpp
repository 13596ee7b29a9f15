#pragma once
// The compiled physics model of one robot in one world: built once from a RobotModel, then
// immutable and shared by any number of Physics instances (physics/physics.hpp).
// MuJoCo stays behind the opaque Impl: no MuJoCo type appears in this header.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "description/robot_model.hpp"
#include "physics/physics_options.hpp"
#include "physics/stage_timer.hpp"

namespace mechsim::physics {

// A simulated 1-DOF joint: a URDF revolute/continuous/prismatic joint, or one part of a URDF
// planar or non-root floating joint ("<name>:x", "<name>:y", "<name>:yaw", ...).
struct JointInfo {
  std::string name;
  bool prismatic = false;     // slide (m) rather than hinge (rad)
  bool urdf_one_dof = false;  // realises a URDF revolute/continuous/prismatic joint
  bool limited = false;
  double lower = 0.0, upper = 0.0;  // rad or m, when limited
  double effort_limit = 0.0;        // N m or N, 0 = unbounded
  double damping = 0.0;             // N m s/rad or N s/m
  double frictionloss = 0.0;        // N m or N
  bool actuated = false;            // has an actuator (effort / servo commands)
  // MuJoCo addresses (plain ints, valid for the compiled model).
  int mj_joint = -1, qpos_adr = -1, dof_adr = -1, actuator = -1;
};

// Where a URDF link frame L lives in the compiled model: body -1 is the world.
struct LinkInfo {
  std::string name;
  int body = -1;
  description::Pose X_BL;  // link frame in the MuJoCo body frame
};

// A primitive collision shape of the world's passive models (WorldSpec::models), for drawing
// them: the compiled body that carries it and its frame there. Meshes are not listed.
struct PassiveShape {
  int body = 0;           // compiled body; 0: welded to the world
  std::string body_name;  // "<model>::<link>", "world" for 0
  enum class Kind { Box, Cylinder, Sphere } kind = Kind::Box;
  // Full extents as a WorldBox's: a box's edges; a cylinder's diameter, diameter and length (axis
  // z); a sphere's diameter, three times.
  description::Vec3 size;
  description::Pose X_BG;  // in the body frame
};

// A wheel: a collision cylinder turning about its axis on its link's revolute or continuous
// joint (physics/wheel_identify.hpp; the wheel-soil model acts on these, physics/soil.hpp). A
// narrow one (width <= radius) is an ellipsoid in MuJoCo (ContactDefaults::point_contact_wheels)
// with the same rolling circle; the soil sees its radius and width.
struct WheelInfo {
  std::string link;         // URDF link
  std::size_t joint = 0;    // index into PhysicsModel::joints(): the joint it turns on
  int geom = -1, body = -1;  // MuJoCo geom (a cylinder, or an ellipsoid for a narrow wheel) and body
  double radius = 0.0, width = 0.0;  // m
  bool narrow = false;      // width <= radius
};

// The gazebo differential plugin's law, when the description names one.
struct DifferentialInfo {
  std::string plugin;
  std::size_t joint_a = 0, joint_b = 0;  // indices into joints()
  double force_constant = 0.0;           // N m/rad
  bool active = false;                    // options.differential == PluginLaw
};

// The mesh geoms a model of `robot` would leave out, worded as build()'s warnings, without
// compiling it (for `mechsim check`): plans the bodies and loads every mesh file. A mesh that
// loads but that MuJoCo refuses shows up in build()'s warnings only. Throws as plan_bodies().
std::vector<std::string> mesh_warnings(const description::RobotModel& robot);

// How the arena of the model's Physics instances was sized (physics/arena_estimate.cpp): from the
// geom pairs that can touch (MuJoCo's own filters: contype/conaffinity, same or parent body,
// excluded pairs). Each movable body tree rests on the ground with its lowest geoms at the spawn
// pose, which make what their shapes make on the ground (a box 4 contacts on a plane, about half
// the prisms under it on a height field); every other pair counts one contact. Each contact takes
// as many constraint rows as its friction cone has; joint limits, equalities and friction loss
// add theirs; then a quarter more. A run that needs more grows the arena (ArenaOverflow).
struct ArenaEstimate {
  int candidate_pairs = 0;   // geom pairs that can touch
  int support_geoms = 0;     // pairs of a ground geom and a geom a body tree rests on
  int contacts = 0;          // contacts estimated
  int contact_rows = 0;      // constraint rows of those contacts
  int other_rows = 0;        // limits, equality constraints, friction loss
  ArenaSize size;            // what instances start with: the above with margin, or BuildOptions::arena
  bool from_options = false;  // size was given by BuildOptions::arena
};

// Time of PhysicsModel::build's stages.
struct BuildTimes {
  StageTime mjcf;     // body plan, meshes read and converted, MJCF written
  StageTime compile;  // MuJoCo's compiler (mj_loadXML from memory), terrain, arena estimate
};

class PhysicsModel {
 public:
  // Plans the bodies, writes MJCF, compiles it with MuJoCo from memory. Throws PhysicsError with
  // MuJoCo's message and the offending element when the model cannot be built.
  static std::shared_ptr<const PhysicsModel> build(const description::RobotModel& robot,
                                                   const BuildOptions& options = {});
  ~PhysicsModel();
  PhysicsModel(const PhysicsModel&) = delete;
  PhysicsModel& operator=(const PhysicsModel&) = delete;

  const std::string& robot_name() const { return robot_name_; }
  const BuildOptions& options() const { return options_; }
  double timestep() const { return options_.timestep; }  // s

  const std::vector<JointInfo>& joints() const { return joints_; }
  std::optional<std::size_t> joint_index(std::string_view name) const;
  const std::vector<LinkInfo>& links() const { return links_; }
  std::optional<std::size_t> link_index(std::string_view name) const;
  const std::string& root_link() const { return root_link_; }
  bool fixed_to_world() const { return fixed_to_world_; }
  const std::optional<DifferentialInfo>& differential() const { return differential_; }
  // Links Gazebo would not pull down (<gravity>false, <turnGravityOff>): MuJoCo 2.2.2 has no
  // per-body gravity, so Physics cancels it with an equal upward force at each one's centre
  // of mass. `gravity_off_bodies` are their MuJoCo body ids.
  const std::vector<std::string>& gravity_off_links() const { return gravity_off_links_; }
  const std::vector<int>& gravity_off_bodies() const { return gravity_off_bodies_; }
  // URDF joints that are not simulated (massless child link merged into its parent).
  const std::vector<std::string>& dropped_joints() const { return dropped_joints_; }
  // The robot's wheels (WheelInfo), in document order, then the other robots' (actuated world
  // models; their links "<model>::<link>"), narrow ones included.
  const std::vector<WheelInfo>& wheels() const { return wheels_; }
  // The links that look like wheels but are not, one line each with the reason
  // (physics/wheel_identify.hpp), the other robots' under their prefix.
  const std::vector<std::string>& not_wheels() const { return not_wheels_; }
  const std::vector<PassiveShape>& passive_shapes() const { return passive_shapes_; }

  const std::string& mjcf() const { return mjcf_; }  // the generated document (arena size included)
  const ArenaEstimate& arena() const { return arena_; }
  // Geom pairs MuJoCo tests each step without its broad phase (StepCost::listed_pairs); 0 when the
  // broad phase runs (listed pairs off, too many, or not matching MuJoCo's filters: a warning).
  int listed_pairs() const;
  const BuildTimes& build_times() const { return build_times_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Counts of the compiled model (bodies include the world body).
  int body_count() const;
  int dof_count() const;  // MuJoCo nv
  int geom_count() const;
  std::string body_name(int body) const;  // "world" for -1 or 0
  // The compiled body named `name` (a URDF link, "<model>::<link>" of a world's passive model,
  // "box:<name>" of a world's free object), -1 when there is none.
  int body_index(const std::string& name) const;
  // A compiled geom's name ("<link>/collision/<i>", "<link>/visual/<i>", "ground", "terrain",
  // "box:<name>"), "" when unnamed or out of range; and its MuJoCo body (-1 when out of range).
  std::string_view geom_name(int geom) const;
  int geom_body(int geom) const;
  // What a laser reports as the intensity of a hit on the geom (Gazebo's laser_retro of the shape
  // it came from: RobotModel's Collision/GazeboLinkProperties, WorldBox); 0 out of range.
  double geom_laser_retro(int geom) const;

  struct Impl;  // MuJoCo objects; defined in physics/mujoco_internal.hpp
  const Impl& impl() const { return *impl_; }

 private:
  PhysicsModel();
  std::unique_ptr<Impl> impl_;
  std::string robot_name_, root_link_, mjcf_;
  BuildOptions options_;
  ArenaEstimate arena_;
  BuildTimes build_times_;
  std::vector<JointInfo> joints_;
  std::vector<LinkInfo> links_;
  std::optional<DifferentialInfo> differential_;
  std::vector<WheelInfo> wheels_;
  std::vector<std::string> not_wheels_;
  std::vector<PassiveShape> passive_shapes_;
  std::vector<std::string> dropped_joints_, warnings_, gravity_off_links_;
  std::vector<int> gravity_off_bodies_;
  std::vector<float> geom_laser_retro_;  // by MuJoCo geom id
  bool fixed_to_world_ = false;
};

}  // namespace mechsim::physics
