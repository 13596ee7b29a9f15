#pragma once
// A robot's frames as robot_state_publisher computes them, for both ROS bindings' /tf and
// /tf_static (and anything else that needs a link's pose from joint positions): for every URDF
// joint, parent link -> child link = joint origin * joint motion (a rotation about the axis by q
// for revolute and continuous joints, a translation along it for prismatic ones). C++17-clean.

#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::bridge {

// X_PC of a joint at position q (rad or m): origin * motion. Fixed, floating, planar: origin.
description::Pose joint_transform(const description::Joint& joint, double q);

// Whether the joint moves with its position (revolute, continuous, prismatic).
bool moves(const description::Joint& joint);

// One transform of the robot: joint->parent_link -> joint->child_link.
struct JointFrame {
  const description::Joint* joint = nullptr;
  description::Pose X_PC;
};

// The fixed joints' transforms (what goes to /tf_static once), in joint order.
std::vector<JointFrame> fixed_frames(const description::RobotModel& robot);
// The moving joints' transforms at positions q (per robot.joints, as SimBridge::joint_positions
// gives them) into `out` (cleared first; no allocation once it has grown).
void moving_frames(const description::RobotModel& robot, const std::vector<double>& q, std::vector<JointFrame>& out);

}  // namespace mechsim::bridge
