// The PR2 base's kinematics against hand-computed values: caster headings for translation and
// rotation, the shorter-way flip, wheel speeds (including the caster-rate term), and the
// least-squares odometry, exact for consistent wheels and robust to one slipping wheel.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "controllers/drive/pr2_base_kinematics.hpp"
#include "controllers/drive/test/pr2_base_test_util.hpp"

namespace mechsim::control {
namespace {

using testing::kPr2CasterXY;
using testing::kPr2WheelOffset;
using testing::kPr2WheelRadius;
constexpr double kPi = std::numbers::pi;

TEST(Pr2BaseKinematics, PureTranslationAlignsEveryCasterWithTheVelocity) {
  const Pr2BaseKinematics k = testing::make_pr2_base();
  const std::array<double, 4> zero{};
  std::array<double, 4> h{};
  caster_headings(k, {0.3, 0.0, 0.0}, zero, zero, h);
  for (double v : h) EXPECT_NEAR(v, 0.0, 1e-12);
  caster_headings(k, {0.2, 0.2, 0.0}, zero, zero, h);
  for (double v : h) EXPECT_NEAR(v, kPi / 4.0, 1e-12);
  caster_headings(k, {0.0, -0.1, 0.0}, zero, zero, h);
  for (double v : h) EXPECT_NEAR(v, -kPi / 2.0, 1e-12);
  // Every wheel rolls at the body speed: 0.3 m/s.
  for (std::size_t w = 0; w < 8; ++w) EXPECT_NEAR(wheel_rolling_speed(k, w, {0.3, 0.0, 0.0}, 0.0, 0.0), 0.3, 1e-12);
  for (std::size_t w = 0; w < 8; ++w) {
    EXPECT_NEAR(wheel_rolling_speed(k, w, {0.2, 0.2, 0.0}, kPi / 4.0, 0.0), 0.2 * std::sqrt(2.0), 1e-12);
  }
}

TEST(Pr2BaseKinematics, PureRotationPutsCastersTangentToCirclesAboutTheCentre) {
  const Pr2BaseKinematics k = testing::make_pr2_base();
  // Headings of the tangents for wz > 0, counter-clockwise: fl 3pi/4, fr pi/4, bl -3pi/4, br -pi/4.
  const std::array<double, 4> tangent{3 * kPi / 4, kPi / 4, -3 * kPi / 4, -kPi / 4};
  std::array<double, 4> h{};
  caster_headings(k, {0.0, 0.0, 1.0}, tangent, tangent, h);
  for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(h[c], tangent[c], 1e-12) << c;
  // Wheel speeds: wz * (|pivot| -+ offset); the left wheel is the inner one at these headings.
  const double r = kPr2CasterXY * std::sqrt(2.0);  // 0.31763 m
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_NEAR(wheel_rolling_speed(k, 2 * c, {0.0, 0.0, 1.0}, tangent[c], 0.0), r - kPr2WheelOffset, 1e-12);
    EXPECT_NEAR(wheel_rolling_speed(k, 2 * c + 1, {0.0, 0.0, 1.0}, tangent[c], 0.0), r + kPr2WheelOffset, 1e-12);
  }
}

TEST(Pr2BaseKinematics, CasterFlipsByPiWhenThatIsTheShorterTurn) {
  bool reversed = false;
  // Pointing backwards, asked to go forwards: keep the heading, roll backwards.
  EXPECT_NEAR(std::abs(caster_steer_target(0.3, 0.0, kPi, reversed)), kPi, 1e-12);
  EXPECT_TRUE(reversed);
  // 100 deg away: flip (80 deg turn) rather than turn 100 deg.
  const double from = 100.0 * kPi / 180.0;
  EXPECT_NEAR(std::abs(caster_steer_target(0.3, 0.0, from, reversed)), kPi, 1e-12);
  EXPECT_TRUE(reversed);
  // 80 deg away: turn.
  EXPECT_NEAR(caster_steer_target(0.3, 0.0, 80.0 * kPi / 180.0, reversed), 0.0, 1e-12);
  EXPECT_FALSE(reversed);
  // A reversed caster's wheels roll backwards: -0.3 m/s at heading pi.
  const Pr2BaseKinematics k = testing::make_pr2_base();
  EXPECT_NEAR(wheel_rolling_speed(k, 0, {0.3, 0.0, 0.0}, kPi, 0.0), -0.3, 1e-12);
  // A slow pivot keeps its held heading.
  const std::array<double, 4> held{0.1, 0.2, 0.3, 0.4};
  std::array<double, 4> h{};
  caster_headings(k, {1e-7, 0.0, 0.0}, held, held, h);
  for (std::size_t c = 0; c < 4; ++c) EXPECT_DOUBLE_EQ(h[c], held[c]);
}

TEST(Pr2BaseKinematics, TurningACasterInPlaceRollsItsWheelsApart) {
  const Pr2BaseKinematics k = testing::make_pr2_base();
  // Base still, caster turning at 2 rad/s: the left wheel (offset +0.049) rolls back at 0.098 m/s.
  EXPECT_NEAR(wheel_rolling_speed(k, 0, {}, 0.7, 2.0), -2.0 * kPr2WheelOffset, 1e-12);
  EXPECT_NEAR(wheel_rolling_speed(k, 1, {}, 0.7, 2.0), 2.0 * kPr2WheelOffset, 1e-12);
}

// Wheel speeds consistent with a twist, casters at their target headings.
std::array<double, 8> consistent_speeds(const Pr2BaseKinematics& k, const PlanarTwist& t, std::array<double, 4>& h) {
  const std::array<double, 4> zero{};
  caster_headings(k, t, zero, zero, h);
  std::array<double, 8> s{};
  for (std::size_t w = 0; w < 8; ++w) s[w] = wheel_rolling_speed(k, w, t, h[k.wheels[w].caster], 0.0);
  return s;
}

TEST(Pr2BaseOdometry, ConsistentWheelsGiveTheTwistExactly) {
  const Pr2BaseKinematics k = testing::make_pr2_base();
  Pr2OdometryScratch scratch;
  scratch.resize(8);
  const std::array<double, 4> rates{};
  for (const PlanarTwist& t : {PlanarTwist{0.3, 0.0, 0.0}, PlanarTwist{0.0, 0.0, 0.8}, PlanarTwist{0.2, -0.1, 0.5}}) {
    std::array<double, 4> h{};
    const auto speeds = consistent_speeds(k, t, h);
    PlanarTwist est;
    double rms = 1.0;
    ASSERT_TRUE(estimate_base_twist(k, h, rates, speeds, scratch, est, 3, IlsWeight::Gaussian, &rms));
    EXPECT_NEAR(est.vx, t.vx, 1e-9);
    EXPECT_NEAR(est.vy, t.vy, 1e-9);
    EXPECT_NEAR(est.wz, t.wz, 1e-9);
    EXPECT_LT(rms, 1e-9);
  }
  // A caster turning in place with its wheels rolling apart: the base is still.
  std::array<double, 4> h{0.3, 0.3, 0.3, 0.3};
  const std::array<double, 4> turning{1.5, 0.0, 0.0, 0.0};
  std::array<double, 8> speeds{};
  for (std::size_t w = 0; w < 8; ++w) speeds[w] = wheel_rolling_speed(k, w, {}, h[k.wheels[w].caster], turning[k.wheels[w].caster]);
  PlanarTwist est{9, 9, 9};
  ASSERT_TRUE(estimate_base_twist(k, h, turning, speeds, scratch, est));
  EXPECT_NEAR(est.vx, 0.0, 1e-12);
  EXPECT_NEAR(est.wz, 0.0, 1e-12);
}

TEST(Pr2BaseOdometry, StraightLineAndRotationIntegrateToTheRightPose) {
  const Pr2BaseKinematics k = testing::make_pr2_base();
  Pr2OdometryScratch scratch;
  scratch.resize(8);
  const std::array<double, 4> rates{};
  const auto drive = [&](const PlanarTwist& t, double seconds, PlanarPose pose) {
    std::array<double, 4> h{};
    const auto speeds = consistent_speeds(k, t, h);
    for (int i = 0; i < static_cast<int>(seconds * 1000.0 + 0.5); ++i) {
      PlanarTwist est;
      EXPECT_TRUE(estimate_base_twist(k, h, rates, speeds, scratch, est));
      pose = integrate_pose(pose, est, 0.001);
    }
    return pose;
  };
  PlanarPose p = drive({0.5, 0.0, 0.0}, 2.0, {});  // 1 m ahead
  EXPECT_NEAR(p.x, 1.0, 1e-9);
  EXPECT_NEAR(p.y, 0.0, 1e-9);
  p = drive({0.0, 0.0, kPi / 4.0}, 2.0, p);  // a quarter turn in place
  EXPECT_NEAR(p.x, 1.0, 1e-9);
  EXPECT_NEAR(p.yaw, kPi / 2.0, 1e-9);
  p = drive({0.5, 0.0, 0.0}, 1.0, p);  // 0.5 m along +y of the odometry frame
  EXPECT_NEAR(p.x, 1.0, 1e-9);
  EXPECT_NEAR(p.y, 0.5, 1e-9);
}

TEST(Pr2BaseOdometry, OneSlippingWheelDegradesTheEstimateGracefully) {
  const Pr2BaseKinematics k = testing::make_pr2_base();
  Pr2OdometryScratch scratch;
  scratch.resize(8);
  const std::array<double, 4> rates{};
  const PlanarTwist t{0.4, 0.0, 0.3};
  std::array<double, 4> h{};
  auto speeds = consistent_speeds(k, t, h);
  speeds[3] += 0.2;  // fr right wheel spins 0.2 m/s too fast
  const auto error = [&](int iterations, IlsWeight weight, double* rms) {
    PlanarTwist est;
    EXPECT_TRUE(estimate_base_twist(k, h, rates, speeds, scratch, est, iterations, weight, rms));
    return std::hypot(est.vx - t.vx, est.vy - t.vy, (est.wz - t.wz) * 0.3);
  };
  double rms = 0.0;
  const double plain = error(0, IlsWeight::Uniform, &rms);
  EXPECT_GT(rms, 0.01);  // the slip shows in the residual
  const double gaussian = error(3, IlsWeight::Gaussian, nullptr);
  const double cauchy = error(3, IlsWeight::Cauchy, nullptr);
  // Plain least squares spreads 1/8 of the slip: ~0.025 m/s; re-weighting discounts the wheel.
  EXPECT_GT(plain, 0.01);
  EXPECT_LT(plain, 0.2 / 4.0);
  EXPECT_LT(gaussian, plain / 4.0);
  EXPECT_LT(cauchy, plain);
}

TEST(Pr2BaseOdometry, TooFewRowsDoNotDetermineATwist) {
  Pr2BaseKinematics k;
  k.wheel_radius = 0.1;
  k.casters.push_back({0.0, 0.0, 1.0});
  k.wheels.push_back({0, 0.0, 1.0});  // one wheel at the pivot: 2 rows, wz undetermined
  Pr2OdometryScratch scratch;
  scratch.resize(1);
  const std::array<double, 1> h{0.0}, rates{0.0}, speeds{0.2};
  PlanarTwist est{7.0, 7.0, 7.0};
  EXPECT_FALSE(estimate_base_twist(k, h, rates, speeds, scratch, est));
  EXPECT_EQ(est.vx, 7.0);
}

}  // namespace
}  // namespace mechsim::control
