// Rover odometry: the least-squares twist estimate against the inverse kinematics, its weighted
// and robust forms (a slipping wheel rejected, sensing wheels trusted over driven ones), and the
// exact pose integration against straight lines and circles.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "controllers/drive/rover_drive_kinematics.hpp"
#include "controllers/drive/rover_drive_odometry.hpp"
#include "controllers/drive/test/rover_drive_test_util.hpp"

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

TEST(RoverOdometry, WeightedWithUnitWeightsIsThePlainEstimate) {
  const RoverKinematics k = testing::make_test_rover(0.06);
  Wheels w = drive(k, {0.4, 0.0, 0.3});
  w.speeds[3] += 0.05;  // some disagreement, so that the weights matter
  PlanarTwist plain, weighted;
  double plain_rms = 0.0, weighted_rms = 0.0;
  ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, plain, &plain_rms));
  ASSERT_TRUE(estimate_twist_weighted(k, w.headings, w.speeds, {}, {}, weighted, &weighted_rms));
  EXPECT_NEAR(weighted.vx, plain.vx, 1e-12);
  EXPECT_NEAR(weighted.vy, plain.vy, 1e-12);
  EXPECT_NEAR(weighted.wz, plain.wz, 1e-12);
  EXPECT_NEAR(weighted_rms, plain_rms, 1e-12);
  // Zero weights on the fixed wheels' lateral rows: the crab form of estimate_twist.
  const std::array<double, 6> ones{1, 1, 1, 1, 1, 1};
  const std::array<double, 6> lateral{1, 1, 0, 0, 1, 1};
  ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, plain, nullptr, 0.0));
  ASSERT_TRUE(estimate_twist_weighted(k, w.headings, w.speeds, ones, lateral, weighted));
  EXPECT_NEAR(weighted.vx, plain.vx, 1e-12);
  EXPECT_NEAR(weighted.wz, plain.wz, 1e-12);
}

TEST(RoverOdometry, RobustEstimateRejectsASlippingWheel) {
  const RoverKinematics k = testing::make_test_rover();
  Wheels w = drive(k, {0.5, 0.0, 0.0});
  w.speeds[0] = 0.9;  // FL spins (in the air, or in sand) at nearly twice the ground speed
  PlanarTwist plain, robust;
  ASSERT_TRUE(estimate_twist(k, w.headings, w.speeds, plain));
  EXPECT_GT(plain.vx, 0.55);  // least squares shares the error among all
  EXPECT_GT(std::abs(plain.wz), 0.05);
  std::array<double, 6> work_h{}, work_n{}, trust{};
  double rms = -1.0;
  ASSERT_TRUE(estimate_twist_robust(k, w.headings, w.speeds, {}, {}, RobustOdometryOptions{}, work_h, work_n, robust, &rms,
                                    trust));
  EXPECT_NEAR(robust.vx, 0.5, 0.005);
  EXPECT_NEAR(robust.vy, 0.0, 0.005);
  EXPECT_NEAR(robust.wz, 0.0, 0.01);
  EXPECT_LT(trust[0], 0.05) << "the spinning wheel keeps its weight";
  for (std::size_t i = 1; i < 6; ++i) EXPECT_GT(trust[i], 0.9) << i;
  EXPECT_GE(rms, 0.0);
  // No reweighting: the plain estimate again.
  RobustOdometryOptions off;
  off.iterations = 0;
  ASSERT_TRUE(estimate_twist_robust(k, w.headings, w.speeds, {}, {}, off, work_h, work_n, robust));
  EXPECT_NEAR(robust.vx, plain.vx, 1e-12);
}

