#pragma once
// One running physics instance: per-instance MuJoCo data (and a private copy of the compiled
// model, because servo gains change at run time) over a shared, immutable PhysicsModel.
// Joint I/O is by joint index (PhysicsModel::joint_index). Units: rad, m, s, N, N m.
//
// Hot path: step(), the joint reads/writes and the pose/twist queries allocate nothing and
// throw nothing. Deterministic: the same model, commands and call sequence give bit-identical
// trajectories.

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "description/robot_model.hpp"
#include "physics/physics_model.hpp"
#include "physics/ray_cast.hpp"
#include "physics/soil.hpp"
#include "physics/terramechanics.hpp"
#include "physics/wheel_override.hpp"

namespace mechsim::physics {

// How a joint's actuator is driven. Position and velocity are servos computed inside the
// physics step from the current state (never a kinematic override), bounded by the joint's
// effort limit like every other mode.
enum class JointMode { Effort, Position, Velocity };

// s: time constant of a velocity motor's integral correction (ServoGains::motor).
inline constexpr double kMotorIntegralTime = 0.2;

struct ServoGains {
  double kp = 0.0;  // N m/rad or N/m (position mode)
  double kv = 0.0;  // N m s/rad or N s/m (position mode: damping; velocity mode: gain)
  // Velocity mode only: a joint motor (Gazebo's "vel" + "fmax") rather than a plain servo: the
  // servo's set point gets an integral correction (time constant kMotorIntegralTime), so that it
  // reaches the commanded speed under load unless the joint's effort bound stops it (the
  // correction is bounded by what that bound lets the servo use). kv 0: the stiffest gain an
  // explicit servo keeps stable as the joint's inertia changes: half the joint's inertia at the
  // spawn configuration over the timestep (a one-step servo for half of it).
  bool motor = false;
};

enum class StepCode {
  Ok,
  NonFiniteCommand,     // a commanded effort/position/velocity is NaN or infinite
  NonFiniteState,       // position, velocity or acceleration became NaN or infinite
  RunawayAcceleration,  // |acceleration| exceeded BuildOptions::max_joint_acceleration
  SolverFailure,        // MuJoCo itself flagged a bad state (and would have reset it)
  ArenaFull,            // the step's contacts or constraints did not fit the arena (element says
                        // which; value: the most it holds), and it could not grow (ArenaOverflow)
};

// The outcome of step(). On failure the state is left as it was before the step and `element`
// names the offending joint (or, for a floating base, the body; for ArenaFull "contacts" or
// "constraints").
struct StepStatus {
  StepCode code = StepCode::Ok;
  std::string_view element;  // joint or body name; valid while the PhysicsModel lives
  double value = 0.0;        // the offending value
  bool ok() const { return code == StepCode::Ok; }
  std::string message() const;  // for logs; allocates
};

// A spatial velocity in the world frame, of a link frame's origin.
struct Twist {
  description::Vec3 linear;   // m/s
  description::Vec3 angular;  // rad/s
};

// An axis-aligned box in the world frame (m); empty when min > max.
struct Bounds {
  description::Vec3 min{1e300, 1e300, 1e300}, max{-1e300, -1e300, -1e300};
  bool empty() const { return min.x > max.x; }
};

// Something MuJoCo reported in a step that did not fail it, kept for the user: the arena grew (the
// step was computed again in the larger one, so the physics is unchanged), or a MuJoCo warning
// such as a singular inertia matrix. One notice per growth; one per kind of MuJoCo warning, whose
// `count` goes on counting.
struct PhysicsNotice {
  enum class Kind { ArenaGrown, MujocoWarning };
  Kind kind = Kind::MujocoWarning;
  double time = 0.0;  // s, Physics::time() at the start of the step that first raised it
  std::string text;   // what happened and the counts (contacts, constraints, the DOF)
  long count = 1;     // steps that raised it
};

// How full the arena has been: the most contacts and constraint rows one step has needed since
// construction (MuJoCo's maxuse_con and maxuse_efc), against the arena's current size.
struct ArenaUse {
  ArenaSize size;           // now (grown or as built)
  ArenaSize peak;           // the most one step used
  int growths = 0;          // times the arena grew
};

struct Contact {
  std::string_view link_a, link_b;  // URDF link names, or "ground" / "terrain"
  int geom_a = -1, geom_b = -1;     // MuJoCo geoms (PhysicsModel::geom_name)
  description::Vec3 position;       // world frame (m)
  description::Vec3 normal;         // world frame, from a to b
  double depth = 0.0;               // penetration (m), positive when overlapping
  double normal_force = 0.0;        // N, >= 0
  double friction_force[2] = {0.0, 0.0};  // N, along the contact frame's tangents
  description::Vec3 force;          // world frame (N): normal and friction, the force a exerts on b
};

// A wheel the soil acts on (Physics::soil_wheels()): PhysicsModel::wheels() with the world's
// overrides applied.
struct SoilWheelInfo {
  std::string link;
  std::size_t joint = 0;        // index into PhysicsModel::joints()
  int geom = -1, body = -1;     // MuJoCo geom and body
  WheelShape shape;             // radius, width, grousers (m)
  bool narrow = false;          // width <= radius
  bool axis_from_joint = false; // the axle is the joint's axis (not the geom's z: meshes, spheres)
  std::string origin;           // "its collision cylinder" or "world.wheels (file:line)"
};

// What the soil did to one wheel (Physics::soil_wheels()) in the last step (Physics::set_soil).
// Heading: the direction the wheel rolls, across its axle, along the ground.
struct WheelSoilReading {
  bool contact = false;       // in the soil
  // Slip and slip angle are defined while the wheel rolls or slides at all: moving is true when
  // max(|r w|, |v|) (for the slip) or the ground speed (for the slip angle) exceeds
  // kSlipRestSpeed, 0.1 mm/s (a test rig's carriage runs at a few mm/s). Below it they are 0 and
  // the flags false: undefined, not zero (the report leaves them blank).
  bool moving = false;        // slip defined
  bool sliding = false;       // slip angle defined
  double slip = 0.0;          // (r w - v) / max(|r w|, |v|): > 0 spinning faster than it travels
                              // (driving), < 0 slower (braking); v along the heading, r the rim's
                              // radius (without grousers)
  double slip_angle = 0.0;    // rad: atan2(sideways velocity, |velocity along the heading|)
  double sinkage = 0.0;       // m, of the wheel's lowest point below the soil surface
  double normal_force = 0.0;  // N, the load the soil carries
  double traction = 0.0;      // N, net drawbar pull along the heading (> 0 pulls forward)
  double lateral_force = 0.0; // N, along the axle
  double torque = 0.0;        // N m about the axle (< 0 resists a wheel driven forward)
  double rut_depth = 0.0;     // m: how deep another wheel compacted the soil where this one is
                              // (SoilParameters::multi_pass), 0 on virgin soil
};
inline constexpr double kSlipRestSpeed = 1e-4;  // m/s

// Acceleration of a point (Physics::link_acceleration), world frame.
struct Acceleration {
  description::Vec3 angular;         // rad/s^2
  // m/s^2: the point's acceleration minus gravity, what an accelerometer measures (+g up at rest)
  description::Vec3 specific_force;
};

struct Wrench {
  description::Vec3 force;   // N
  description::Vec3 torque;  // N m, about the point the wrench is given at
};

class Physics {
 public:
  explicit Physics(std::shared_ptr<const PhysicsModel> model);
  ~Physics();
  Physics(const Physics&) = delete;
  Physics& operator=(const Physics&) = delete;

