#pragma once
// Options for building the MuJoCo model of one robot in one world.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "description/robot_model.hpp"
#include "physics/contact_defaults.hpp"
#include "physics/heightmap.hpp"

namespace mechsim::physics {

enum class Integrator {
  Euler,     // MuJoCo semi-implicit Euler, joint damping implicit (default; Gazebo ODE's kind)
  Rk4,       // 4th-order Runge-Kutta: best energy behaviour for smooth, contact-free systems
  Implicit,  // implicit in velocity: damping, servo velocity gains and Coriolis terms implicit
};

// The name used in scenario files and on the command line: "euler", "rk4", "implicit".
constexpr const char* integrator_name(Integrator i) {
  return i == Integrator::Euler ? "euler" : i == Integrator::Rk4 ? "rk4" : "implicit";
}

// The integrator named `name` (as integrator_name writes it); nullopt for any other text.
constexpr std::optional<Integrator> parse_integrator(std::string_view name) {
  if (name == "implicit") return Integrator::Implicit;
  if (name == "euler") return Integrator::Euler;
  if (name == "rk4") return Integrator::Rk4;
  return std::nullopt;
}

// How the CC8 rocker differential (or any gazebo differential plugin) is realised.
enum class DifferentialMode {
  // The URDF's <mimic> tags as MuJoCo joint equality constraints; the plugin is ignored.
  MimicConstraint,
  // The Gazebo differential plugin's spring law, applied every step:
  // tau_A = -k (q_A - q_B), tau_B = +k (q_A - q_B), k = forceConstant (N m/rad).
  // A <mimic> tag coupling the plugin's two joints is then not turned into a constraint.
  PluginLaw,
};

// An object in the world (to grasp, push or bump into): a box, a cylinder or a sphere (the
// shapes of Gazebo's SDF worlds), or a fixed mesh (a static SDF model's). A fixed one is a world geom; a free one is a body with a free
// joint, after the robot's (the robot's root stays the first free joint). Both collide with the
// robot and the ground, with their surface's friction (each contact takes the smaller of its two
// surfaces', contact_defaults.hpp); contacts name them "box:<name>" whatever the shape (the name
// scenarios and contact sensors already use).
struct WorldBox {
  enum class Shape { Box, Cylinder, Sphere, Mesh };
  std::string name;                      // unique among the world's objects
  description::Pose pose;                // X_W<centre>; a cylinder's axis is its z; a mesh's own frame
  // The extents along the object's x, y, z (m), > 0: a box's edges; a cylinder's diameter,
  // diameter (equal) and length; a sphere's diameter three times; a mesh's bounding box (scaled),
  // which spans mesh_min..mesh_min + size in its frame.
  description::Vec3 size{0.1, 0.1, 0.1};
  Shape shape = Shape::Box;
  // Mesh only: the file (STL, OBJ, or anything assimp reads, as robot meshes), its scale, and its
  // bounds' low corner (m, scaled). MuJoCo collides with its convex hull; a free one's mass fills
  // its bounds (a solid box's inertia about the bounds' centre).
  std::string mesh_path;
  description::Vec3 mesh_scale{1.0, 1.0, 1.0};
  description::Vec3 mesh_min{0.0, 0.0, 0.0};
  double mass = 1.0;                     // kg, > 0; free objects only (uniform density; a mesh's
                                         // as if it filled its bounds)
  bool fixed = true;
  double laser_retro = 0.0;              // what lasers report hitting it (SDF <laser_retro>)
  // The surface's friction along fdir1 and across it (SDF <mu>, <mu2>; unset: Gazebo's 1), one
  // coefficient in the physics (isotropic_friction).
  std::optional<double> mu, mu2;
};

// A passive articulated object in the world (an SDF world's moving model of several links): its
// links and joints as a description, its root link at `pose`. Nothing drives it (no actuators,
// no controllers); its joints keep their damping, friction and limits; its names in the MuJoCo
// model are prefixed "<name>::". It collides with the world, the robot and its own links as a
// world object does.
//
// `actuated`: another robot in the same world (Gazebo's second spawned model) rather than an
// object. Its URDF joints get actuators and appear in PhysicsModel::joints() as
// "<name>::<joint>" (effort, servo and motor commands as the robot's), its links in links() as
// "<name>::<link>"; it collides with the world, the robot and the other robots, and its own links
// touch each other only where the description's selfCollide says (as the robot's do); its wheels
// meet the soil as the robot's do (PhysicsModel::wheels()). Its mimic joints are constraints; the
// differential plugin's law acts on the first robot only.
struct WorldModel {
  std::string name;
  std::shared_ptr<const description::RobotModel> robot;
  description::Pose pose;  // X_W<root link> (for a root link `world`: of the description's world frame)
  bool actuated = false;
};

// The most actuated world models one physics holds (one contact bit each, MuJoCo's masks are 32
// bits, signed: the world's and the first robot's come first).
inline constexpr int kMaxActuatedModels = 29;

// The world the robot is placed in.
struct WorldSpec {
  enum class Kind { Empty, Heightmap };
  Kind kind = Kind::Empty;        // Empty: ground plane z = 0 and gravity
  SharedHeightmap terrain;         // required when kind == Heightmap
  double gravity = 9.81;           // m/s^2 along -z of the world
  bool ground_plane = true;        // an infinite plane at z = 0 (Empty only)
  // The ground plane's friction along fdir1 and across it: Gazebo's ground_plane model's (mu 100,
  // mu2 50) unless an SDF world's plane says otherwise; one coefficient in the physics, their
  // mean (isotropic_friction). Height fields have ContactDefaults::ground_friction.
  std::optional<double> ground_mu = 100.0, ground_mu2 = 50.0;
  std::vector<WorldBox> boxes;     // objects in the world (any kind of world)
  std::vector<WorldModel> models;  // passive articulated objects and other robots (WorldModel)
};

// Where the robot starts: X_W<root> for a floating robot; for a robot whose root link is
// `world`, the pose of the URDF world frame in the simulation world.
struct SpawnPose {
  double x = 0.0, y = 0.0, z = 0.0;           // m
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // rad, fixed axes, URDF convention
};

// The size of MuJoCo 2.2.2's per-instance contact and constraint arena (its <size nconmax njmax>).
// Memory: about 12 bytes x constraints^2 (the constraint solver's dense matrices), allocated and
// zeroed by every mj_makeData; MuJoCo adds a stack of 40 (constraints + dofs)^2 bytes of address
// space, touched only as used.
struct ArenaSize {
  int contacts = 0;     // contacts one step can hold (nconmax)
  int constraints = 0;  // scalar constraint rows one step can hold (njmax): contacts, limits, ...
  bool operator==(const ArenaSize& o) const { return contacts == o.contacts && constraints == o.constraints; }
};

// What a step does when its contacts or constraints do not fit the arena (MuJoCo would drop the
// surplus, which changes the physics).
enum class ArenaOverflow {
  // Double what overflowed (up to BuildOptions::max_arena), rebuild the instance's data with its
  // state, and compute the step again: the physics is exactly that of a large enough arena.
  // Each growth is reported (Physics::notices()).
  Grow,
  Fail,  // the step fails with StepCode::ArenaFull and the state stays as before it
};

// The most constraints an arena may have: MuJoCo 2.2.2 sizes its stack 5 (njmax + nv)^2 in an int.
inline constexpr int kMaxArenaConstraints = 16000;

// Ways of computing the same MuJoCo step at less cost (physics/README.md, "Step cost"). None
// changes what is simulated: the same contacts with the same parameters, the same equations and
// solver; results differ from the slower way by floating-point rounding only (the order of sums).
// `before()` turns all off: the step as mechsim computed it before, for benchmarks and fidelity
// comparisons in one run (mechsim bench --compare-step-cost).
struct StepCost {
  // Every geom pair that MuJoCo's collision filters let touch (contype/conaffinity, welded and
  // parent/child bodies, excludes) as a predefined pair with the contact parameters MuJoCo would
  // give it, tested every step without a broad phase (<option collision="predefined">), when at most
  // kMaxListedMovingPairs of them join two movable bodies; else MuJoCo's broad phase. On the PR2
  // (no self-collision, 61 collision geoms) the broad phase swept 74 bodies and tested ~900 geom
  // pairs of overlapping links a step to find 8 wheel contacts: a quarter of the step.
  bool listed_pairs = true;
  // The constraint solver's Jacobian in MuJoCo's sparse form (mjJAC_SPARSE; MuJoCo's "auto" picks
  // it from 60 DOFs): a branched robot's contact and equality rows touch a few of its DOFs.
  bool sparse_jacobian = true;
  // Cartesian forces on bodies (xfrc_applied: gravity-off links, outside wrenches, the soil's
  // wheel forces) turned into joint forces in one pass over the body tree, where MuJoCo 2.2.2
  // builds a dense Jacobian per body (mj_applyFT: a tenth of the PR2's step for its 40 gravity-off
  // links). Euler and implicit integrators; RK4 keeps MuJoCo's (its stages move the bodies).
  bool tree_external_forces = true;
  static constexpr StepCost before() { return {false, false, false}; }
  bool operator==(const StepCost&) const = default;
};

// Most listed pairs (StepCost::listed_pairs) between two movable bodies: each is tested every step
// (a bounding-sphere test, ~0.1 us), where MuJoCo's sweep and prune finds the close ones.
inline constexpr int kMaxListedMovingPairs = 1000;

struct BuildOptions {
  double timestep = 0.001;  // s (1 kHz)
  // Euler is the default, measured against Implicit on every acceptance test (PR2 and CC8, 1 ms):
  // the same figures at 1/3 of the PR2's step (70 vs 250 us) and 1/2 of the CC8's. (Implicit's
  // extra cost is MuJoCo 2.2's full velocity derivative of the Coriolis forces.) See
  // robots/pr2/README.md. Choose per run with SimulationOptions / scenario `integrator:`.
  Integrator integrator = Integrator::Euler;
  DifferentialMode differential = DifferentialMode::MimicConstraint;
  ContactDefaults contact;
  WorldSpec world;
  SpawnPose spawn;
  bool visuals = true;  // build visual geoms (group 1, never collide) for rendering
  // Also build render-only tiles of a height field at several levels of detail (group 3, never
  // collide; physics/terrain_tiles.hpp), for cameras. No effect on an empty world.
  bool render_terrain = false;
  // Runaway detector: |joint acceleration| above this (rad/s^2 or m/s^2) fails the step.
  double max_joint_acceleration = 1e6;
  // Initial arena of each Physics instance; nullopt: sized from what can touch what in the model
  // (PhysicsModel::arena()). Growth never goes past max_arena (8000 constraints: ~0.8 GB).
  std::optional<ArenaSize> arena;
  ArenaOverflow arena_overflow = ArenaOverflow::Grow;
  ArenaSize max_arena{16000, 8000};
  StepCost step_cost;  // cheaper ways to the same step (all on by default)
};

}  // namespace mechsim::physics
