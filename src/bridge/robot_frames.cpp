#include "bridge/robot_frames.hpp"

#include <cmath>

#include "physics/transform.hpp"

namespace mechsim::bridge {

bool moves(const description::Joint& j) {
  using description::JointType;
  return j.type == JointType::Revolute || j.type == JointType::Continuous || j.type == JointType::Prismatic;
}

description::Pose joint_transform(const description::Joint& joint, double q) {
  using description::JointType;
  description::Pose motion;
  if (joint.type == JointType::Revolute || joint.type == JointType::Continuous) {
    const double s = std::sin(0.5 * q);
    motion.orientation = {std::cos(0.5 * q), joint.axis.x * s, joint.axis.y * s, joint.axis.z * s};
  } else if (joint.type == JointType::Prismatic) {
    motion.position = {joint.axis.x * q, joint.axis.y * q, joint.axis.z * q};
  }
  return physics::compose(joint.origin, motion);
}

std::vector<JointFrame> fixed_frames(const description::RobotModel& robot) {
  std::vector<JointFrame> out;
  for (const description::Joint& j : robot.joints)
    if (!moves(j)) out.push_back({&j, j.origin});
  return out;
}

void moving_frames(const description::RobotModel& robot, const std::vector<double>& q, std::vector<JointFrame>& out) {
  out.clear();
  for (std::size_t i = 0; i < robot.joints.size() && i < q.size(); ++i) {
    const description::Joint& j = robot.joints[i];
    if (moves(j)) out.push_back({&j, joint_transform(j, q[i])});
  }
}

}  // namespace mechsim::bridge