TEST(RoverOdometry, RobustEstimateRejectsAStuckWheelInATurn) {
  const RoverKinematics k = testing::make_test_rover(0.06);
  const PlanarTwist t{0.4, 0.0, 0.3};
  Wheels w = drive(k, t);
  w.speeds[4] = 0.0;  // RL stuck
  std::array<double, 6> work_h{}, work_n{}, trust{};
  PlanarTwist robust;
  ASSERT_TRUE(estimate_twist_robust(k, w.headings, w.speeds, {}, {}, RobustOdometryOptions{}, work_h, work_n, robust,
                                    nullptr, trust));
  EXPECT_NEAR(robust.vx, t.vx, 0.01);
  EXPECT_NEAR(robust.wz, t.wz, 0.02);
  EXPECT_LT(trust[4], 0.05);
}

TEST(RoverOdometry, RobustEstimateIsExactOnConsistentWheels) {
  const RoverKinematics k = testing::make_test_rover(0.06);
  for (const PlanarTwist t : {PlanarTwist{0.5, 0.0, 0.0}, PlanarTwist{0.3, 0.0, 0.5}, PlanarTwist{0.0, 0.0, -0.7}}) {
    const Wheels w = drive(k, t);
    std::array<double, 6> work_h{}, work_n{}, trust{};
    PlanarTwist robust;
    ASSERT_TRUE(estimate_twist_robust(k, w.headings, w.speeds, {}, {}, RobustOdometryOptions{}, work_h, work_n, robust,
                                      nullptr, trust));
    EXPECT_NEAR(robust.vx, t.vx, 1e-12);
    EXPECT_NEAR(robust.wz, t.wz, 1e-12);
    for (double v : trust) EXPECT_NEAR(v, 1.0, 1e-12);
  }
}

TEST(RoverOdometry, CrabTrustsTheSensingWheelsOverTheDrivenOnes) {
  // Crab at 45 deg commanded at 0.5 m/s; the ground moves the body at 0.4 m/s along the same
  // direction and turns it at 0.05 rad/s. The driven wheels (FL, ML, MR, RL) report their set
  // points; the unpowered FR and RR roll with the ground.
  const RoverKinematics k = testing::make_test_rover(0.06);
  const PlanarTwist command{0.35355, 0.35355, 0.0};
  const PlanarTwist truth{0.28284, 0.28284, 0.05};
  Wheels w = drive(k, command);
  for (std::size_t i : {std::size_t{1}, std::size_t{5}}) {
    w.speeds[i] = rolling_speed(k, i, w.headings[static_cast<std::size_t>(k.wheels[i].steering)], truth);
  }
  const std::array<double, 6> lateral_plain{1, 1, 0, 0, 1, 1};
  PlanarTwist plain;
  ASSERT_TRUE(estimate_twist_weighted(k, w.headings, w.speeds, {}, lateral_plain, plain));
  EXPECT_GT(std::hypot(plain.vx, plain.vy), 0.45);  // mostly the command
  const std::array<double, 6> rolling{0.01, 1, 0.01, 0.01, 0.01, 1};
  const std::array<double, 6> lateral{0.1, 0.1, 0, 0, 0.1, 0.1};
  std::array<double, 6> work_h{}, work_n{};
  PlanarTwist sensed;
  ASSERT_TRUE(estimate_twist_robust(k, w.headings, w.speeds, rolling, lateral, RobustOdometryOptions{}, work_h, work_n,
                                    sensed));
  EXPECT_NEAR(std::hypot(sensed.vx, sensed.vy), 0.4, 0.01);
  EXPECT_NEAR(std::atan2(sensed.vy, sensed.vx), kPi / 4, 0.02);
  EXPECT_NEAR(sensed.wz, 0.05, 0.01);
  EXPECT_GT(std::abs(plain.wz - truth.wz), 0.04);  // the plain estimate does not see the yaw
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
  std::array<double, 2> work_h{}, work_n{};
  EXPECT_FALSE(estimate_twist_robust(k, {}, speeds, {}, {}, RobustOdometryOptions{}, work_h, work_n, estimate));
  const std::array<double, 2> zero{0.0, 0.0};
  EXPECT_FALSE(estimate_twist_weighted(k, {}, speeds, zero, zero, estimate));
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