  const PhysicsModel& model() const { return *model_; }

  // Advances the world by one timestep (PhysicsModel::timestep()).
  StepStatus step();
  double time() const;  // s since reset

  // Back to the spawn state: spawn pose, zero joint positions and velocities, all joints in
  // effort mode with zero command, time 0. Reuses the arena (a grown one stays grown); no allocation.
  void reset();

  // See PhysicsNotice; kept over reset(). Grows only when something new happens (allocates then).
  const std::vector<PhysicsNotice>& notices() const { return notices_; }
  ArenaUse arena_use() const;

  std::size_t joint_count() const { return model_->joints().size(); }
  double position(std::size_t joint) const;  // rad or m
  double velocity(std::size_t joint) const;  // rad/s or m/s
  // Generalised force on the joint from its actuator (effort command, servo or motor), N m or N.
  double actuator_effort(std::size_t joint) const;
  // Generalised force from constraints: limits, friction loss, contacts, mimic equalities.
  double constraint_effort(std::size_t joint) const;
  // Generalised force applied by plugin laws (the differential spring), N m or N.
  double applied_effort(std::size_t joint) const;
  // actuator + applied + constraint effort: everything acting on the joint in the last step
  // (Gazebo's Joint::GetForce sums what was set on the joint, plugins included).
  double effort(std::size_t joint) const;

