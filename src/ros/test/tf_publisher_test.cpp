// The built-in robot state publisher's transform per joint: origin * motion, as
// robot_state_publisher computes it from the URDF.
#include <gtest/gtest.h>

#include <cmath>

#include "ros/tf_publisher.hpp"

namespace mechsim::ros {
namespace {

using description::Joint;
using description::JointType;

constexpr double kPi = 3.14159265358979323846;

// Rotates v by the pose's orientation and adds its position (the child point in the parent).
description::Vec3 apply(const description::Pose& X, const description::Vec3& v) {
  const auto& q = X.orientation;
  // v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
  const double cx = q.y * v.z - q.z * v.y, cy = q.z * v.x - q.x * v.z, cz = q.x * v.y - q.y * v.x;
  const double ccx = q.y * cz - q.z * cy, ccy = q.z * cx - q.x * cz, ccz = q.x * cy - q.y * cx;
  return {X.position.x + v.x + 2 * (q.w * cx + ccx), X.position.y + v.y + 2 * (q.w * cy + ccy),
          X.position.z + v.z + 2 * (q.w * cz + ccz)};
}

TEST(JointTransform, RevoluteRotatesAboutTheAxisAfterTheOrigin) {
  Joint j;
  j.type = JointType::Revolute;
  j.origin.position = {1.0, 0.0, 0.5};
  // origin rotated 90 degrees about z: the joint's x axis is the parent's y axis
  j.origin.orientation = {std::cos(kPi / 4), 0.0, 0.0, std::sin(kPi / 4)};
  j.axis = {0.0, 0.0, 1.0};
  const description::Pose X = joint_transform(j, kPi / 2);
  // The child's x axis after 90 + 90 degrees about z points along the parent's -x.
  const description::Vec3 p = apply(X, {1.0, 0.0, 0.0});
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, 0.0, 1e-12);
  EXPECT_NEAR(p.z, 0.5, 1e-12);
  const double norm = X.orientation.w * X.orientation.w + X.orientation.x * X.orientation.x +
                      X.orientation.y * X.orientation.y + X.orientation.z * X.orientation.z;
  EXPECT_NEAR(norm, 1.0, 1e-12);
}

TEST(JointTransform, PrismaticTranslatesAlongTheAxisInTheJointFrame) {
  Joint j;
  j.type = JointType::Prismatic;
  j.origin.position = {0.0, 0.0, 1.0};
  j.origin.orientation = {std::cos(kPi / 4), std::sin(kPi / 4), 0.0, 0.0};  // 90 degrees about x
  j.axis = {0.0, 1.0, 0.0};  // the joint's y is the parent's z after the origin rotation
  const description::Pose X = joint_transform(j, 0.3);
  EXPECT_NEAR(X.position.x, 0.0, 1e-12);
  EXPECT_NEAR(X.position.y, 0.0, 1e-12);
  EXPECT_NEAR(X.position.z, 1.3, 1e-12);
}

TEST(JointTransform, FixedJointIsItsOriginWhateverQ) {
  Joint j;
  j.type = JointType::Fixed;
  j.origin.position = {0.0, 0.0, 0.25};
  const description::Pose X = joint_transform(j, 1.0);
  EXPECT_DOUBLE_EQ(X.position.z, 0.25);
  EXPECT_DOUBLE_EQ(X.orientation.w, 1.0);
}

}  // namespace
}  // namespace mechsim::ros
