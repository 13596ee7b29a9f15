#pragma once
// The robot's floating base as the tick sees it: a physics port beside the joints. The
// simulation fills BaseState from the physics with the joint states (step 1 of the tick) and
// applies a BaseVelocityCommand before the physics step (step 3), so that a model plugin that
// moves the base itself (gazebo_ros_planar_move: Gazebo's Model::SetLinearVel/SetAngularVel)
// acts inside the tick like every other command, never around it.

#include "description/pose.hpp"

namespace mechsim::mechanism {

// The root link, world frame W. Valid only when `floating` (a robot fixed to the world has none).
struct BaseState {
  bool floating = false;
  description::Pose X_WB;        // pose of the root link frame B in W (m, unit quaternion)
  description::Vec3 linear;      // m/s, velocity of B's origin, in W
  description::Vec3 angular;     // rad/s, angular velocity of B, in W
};

// A planar velocity set on the base before the next physics step, as Gazebo's planar move does:
// the root link's origin gets linear velocity (vx, vy, 0) and angular velocity (0, 0, wz), both
// in W; gravity, contacts and joints act on it from there within the step. Inactive: the physics
// leaves the base alone. Written by the controller that claims the base (control/hardware.hpp).
struct BaseVelocityCommand {
  bool active = false;
  double vx = 0.0, vy = 0.0;  // m/s, W
  double wz = 0.0;            // rad/s, about W's z
};

}  // namespace mechsim::mechanism