  // Commands, applied by the next step(). set_effort is for JointMode::Effort; the others
  // select their servo's set point. NaN/inf is caught by step() and reported.
  void set_effort(std::size_t joint, double effort);
  void set_position_command(std::size_t joint, double position);
  void set_velocity_command(std::size_t joint, double velocity);
  // Switches the joint's actuator mode by setting its gains. Gains of zero choose a default:
  // a critically damped 10 Hz servo for the joint's inertia at the spawn configuration.
  void set_mode(std::size_t joint, JointMode mode, ServoGains gains = {});
  JointMode mode(std::size_t joint) const;
  ServoGains gains(std::size_t joint) const;

  // Rotor inertia reflected onto the joint (MuJoCo armature: kg m^2 for hinges, kg for slides),
  // added to the joint's diagonal of the mass matrix; this instance only, kept over reset().
  // For drives whose motor the description does not model (the PR2 gripper's fingers). Not for
  // the control loop: the model's constants at qpos0 are recomputed (mj_setConst, allocating)
  // before the next step, once for any number of armatures set in a row.
  // Throws std::invalid_argument on a negative or non-finite value.
  void set_armature(std::size_t joint, double armature);
  double armature(std::size_t joint) const;

  // The inertia the joint's own effort sees in the current configuration, every other joint
  // (and a floating base) free: 1 / (M^-1)_jj (kg m^2 or kg, armature included). Joint damping
  // (N m s/rad or N s/m) as MuJoCo integrates it, implicitly. Both for set-up decisions, not
  // for the control loop (they allocate and recompute the mass matrix).
  double effective_inertia(std::size_t joint) const;
  double joint_damping(std::size_t joint) const;
  // Gazebo's set_joint_properties and set_link_properties on a running model (this instance's
  // copy only; physics_properties.cpp). Damping (N m s/rad or N s/m) throws std::invalid_argument
  // when negative or not finite; limits (rad or m) when not finite or lower > upper (they bound the
  // joint from the next step on). A link's inertial: mass (kg), its centre-of-mass frame X_LC and
  // the tensor there (kg m^2: ixx ixy ixz iyy iyz izz); "" when set, else why not (a link sharing
  // its physics body with another, a non-physical tensor).
  void set_joint_damping(std::size_t joint, double damping);
  void set_joint_limits(std::size_t joint, double lower, double upper);
  std::pair<double, double> joint_limits(std::size_t joint) const;  // (-inf, inf) when unlimited
  std::string set_link_inertial(std::size_t link, double mass, const description::Pose& X_LC,
                                const std::array<double, 6>& inertia);

  // Bounds the joint's actuator effort in every mode to +-limit (N m or N), for the following
  // steps: a Gazebo model plugin's velocity motor torque (Gazebo's joint "fmax"). 0 gives back the
  // joint's own bound (JointInfo::effort_limit, none when that is 0). Hot path: no allocation.
  void set_effort_limit(std::size_t joint, double limit) noexcept;

  // The floating root link's pose X_WB and twist (world frame, at B's origin), read straight from
  // the state (no kinematics pass: cheap enough for every tick). False when the robot is fixed to
  // the world.
  bool root_state(description::Pose& X_WB, Twist& V_WB) const noexcept;
  // The same for any link whose body floats on a free joint of its own (another robot's root,
  // "<model>::<root>"): false, changing nothing, for one that does not. Hot path.
  bool free_link_state(std::size_t link, description::Pose& X_WL, Twist& V_WL) const noexcept;
  // Sets the floating root link's velocity (world frame, at B's origin) for the next step, as
  // Gazebo's Model::SetLinearVel/SetAngularVel: gravity, contacts and joints act from there within
  // the step. Hot path (no allocation); ignored when the robot is fixed to the world.
  void command_root_velocity(const Twist& V_WB) noexcept;
  // The same for a link whose body floats on a free joint of its own (another robot's root);
  // ignored for one that does not.
  void command_free_link_velocity(std::size_t link, const Twist& V_WL) noexcept;

  // A world rebuilt with more or fewer robots or objects goes on from `old`'s state: time,
  // gravity, soil (every wheel's soil state by its link, and the ruts); for every body of both
  // models (by name) its joints' positions, velocities and spawn positions; for every joint of both (by name) its
  // mode, servo gains, command, motor integral, effort bound and armature. What is new keeps its
  // spawn state. Not for a loop (allocates).
  void take_state_from(const Physics& old);

