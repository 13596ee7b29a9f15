#pragma once
// The geometry of pr2_head_action's point_head_action (apps/point_head_action.cpp): the joints of
// the chain from the pan link's parent (the root, the PR2's torso_lift_link) to a pointing frame,
// and the joint positions that turn a pointing axis of that frame towards a target point.
// Solved by damped Gauss-Newton on the chain's forward kinematics from zero joint positions, each
// step clamped to the joints' limits (pr2_head_action iterates a Jacobian transpose from zero, and
// clamps too): the result points as close to the target as the limits allow. No ROS types: plain
// C++17 over the URDF (tested in ros_test).

#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::ros {

class HeadPointing {
 public:
  // Throws std::runtime_error naming what the robot lacks (the pan link, its parent, a chain from
  // the root to the pointing frame).
  HeadPointing(const description::RobotModel& robot, const std::string& pan_link, const std::string& pointing_frame);

  const std::string& root() const { return root_; }
  const std::string& pointing_frame() const { return tip_; }
  // The movable joints of the chain, root to tip (the head's pan and tilt joints on the PR2).
  const std::vector<std::string>& joint_names() const { return names_; }

  // The pointing frame in the root frame at joint positions q (per joint_names()).
  description::Pose frame_in_root(const std::vector<double>& q) const;
  // The angle (rad) between the frame's axis (in the frame, any length > 0) and the direction from
  // the frame's origin to the target (in the root frame).
  double pointing_error(const std::vector<double>& q, const description::Vec3& axis, const description::Vec3& target) const;
  // Joint positions that point `axis` at `target` (root frame), within the joints' limits.
  std::vector<double> solve(const description::Vec3& axis, const description::Vec3& target) const;

 private:
  std::vector<const description::Joint*> chain_;  // root to tip
  std::vector<int> movable_;                      // index into chain_ of each joint_names() entry
  std::vector<std::string> names_;
  std::string root_, tip_;
};

}  // namespace mechsim::ros
