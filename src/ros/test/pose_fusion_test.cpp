// mechsim's robot_pose_ekf fusion (pose_fusion.hpp): it starts at the odometry, follows the
// odometry's translation turned by the fused heading, weighs the heading increments by their
// variances, and takes roll and pitch from the IMU relative to its first sample.
#include <gtest/gtest.h>

#include <cmath>

#include "ros/pose_fusion.hpp"

namespace mechsim::ros {
namespace {

TEST(PoseFusion, StartsAtTheOdometryAndFollowsItAlone) {
  PoseFusion f;
  EXPECT_FALSE(f.update());  // nothing before odometry
  f.add_odometry({1.0, 2.0, 0.5, 0.01, 0.02});
  ASSERT_TRUE(f.update());
  EXPECT_DOUBLE_EQ(f.estimate().x, 1.0);
  EXPECT_DOUBLE_EQ(f.estimate().y, 2.0);
  EXPECT_DOUBLE_EQ(f.estimate().yaw, 0.5);
  // 1 m forward along the heading 0.5, then a quarter turn in place.
  f.add_odometry({1.0 + std::cos(0.5), 2.0 + std::sin(0.5), 0.5, 0.01, 0.02});
  f.update();
  f.add_odometry({1.0 + std::cos(0.5), 2.0 + std::sin(0.5), 0.5 + M_PI / 2, 0.01, 0.02});
  f.update();
  EXPECT_NEAR(f.estimate().x, 1.0 + std::cos(0.5), 1e-12);
  EXPECT_NEAR(f.estimate().y, 2.0 + std::sin(0.5), 1e-12);
  EXPECT_NEAR(f.estimate().yaw, 0.5 + M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(f.estimate().covariance[0], 0.01);
  EXPECT_DOUBLE_EQ(f.estimate().covariance[35], 0.02);
}

// The odometry says the robot turned 0.2 rad, the IMU 0.1 rad: with equal variances the heading
// turns 0.15, and the translation that follows goes along the fused heading.
TEST(PoseFusion, WeighsHeadingIncrementsByTheirVariances) {
  PoseFusion f;
  f.add_odometry({0.0, 0.0, 0.0, 0.0, 0.04});
  f.add_imu({0.0, 0.0, 1.0, 0.04});
  f.update();
  f.add_odometry({0.0, 0.0, 0.2, 0.0, 0.04});
  f.add_imu({0.0, 0.0, 1.1, 0.04});
  f.update();
  EXPECT_NEAR(f.estimate().yaw, 0.15, 1e-12);
  EXPECT_NEAR(f.estimate().covariance[35], 0.02, 1e-12);  // 1 / (1/0.04 + 1/0.04)
  // 1 m forward in the odometry's frame (heading 0.2): along 0.15 in the fused one.
  f.add_odometry({std::cos(0.2), std::sin(0.2), 0.2, 0.0, 0.04});
  f.add_imu({0.0, 0.0, 1.1, 0.04});
  f.update();
  EXPECT_NEAR(f.estimate().x, std::cos(0.15), 1e-12);
  EXPECT_NEAR(f.estimate().y, std::sin(0.15), 1e-12);
  // An IMU without covariance is trusted as robot_pose_ekf trusts one: the heading follows it.
  PoseFusion g;
  g.add_odometry({0.0, 0.0, 0.0, 0.0, 0.0});
  g.add_imu({0.0, 0.0, 0.0, 0.0});
  g.update();
  g.add_odometry({0.0, 0.0, 0.3, 0.0, 0.0});
  g.add_imu({0.0, 0.0, 0.1, 0.0});
  g.update();
  EXPECT_NEAR(g.estimate().yaw, 0.1, 1e-4);
}

TEST(PoseFusion, RollAndPitchAreTheImusRelativeToItsMountingAndHeadingsWrap) {
  PoseFusion f;
  f.add_odometry({0.0, 0.0, M_PI - 0.05, 0.0, 0.01});
  f.add_imu({0.02, -0.01, 3.0, 0.01});
  f.update();
  f.add_imu({0.05, 0.03, 3.0 + 0.1, 0.01});
  f.add_odometry({0.0, 0.0, -M_PI + 0.05, 0.0, 0.01});  // +0.1 across the wrap
  f.update();
  EXPECT_NEAR(f.estimate().roll, 0.03, 1e-12);
  EXPECT_NEAR(f.estimate().pitch, 0.04, 1e-12);
  EXPECT_NEAR(f.estimate().yaw, -M_PI + 0.05, 1e-12);
  f.drop_imu();
  f.add_odometry({0.0, 0.0, -M_PI + 0.25, 0.0, 0.01});
  f.update();
  EXPECT_NEAR(f.estimate().yaw, -M_PI + 0.25, 1e-12);
  EXPECT_NEAR(angle_difference(-M_PI + 0.1, M_PI - 0.1), 0.2, 1e-12);
}

}  // namespace
}  // namespace mechsim::ros