  // Initial conditions (not for use inside a control loop): sets a joint's state directly.
  void set_joint_state(std::size_t joint, double position, double velocity = 0.0);

  // Initial conditions of a floating robot's root body (ignored when fixed to the world):
  // pose X_W<root> and twist in the world frame at the root body's origin.
  void set_base_pose(const description::Pose& X_WB);
  void set_base_twist(const Twist& V_WB);
  // Moves a floating robot's spawn pose X_W<root> (where reset() returns) and resets to it; for
  // set-up only (recomputes the model's constants, allocates nothing but is not for a loop).
  // Ignored when the robot is fixed to the world.
  void set_spawn_pose(const description::Pose& X_WB);
  // The same for a link floating on a free joint of its own (another robot's root): its spawn
  // pose becomes X_WL and every body goes back to its spawn state, so only for a physics just
  // built (a world rebuilt with another robot, before take_state_from). False, changing nothing,
  // for a link without one.
  bool set_free_link_spawn_pose(std::size_t link, const description::Pose& X_WL);

  // Forces from outside (Gazebo's apply_body_wrench / apply_joint_effort; sim/external_forces.hpp
  // keeps their timing): they act in every step until changed, on top of everything else, and
  // reset() clears them. clear_external_forces() removes all of them; the add_* calls add to what
  // is there. A wrench on a link: force_W (N) acting at the centre of mass of the link's body
  // moved by offset_W (m), plus torque_W (N m), world frame (gazebo_ros' reference_point); on a
  // link without a body of its own, on the body it is merged into. A joint effort is a
  // generalised force (N m or N). None allocates.
  void clear_external_forces();
  void add_link_wrench(std::size_t link, const description::Vec3& force_W, const description::Vec3& torque_W,
                       const description::Vec3& offset_W);
  void add_joint_effort(std::size_t joint, double effort);
  // Gravity (m/s^2, world frame) of this instance; set_gravity keeps the links Gazebo exempts
  // from gravity exempt. Kept over reset().
  description::Vec3 gravity() const;
  void set_gravity(const description::Vec3& g_W);

  // Pose X_WL and twist of URDF link `link` (PhysicsModel::link_index).
  description::Pose link_pose(std::size_t link) const;
  Twist link_twist(std::size_t link) const;
  // Any compiled body's frame (PhysicsModel::body_index, e.g. a world object's) and the twist of
  // its origin, world frame. `body` must be in [1, body_count()).
  description::Pose body_pose(int body) const;
  Twist body_twist(int body) const;
  // The body's centre of mass, world frame (m).
  description::Vec3 body_com(int body) const;
  // Sets a body that floats on a free joint of its own (a world's free object or passive model's
  // root) to pose X_WB with twist V (world frame, at its origin); false, changing nothing, for a
  // body without one.
  bool set_free_body_state(int body, const description::Pose& X_WB, const Twist& V);
  description::Pose base_pose() const;  // the root link
  Twist base_twist() const;

  // The box around the robot's collision geometry in its current pose (meshes by their bounding
  // spheres); empty for a robot without collision geometry. The robot's footprint on the ground
  // is its x-y extent.
  Bounds robot_bounds() const;
  // The same for the collision geometry of the links whose names begin with `link_prefix`
  // (another robot's: "<name>::"); "" for the first robot's alone (links without "::").
  Bounds collision_bounds(const std::string& link_prefix) const;

  // Wheel-soil: with a soil, every wheel of the model (PhysicsModel::wheels(), narrow ones
  // included), as `wheels` overrides it (WheelOverride: a link that is not a wheel, one that is,
  // dimensions, grousers), meets the ground through the soil's wheel-soil model (terramechanics.hpp)
  // instead of rigid contact: step() computes each wheel's sinkage, slip and slip angle from the
  // state and applies the soil's force and moment to the wheel's body within the step (MuJoCo's
  // mj_step1, the forces, mj_step2). The wheels' rigid contact with the ground then starts
  // soil.bedrock_depth below its surface (a bound on sinkage); other contacts are untouched.
  // nullopt (the default): rigid ground. Set-up only (allocates); the soil's state (shear
  // displacements) restarts on reset(). Throws std::invalid_argument naming the bad parameter
  // (check_soil), the wheel a soil cannot carry (check_soil_width) or the override's link.
  void set_soil(std::optional<SoilParameters> soil, std::vector<WheelOverride> wheels = {});
  const std::optional<SoilParameters>& soil() const;
  // The wheels the soil acts on (empty without a soil), and one line for each wheel an override
  // took out.
  const std::vector<SoilWheelInfo>& soil_wheels() const;
  const std::vector<std::string>& soil_wheel_notes() const;
  // One reading per soil_wheels() for the last step; empty without a soil.
  const std::vector<WheelSoilReading>& wheel_soil() const;

