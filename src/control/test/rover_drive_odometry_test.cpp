// Rover odometry: the least-squares twist estimate against the inverse kinematics, and the
// exact pose integration against straight lines and circles.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "control/rover_drive_kinematics.hpp"
#include "control/test/rover_drive_test_util.hpp"

namespace mechsim::control {
namespace {

constexpr double kPi = std::numbers::pi;

struct Wheels {
  std::array<double, 4> headings{};
  std::array<double, 6> speeds{};
};

Wheels drive(const RoverKinematics& k, const PlanarTwist& t) {
  Wheels w;
  const std::array<double, 4> zero{};
  inverse_kinematics(k, t, zero, zero, w.headings, w.speeds);
  return w;
}

TEST(RoverOdometry, EstimateInvertsTheInverseKinematics) {
  const RoverKinematics k = testing::make_test_rover(0.06);  // with steering offsets
  for (const PlanarTwist t : {PlanarTwist{0.5, 0.0, 0.0}, PlanarTwist{0.5, 0.0, 0.25}, PlanarTwist{-0.3, 0.0, 0.6},
                              PlanarTwist{0.0, 0.0, -0.7}, PlanarTwist{0.08, 0.0, 0.4}}) {
    const Wheels w = drive(k, t);
    PlanarTwist estimate{9, 9, 9};
    double residual = -1.0;
    ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, estimate, &residual));
    EXPECT_NEAR(estimate.vx, t.vx, 1e-12) << t.vx << " " << t.wz;
    EXPECT_NEAR(estimate.vy, t.vy, 1e-12);
    EXPECT_NEAR(estimate.wz, t.wz, 1e-12);
    EXPECT_NEAR(residual, 0.0, 1e-12);
  }
}

TEST(RoverOdometry, CrabIgnoresTheSidewaysDraggedFixedWheels) {
  const RoverKinematics k = testing::make_test_rover();
  const PlanarTwist t{0.3, 0.2, 0.0};
  const Wheels w = drive(k, t);
  PlanarTwist estimate;
  double residual = 0.0;
  ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, estimate, &residual, 0.0));
  EXPECT_NEAR(estimate.vx, 0.3, 1e-12);
  EXPECT_NEAR(estimate.vy, 0.2, 1e-12);
  EXPECT_NEAR(estimate.wz, 0.0, 1e-12);
  EXPECT_NEAR(residual, 0.0, 1e-12);
  // Counting the fixed wheels' no-side-slip rows pulls vy towards zero and shows as residual.
  ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, estimate, &residual, 1.0));
  EXPECT_LT(estimate.vy, 0.19);
  EXPECT_GT(residual, 0.01);
}

TEST(RoverOdometry, SlipShowsAsResidual) {
  const RoverKinematics k = testing::make_test_rover();
  Wheels w = drive(k, {0.5, 0.0, 0.0});
  w.speeds[0] = 0.7;  // FL spins faster than the others
  PlanarTwist estimate;
  double residual = 0.0;
  ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, estimate, &residual));
  EXPECT_NEAR(estimate.vx, 0.5 + 0.2 / 6.0, 1e-3);  // the mean of the rolling speeds, nearly
  EXPECT_GT(residual, 0.05);
}

TEST(RoverOdometry, UndeterminedWheelsReturnFalse) {
  RoverKinematics k;
  k.wheel_radius = 0.1;
  k.wheels = {RoverWheel{0.0, 0.3}, RoverWheel{0.0, 0.3}};  // two wheels in one place
  finish_rover_kinematics(k);
  PlanarTwist estimate{1, 2, 3};
  const std::array<double, 2> speeds{0.5, 0.5};
  EXPECT_FALSE(estimate_twist(k, {}, speeds, estimate));
  EXPECT_EQ(estimate.vx, 1.0);
}

TEST(RoverOdometry, IntegratesAStraightLine) {
  PlanarPose pose{1.0, 2.0, 0.5};
  for (int i = 0; i < 1000; ++i) pose = integrate_pose(pose, {0.2, 0.1, 0.0}, 0.01);
  // 10 s at (0.2, 0.1) m/s in the body, heading 0.5 rad.
  EXPECT_NEAR(pose.x, 1.0 + 10 * (0.2 * std::cos(0.5) - 0.1 * std::sin(0.5)), 1e-9);
  EXPECT_NEAR(pose.y, 2.0 + 10 * (0.2 * std::sin(0.5) + 0.1 * std::cos(0.5)), 1e-9);
  EXPECT_DOUBLE_EQ(pose.yaw, 0.5);
}

TEST(RoverOdometry, IntegratesACircleExactlyWhateverTheStep) {
  // vx = 0.5 m/s, wz = 0.25 rad/s: a circle of radius 2 m centred at (0, 2).
  for (int steps : {6283, 10, 1}) {
    PlanarPose pose;
    const double dt = kPi / 2 / 0.25 / steps;
    for (int i = 0; i < steps; ++i) pose = integrate_pose(pose, {0.5, 0.0, 0.25}, dt);
    EXPECT_NEAR(pose.x, 2.0, 1e-9) << dt;  // a quarter turn
    EXPECT_NEAR(pose.y, 2.0, 1e-9) << dt;
    EXPECT_NEAR(pose.yaw, kPi / 2, 1e-9) << dt;
  }
  PlanarPose pose;
  for (int i = 0; i < 2000; ++i) pose = integrate_pose(pose, {0.5, 0.0, 0.25}, 2 * kPi / 0.25 / 2000);
  EXPECT_NEAR(pose.x, 0.0, 1e-9);  // a whole turn comes back
  EXPECT_NEAR(pose.y, 0.0, 1e-9);
  EXPECT_NEAR(pose.yaw, 0.0, 1e-9);
}

TEST(RoverOdometry, IntegratesASidewaysArc) {
  // A body twist with vy and wz (the body origin off the turn centre): radius |v| / wz about
  // the point (-vy, vx) / wz in the body.
  PlanarPose pose;
  const PlanarTwist t{0.0, 0.3, 0.5};
  for (int i = 0; i < 100; ++i) pose = integrate_pose(pose, t, kPi / 0.5 / 100);  // half a turn
  EXPECT_NEAR(pose.x, -2 * 0.3 / 0.5, 1e-9);
  EXPECT_NEAR(pose.y, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(pose.yaw), kPi, 1e-9);
}

}  // namespace
}  // namespace mechsim::control
