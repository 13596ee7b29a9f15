// Rover drive kinematics against hand-computed values on the test rover of
// rover_drive_test_util.hpp: steered corners at (+-0.5, +-0.4) m, fixed wheels at (0, +-0.45) m.
// Steering order FL, FR, RL, RR; wheel order FL, FR, ML, MR, RL, RR.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "controllers/drive/rover_drive_kinematics.hpp"
#include "controllers/drive/test/rover_drive_test_util.hpp"

namespace mechsim::control {
namespace {

using std::atan;
using std::hypot;
constexpr double kPi = std::numbers::pi;

struct Result {
  std::array<double, 4> headings{};
  std::array<double, 6> speeds{};
};

Result solve(const RoverKinematics& k, const PlanarTwist& t, const std::array<double, 4>& reference = {}) {
  Result r;
  const std::array<double, 4> hold{0.11, 0.22, 0.33, 0.44};
  inverse_kinematics(k, t, hold, reference, r.headings, r.speeds);
  return r;
}

TEST(RoverKinematics, FinishFindsTheAxleLineAndTheSteeredWheels) {
  const RoverKinematics k = testing::make_test_rover();
  EXPECT_DOUBLE_EQ(k.axle_x, 0.0);
  ASSERT_EQ(k.steering_wheel.size(), 4u);
  EXPECT_EQ(k.steering_wheel[0], 0);  // steering_FL carries wheel FL
  EXPECT_EQ(k.steering_wheel[2], 4);  // steering_RL carries wheel RL
  EXPECT_NEAR(k.characteristic_length, (4 * hypot(0.5, 0.4) + 2 * 0.45) / 6.0, 1e-12);
}

TEST(RoverKinematics, AckermannTurnCentreOnTheMiddleAxleLine) {
  const RoverKinematics k = testing::make_test_rover();
  const double vx = 0.5, wz = 0.25;  // R = vx / wz = 2 m to the left
  const double R = 2.0;
  const Result r = solve(k, {vx, 0.0, wz});
  // heading_i = atan(x_i / (R - y_i)); speed_i = wz * distance from the turn centre (0, R).
  EXPECT_NEAR(r.headings[0], atan(0.5 / (R - 0.4)), 1e-12);   // FL
  EXPECT_NEAR(r.headings[1], atan(0.5 / (R + 0.4)), 1e-12);   // FR
  EXPECT_NEAR(r.headings[2], atan(-0.5 / (R - 0.4)), 1e-12);  // RL
  EXPECT_NEAR(r.headings[3], atan(-0.5 / (R + 0.4)), 1e-12);  // RR
  EXPECT_NEAR(r.speeds[0], wz * hypot(0.5, R - 0.4), 1e-12);  // FL
  EXPECT_NEAR(r.speeds[1], wz * hypot(0.5, R + 0.4), 1e-12);  // FR
  EXPECT_NEAR(r.speeds[4], wz * hypot(0.5, R - 0.4), 1e-12);  // RL
  EXPECT_NEAR(r.speeds[5], wz * hypot(0.5, R + 0.4), 1e-12);  // RR
}

TEST(RoverKinematics, AckermannMiddleWheelsRollAtTheirRadius) {
  const RoverKinematics k = testing::make_test_rover();
  const Result r = solve(k, {0.5, 0.0, 0.25});
  std::array<double, 6> expected{};
  expected[2] = 0.25 * (2.0 - 0.45);  // ML, inner
  expected[3] = 0.25 * (2.0 + 0.45);  // MR, outer
  EXPECT_NEAR(r.speeds[2], expected[2], 1e-12);
  EXPECT_NEAR(r.speeds[3], expected[3], 1e-12);
}

TEST(RoverKinematics, AckermannRightTurnMirrors) {
  const RoverKinematics k = testing::make_test_rover();
  const Result left = solve(k, {0.5, 0.0, 0.25});
  const Result right = solve(k, {0.5, 0.0, -0.25});
  EXPECT_NEAR(right.headings[0], -left.headings[1], 1e-12);  // FL right = -FR left
  EXPECT_NEAR(right.headings[3], -left.headings[2], 1e-12);  // RR right = -RL left
  EXPECT_NEAR(right.speeds[0], left.speeds[1], 1e-12);
  EXPECT_NEAR(right.speeds[5], left.speeds[4], 1e-12);  // RR right = RL left
}

TEST(RoverKinematics, TightAckermannInsideTheWheelbaseReversesTheInnerWheels) {
  // R = 0.2 m: the turn centre lies between the left wheels (y = 0.4) and the body's axis. The
  // inner corners would have to point past 90 deg; they point at atan(x / (R - y)) and roll
  // backwards instead.
  const RoverKinematics k = testing::make_test_rover();
  const double wz = 0.5, R = 0.2;
  const Result r = solve(k, {wz * R, 0.0, wz});
  EXPECT_NEAR(r.headings[0], atan(0.5 / (R - 0.4)), 1e-12);  // -68.2 deg
  EXPECT_LT(r.headings[0], 0.0);
  EXPECT_NEAR(r.speeds[0], -wz * hypot(0.5, R - 0.4), 1e-12);
  EXPECT_NEAR(r.speeds[2], wz * (R - 0.45), 1e-12);  // ML rolls backwards, unsteered
  EXPECT_NEAR(r.headings[1], atan(0.5 / (R + 0.4)), 1e-12);
  EXPECT_NEAR(r.speeds[1], wz * hypot(0.5, R + 0.4), 1e-12);
  for (double h : r.headings) EXPECT_LE(std::abs(h), kPi / 2 + 1e-12);
}

TEST(RoverKinematics, CrabKeepsAllWheelsParallel) {
  const RoverKinematics k = testing::make_test_rover();
  const double vx = 0.3, vy = 0.2;
  const Result r = solve(k, {vx, vy, 0.0});
  for (double h : r.headings) EXPECT_NEAR(h, std::atan2(vy, vx), 1e-12);
  for (int i : {0, 1, 4, 5}) EXPECT_NEAR(r.speeds[i], hypot(vx, vy), 1e-12);
  // The fixed wheels cannot steer: they roll with the forward component (and slip sideways).
  EXPECT_NEAR(r.speeds[2], vx, 1e-12);
  EXPECT_NEAR(r.speeds[3], vx, 1e-12);
}

TEST(RoverKinematics, CrabBackwardsAndLeftPointsTheWheelsForwardRight) {
  // atan2(0.2, -0.3) = 146 deg is beyond the +-90 deg range: the wheels point at -34 deg and
  // roll backwards.
  const RoverKinematics k = testing::make_test_rover();
  const Result r = solve(k, {-0.3, 0.2, 0.0});
  for (double h : r.headings) EXPECT_NEAR(h, std::atan2(0.2, -0.3) - kPi, 1e-12);
  for (int i : {0, 1, 4, 5}) EXPECT_NEAR(r.speeds[i], -hypot(0.3, 0.2), 1e-12);
}

TEST(RoverKinematics, PointTurnWheelsAreTangentToCirclesAroundTheCentre) {
  const RoverKinematics k = testing::make_test_rover();
  const double wz = 0.5;
  const Result r = solve(k, {0.0, 0.0, wz});
  const double corner = hypot(0.5, 0.4);
  EXPECT_NEAR(r.headings[0], atan(0.5 / -0.4), 1e-12);  // FL: -51.3 deg
  EXPECT_NEAR(r.headings[1], atan(0.5 / 0.4), 1e-12);   // FR: +51.3 deg
  EXPECT_NEAR(r.headings[2], atan(-0.5 / -0.4), 1e-12); // RL: +51.3 deg
  EXPECT_NEAR(r.headings[3], atan(-0.5 / 0.4), 1e-12);  // RR: -51.3 deg
  const std::array<std::array<double, 2>, 4> pos{{{0.5, 0.4}, {0.5, -0.4}, {-0.5, 0.4}, {-0.5, -0.4}}};
  for (std::size_t s = 0; s < 4; ++s) {  // tangent: heading perpendicular to the radius
    EXPECT_NEAR(std::cos(r.headings[s]) * pos[s][0] + std::sin(r.headings[s]) * pos[s][1], 0.0, 1e-12) << s;
  }
  // Speed proportional to the distance; the left wheels roll backwards, the right forwards.
  EXPECT_NEAR(r.speeds[0], -wz * corner, 1e-12);
  EXPECT_NEAR(r.speeds[1], wz * corner, 1e-12);
  EXPECT_NEAR(r.speeds[4], -wz * corner, 1e-12);
  EXPECT_NEAR(r.speeds[5], wz * corner, 1e-12);
  EXPECT_NEAR(r.speeds[2], -wz * 0.45, 1e-12);
  EXPECT_NEAR(r.speeds[3], wz * 0.45, 1e-12);
}

TEST(RoverKinematics, SteeringOffsetChangesTheRollingSpeedOnly) {
  // Tyres 0.06 m outboard of the steering axes: headings unchanged (the pivot's velocity sets
  // them), rolling speed minus wz * offset.
  const RoverKinematics plain = testing::make_test_rover();
  const RoverKinematics off = testing::make_test_rover(0.06);
  const PlanarTwist t{0.5, 0.0, 0.25};
  const Result a = solve(plain, t);
  const Result b = solve(off, t);
  for (std::size_t s = 0; s < 4; ++s) EXPECT_DOUBLE_EQ(a.headings[s], b.headings[s]);
  EXPECT_NEAR(b.speeds[0], a.speeds[0] - 0.25 * 0.06, 1e-12);   // FL: offset +0.06 (left)
  EXPECT_NEAR(b.speeds[1], a.speeds[1] + 0.25 * 0.06, 1e-12);   // FR: offset -0.06 (right)
  EXPECT_DOUBLE_EQ(b.speeds[2], a.speeds[2]);
  // And equals the tyre's own ground speed: pivot (0.5, 0.4) + 0.06 along the fork's y.
  const double h = b.headings[0];
  const double cx = 0.5 - 0.06 * std::sin(h), cy = 0.4 + 0.06 * std::cos(h);
  const double vx = 0.5 - 0.25 * cy, vy = 0.25 * cx;
  EXPECT_NEAR(b.speeds[0], std::cos(h) * vx + std::sin(h) * vy, 1e-12);
  EXPECT_NEAR(-std::sin(h) * vx + std::cos(h) * vy, 0.0, 1e-12);  // no side slip of the tyre
}

TEST(RoverKinematics, AStoppedRoverHoldsItsSteering) {
  const RoverKinematics k = testing::make_test_rover();
  const Result r = solve(k, {0.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(r.headings[0], 0.11);
  EXPECT_DOUBLE_EQ(r.headings[3], 0.44);
  for (double s : r.speeds) EXPECT_EQ(s, 0.0);
}

TEST(RoverKinematics, FoldHeadingPicksTheShorterWayWithinRange) {
  bool reverse = false;
  // pi/2 range: exactly one candidate fits.
  EXPECT_NEAR(fold_heading(-1.0, 0.1, kPi / 2, 0.0, reverse), std::atan2(0.1, -1.0) - kPi, 1e-12);
  EXPECT_TRUE(reverse);
  EXPECT_NEAR(fold_heading(1.0, 0.1, kPi / 2, 0.0, reverse), std::atan2(0.1, 1.0), 1e-12);
  EXPECT_FALSE(reverse);
  // A wider range (2 rad): 100 deg and -80 deg both fit; the one nearer the current heading wins.
  const double a = 100.0 * kPi / 180.0;
  EXPECT_NEAR(fold_heading(std::cos(a), std::sin(a), 2.0, 1.5, reverse), a, 1e-12);
  EXPECT_FALSE(reverse);
  EXPECT_NEAR(fold_heading(std::cos(a), std::sin(a), 2.0, -1.0, reverse), a - kPi, 1e-12);
  EXPECT_TRUE(reverse);
  // A narrow range (0.5 rad) clamps.
  EXPECT_NEAR(fold_heading(1.0, 1.0, 0.5, 0.0, reverse), 0.5, 1e-12);
}

TEST(RoverKinematics, AutoModeFollowsTheTwist) {
  const RoverKinematics k = testing::make_test_rover();
  auto pick = [&](double vx, double vy, double wz) { return select_drive_mode(k, DriveMode::Auto, {vx, vy, wz}); };
  EXPECT_EQ(pick(0.5, 0.0, 0.0).mode, DriveMode::Ackermann);
  EXPECT_EQ(pick(0.5, 0.0, 0.3).mode, DriveMode::Ackermann);
  EXPECT_EQ(pick(0.5, 0.2, 0.0).mode, DriveMode::Crab);
  EXPECT_EQ(pick(0.0, 0.2, 0.0).mode, DriveMode::Crab);
  EXPECT_EQ(pick(0.0, 0.0, 0.3).mode, DriveMode::PointTurn);
  EXPECT_FALSE(pick(0.5, 0.2, 0.0).unsupported);
  // vy with wz: unsupported, mapped to the mode keeping the larger wheel speed.
  const ModeChoice big_vy = pick(0.3, 0.5, 0.1);  // 0.5 m/s vs 0.1 rad/s * ~0.6 m
  EXPECT_EQ(big_vy.mode, DriveMode::Crab);
  EXPECT_TRUE(big_vy.unsupported);
  EXPECT_EQ(big_vy.twist.wz, 0.0);
  EXPECT_EQ(big_vy.twist.vy, 0.5);
  const ModeChoice big_wz = pick(0.3, 0.05, 1.0);
  EXPECT_EQ(big_wz.mode, DriveMode::Ackermann);
  EXPECT_TRUE(big_wz.unsupported);
  EXPECT_EQ(big_wz.twist.vy, 0.0);
  EXPECT_EQ(big_wz.twist.wz, 1.0);
}

TEST(RoverKinematics, ForcedModesDropWhatTheyCannotDo) {
  const RoverKinematics k = testing::make_test_rover();
  const ModeChoice crab = select_drive_mode(k, DriveMode::Crab, {0.5, 0.0, 0.3});
  EXPECT_EQ(crab.mode, DriveMode::Crab);
  EXPECT_TRUE(crab.unsupported);
  EXPECT_EQ(crab.twist.wz, 0.0);
  const ModeChoice turn = select_drive_mode(k, DriveMode::PointTurn, {0.5, 0.0, 0.3});
  EXPECT_EQ(turn.mode, DriveMode::PointTurn);
  EXPECT_EQ(turn.twist.vx, 0.0);
  EXPECT_EQ(turn.twist.wz, 0.3);
  const ModeChoice ack = select_drive_mode(k, DriveMode::Ackermann, {0.5, 0.0, 0.3});
  EXPECT_FALSE(ack.unsupported);
  EXPECT_EQ(ack.twist.vx, 0.5);
}

TEST(RoverKinematics, ModeNamesRoundTrip) {
  for (DriveMode m : {DriveMode::Auto, DriveMode::Ackermann, DriveMode::Crab, DriveMode::PointTurn}) {
    DriveMode parsed = DriveMode::Auto;
    ASSERT_TRUE(parse_drive_mode(drive_mode_name(m), parsed));
    EXPECT_EQ(parsed, m);
  }
  DriveMode parsed = DriveMode::Crab;
  EXPECT_FALSE(parse_drive_mode("skid", parsed));
  EXPECT_EQ(parsed, DriveMode::Crab);
}

}  // namespace
}  // namespace mechsim::control