  // Contacts of the last step. Fills `out` (cleared first); allocates only when `out` has
  // too little capacity. Returns the number of contacts.
  std::size_t contacts(std::vector<Contact>& out) const;

  // Torques the differential plugin law applied in the last step on its joints A and B (N m).
  double differential_torque_a() const { return diff_tau_a_; }
  double differential_torque_b() const { return diff_tau_b_; }

  // Height (m) of the world's ground (plane or terrain) under (x, y), by a ray cast straight
  // down; NaN where there is no ground.
  double ground_height(double x, double y) const;

  // Sensing (sensors/ calls these at the sensors' rates; they allocate nothing).
  // Casts `count` rays from `origin` along the unit `directions` (world frame) against the shapes
  // of `filter` (ray_cast.hpp), from `near` to `far` (m) along each: ranges[i] is the distance
  // from the origin to the first hit, +inf when nothing is hit within [near, far]. Nothing nearer
  // than `near` is seen (Gazebo's rays start at the minimum range). `hit_geoms`, when given, gets
  // each ray's hit geom (MuJoCo id, PhysicsModel::geom_laser_retro), -1 where nothing is hit.
  void cast_rays(const RayFilter& filter, const description::Vec3& origin, const description::Vec3* directions,
                 std::size_t count, double near, double far, double* ranges, int* hit_geoms = nullptr) const;
  // Acceleration of the point p_L (link frame, m) fixed to link `link` over the last step, in the
  // world frame (MuJoCo's post-constraint recursive Newton-Euler: a few microseconds; not for
  // every tick of a large model).
  Acceleration link_acceleration(std::size_t link, const description::Vec3& p_L) const;
  // The wrench the parent body applies to link `link`'s body through its joint in the last step
  // (everything the joint transmits: constraint, actuator, limits), at point p_L of the link,
  // world frame. Meaningful only when the link has its own MuJoCo body (LinkInfo::body differs
  // from its parent link's).
  Wrench joint_wrench(std::size_t link, const description::Vec3& p_L) const;

  // Total mechanical energy (J) of the robot: kinetic + gravitational potential.
  double energy() const;

  struct Data;  // MuJoCo objects; physics.cpp only
  const Data& data() const { return *data_; }  // for physics/ only (physics_data.hpp)

 private:
  // Free joint `joint`'s spawn configuration (qpos0) becomes X_WBody; every body back to its spawn
  // state (set_spawn_pose, set_free_link_spawn_pose).
  void set_free_joint_spawn(int joint, const description::Pose& X_WBody);

  void refresh_kinematics() const;
  // The twist of the point p_W (world frame) moving with body b.
  Twist point_twist(int b, const description::Vec3& p_W) const;
  void ensure_constants();
  void save_state();
  void restore_saved_state();
  void spawn_state();
  void forward();
  // Runs mj_step (step) or mj_forward from the saved state until it fits the arena, growing it
  // as ArenaOverflow allows; false when it did not fit.
  bool compute_in_arena(bool step);
  // One mj_step, with the soil's forces on the wheels when there is a soil (wheel_soil.cpp), body
  // forces as joint forces (StepCost::tree_external_forces).
  void mujoco_step();
  // mj_step2 with xfrc_applied as joint forces gathered over the body tree (tree_forces.cpp).
  void step2_with_tree_forces();
  void apply_soil();     // from the state at the start of the step: forces, pending soil state
  void commit_soil();    // the step succeeded: its soil state becomes the state
  bool grow_arena(bool contacts_full, bool constraints_full, const char* what);
  void note_mujoco_warnings();
  std::shared_ptr<const PhysicsModel> model_;
  std::vector<PhysicsNotice> notices_;
  std::unique_ptr<Data> data_;
  double diff_tau_a_ = 0.0, diff_tau_b_ = 0.0;
};

}  // namespace mechsim::physics
