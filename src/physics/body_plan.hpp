#pragma once
// The MuJoCo body tree planned from a RobotModel, before any MJCF is written: which URDF links
// become MuJoCo bodies, which are merged into their parent, where every URDF link frame sits in
// its body, and which joints, geoms and constraints each body carries. Plain data; no MuJoCo.

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "description/robot_model.hpp"
#include "physics/physics_options.hpp"

namespace mechsim::physics {

// A MuJoCo joint (one URDF joint becomes one MuJoCo joint, except planar: 3, floating: 1 or 4).
struct PlannedJoint {
  enum class Kind { Hinge, Slide, Ball, Free };
  std::string name;         // MuJoCo joint name (the URDF name, or "<name>:x" etc. for parts)
  std::string urdf_joint;   // the URDF joint it realises
  Kind kind = Kind::Hinge;
  description::Vec3 axis{0.0, 0.0, 1.0};  // in the body frame, unit
  bool limited = false;
  double lower = 0.0, upper = 0.0;  // rad or m
  double damping = 0.0;             // N m s/rad or N s/m
  double frictionloss = 0.0;        // N m or N
  double effort_limit = 0.0;        // N m or N; 0 = none
  double velocity_limit = 0.0;      // rad/s or m/s; 0 = none
  bool one_dof_urdf = false;        // realises a revolute/continuous/prismatic URDF joint
};

struct PlannedGeom {
  std::string name;  // "<link>/collision/<i>" or "<link>/visual/<i>"
  std::string link;  // the URDF link it came from
  description::Pose X_BG;  // geom frame in its body frame
  description::Geometry geometry;
  bool visual = false;
  bool self_collide = false;  // the source link's gazebo <selfCollide>
  double friction = 1.0;      // sliding
  // What lasers report hitting it (Gazebo's laser_retro): the collision's own, else the link's
  // gazebo <laserRetro>; a visual takes the link's, else its first collision's that has one.
  double laser_retro = 0.0;
  // A wheel: a collision cylinder whose link turns about the cylinder's axis on a revolute or
  // continuous joint (the wheel-soil model acts on these). A narrow one is no longer than its
  // radius (see ContactDefaults::point_contact_wheels).
  bool wheel = false;
  bool narrow_wheel = false;
  std::optional<std::array<double, 4>> rgba;
};

struct PlannedBody {
  std::string name;  // the URDF link that owns the body
  int parent = -1;   // index into BodyPlan::bodies; -1 = world
  description::Pose X_PB;  // body frame in the parent body frame (world frame for parent -1)
  std::optional<description::Inertial> inertial;  // in the body (= link) frame
  std::vector<PlannedJoint> joints;
  std::vector<PlannedGeom> geoms;
};

// Where a URDF link frame L lives: body -1 is the world body.
struct LinkFrame {
  std::string link;
  int body = -1;
  description::Pose X_BL;
};

struct PlannedMimic {
  std::string follower, leader;  // MuJoCo joint names
  double multiplier = 1.0, offset = 0.0;
  // s: the constraint's MuJoCo solref time constant; 0: MuJoCo's default (URDF <mimic>). A mimic
  // joint plugin sets the follower's position every step in Gazebo: its constraint is as stiff as
  // the step allows (two timesteps).
  double time_constant = 0.0;
};

struct PlannedDifferential {
  std::string plugin;          // the gazebo plugin's name
  std::string joint_a, joint_b;  // URDF joint names
  double force_constant = 0.0;   // N m/rad
};

struct BodyPlan {
  std::vector<PlannedBody> bodies;  // parents before children
  std::vector<PlannedGeom> world_geoms;  // geoms of links merged into the world body
  std::vector<LinkFrame> link_frames;    // one per URDF link, document order
  std::vector<PlannedMimic> mimics;
  std::optional<PlannedDifferential> differential;
  std::vector<std::pair<std::string, std::string>> excludes;  // body name pairs never in contact
  std::vector<std::string> gravity_off_links;  // gazebo <gravity>false / <turnGravityOff>, with mass
  std::vector<std::string> dropped_joints;  // URDF joints not simulated (massless child)
  std::vector<std::string> warnings;
  bool fixed_to_world = false;
  // The world's passive models (WorldSpec::models), planned as robots of their own, every name
  // prefixed "<model>::" and their roots placed at the model's pose. No actuators are written
  // for their joints.
  std::vector<BodyPlan> passive;
  // Set on a plan in `passive` of an actuated world model (another robot): its contact bit,
  // 2^(2 + its index among the actuated models), and its one-DOF URDF joints keep their actuators.
  int robot_bit = 0;
};

// Throws PhysicsError (physics/physics_error.hpp) on descriptions MuJoCo cannot represent.
BodyPlan plan_bodies(const description::RobotModel& robot, const BuildOptions& options);

}  // namespace mechsim::physics
