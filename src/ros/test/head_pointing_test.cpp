// The geometry of mechsim's point_head_action (head_pointing.hpp) on a PR2-like head of our own: a
// pan joint about z on the torso, a tilt joint about y 6.8 cm ahead of it, a camera frame above
// the tilt link and an optical frame looking along its z. The solved joints point the axis at the
// target (angle below 1e-6 rad), and stay within the joints' limits where the target is out of
// reach.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "description/urdf/urdf_parser.hpp"
#include "ros/head_pointing.hpp"

namespace mechsim::ros {
namespace {

constexpr const char* kHead = R"(<robot name="head">
  <link name="base_link"/>
  <link name="torso_lift_link"/>
  <joint name="torso_joint" type="fixed"><parent link="base_link"/><child link="torso_lift_link"/><origin xyz="-0.05 0 0.8"/></joint>
  <link name="head_pan_link"/>
  <joint name="head_pan_joint" type="revolute"><parent link="torso_lift_link"/><child link="head_pan_link"/>
    <origin xyz="-0.01707 0 0.38145"/><axis xyz="0 0 1"/><limit lower="-2.857" upper="2.857" effort="6" velocity="6"/></joint>
  <link name="head_tilt_link"/>
  <joint name="head_tilt_joint" type="revolute"><parent link="head_pan_link"/><child link="head_tilt_link"/>
    <origin xyz="0.068 0 0"/><axis xyz="0 1 0"/><limit lower="-0.3712" upper="1.29626" effort="5" velocity="5"/></joint>
  <link name="camera_link"/>
  <joint name="camera_joint" type="fixed"><parent link="head_tilt_link"/><child link="camera_link"/><origin xyz="0.05 0.03 0.12"/></joint>
  <link name="camera_optical_frame"/>
  <joint name="optical_joint" type="fixed"><parent link="camera_link"/><child link="camera_optical_frame"/>
    <origin rpy="-1.5707963 0 -1.5707963"/></joint>
</robot>)";

description::RobotModel head() { return description::parse_urdf_string(kHead, "head.urdf", {}); }

TEST(HeadPointing, TheChainRunsFromThePanLinksParentToThePointingFrame) {
  const description::RobotModel robot = head();
  const HeadPointing h(robot, "head_pan_link", "camera_optical_frame");
  EXPECT_EQ(h.root(), "torso_lift_link");
  EXPECT_THAT(h.joint_names(), ::testing::ElementsAre("head_pan_joint", "head_tilt_joint"));
  const description::Pose X = h.frame_in_root({0.0, 0.0});
  EXPECT_NEAR(X.position.x, -0.01707 + 0.068 + 0.05, 1e-12);
  EXPECT_NEAR(X.position.z, 0.38145 + 0.12, 1e-12);
  EXPECT_THROW(HeadPointing(robot, "no_such_link", "camera_link"), std::runtime_error);
  EXPECT_THROW(HeadPointing(robot, "head_pan_link", "nowhere"), std::runtime_error);
  EXPECT_THROW(HeadPointing(robot, "head_pan_link", "base_link"), std::runtime_error);  // not below the root
}

TEST(HeadPointing, PointsTheAxisAtTheTarget) {
  const description::RobotModel robot = head();
  for (const char* frame : {"head_tilt_link", "camera_link", "camera_optical_frame"}) {
    const HeadPointing h(robot, "head_pan_link", frame);
    const description::Vec3 axis = std::string(frame) == "camera_optical_frame" ? description::Vec3{0, 0, 1} : description::Vec3{1, 0, 0};
    for (const description::Vec3 target : {description::Vec3{2.0, 1.0, 0.0}, description::Vec3{1.0, -2.0, 1.2},
                                           description::Vec3{-1.5, 0.5, 0.3}}) {
      const std::vector<double> q = h.solve(axis, target);
      EXPECT_LT(h.pointing_error(q, axis, target), 1e-6)
          << frame << " at (" << target.x << ", " << target.y << ", " << target.z << "): q " << q[0] << ", " << q[1];
    }
  }
}

TEST(HeadPointing, StaysWithinTheJointLimitsWhereTheTargetIsOutOfReach) {
  const description::RobotModel robot = head();
  const HeadPointing h(robot, "head_pan_link", "head_tilt_link");
  // Straight up: the tilt would have to reach -pi/2, its limit is -0.3712.
  const std::vector<double> q = h.solve({1, 0, 0}, {0.06, 0.0, 5.0});
  EXPECT_GE(q[1], -0.3712 - 1e-12);
  EXPECT_NEAR(q[1], -0.3712, 1e-6);
  EXPECT_NEAR(h.pointing_error(q, {1, 0, 0}, {0.06, 0.0, 5.0}), M_PI / 2 - 0.3712, 0.02);
}

}  // namespace
}  // namespace mechsim::ros
