// The kinematics and odometry that diff_drive_controller and Gazebo's diff drive plugin share, and
// diff_drive_controller's speed limiter: wheel rim speeds, the unicycle step on an arc and along
// the mid-way heading, the rolling mean, odometry from wheel positions around a circle, and the
// limiter's jerk, acceleration and velocity bounds.

#include <gtest/gtest.h>

#include <cmath>

#include "control/hardware.hpp"
#include "control/params.hpp"
#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/drive/speed_limiter.hpp"

namespace mechsim::control {
namespace {

TEST(DiffDriveKinematics, RimSpeedsOfATwist) {
  const WheelRimSpeeds s = diff_drive_rim_speeds(0.5, 1.0, 0.3);
  EXPECT_DOUBLE_EQ(s.left, 0.35);
  EXPECT_DOUBLE_EQ(s.right, 0.65);
  const WheelRimSpeeds spin = diff_drive_rim_speeds(0.0, -2.0, 0.4);
  EXPECT_DOUBLE_EQ(spin.left, 0.4);
  EXPECT_DOUBLE_EQ(spin.right, -0.4);
}

TEST(DiffDriveKinematics, UnicycleLandsOnTheArc) {
  // A quarter circle of radius 2 in 1000 steps, both integrators: exact lands on (2, 2), the
  // mid-way heading step within its second-order error.
  for (const bool exact : {true, false}) {
    PlanarPose p;
    const double ds = 2.0 * (M_PI / 2.0) / 1000.0, dtheta = (M_PI / 2.0) / 1000.0;
    for (int i = 0; i < 1000; ++i) p = integrate_unicycle(p, ds, dtheta, exact);
    EXPECT_NEAR(p.x, 2.0, exact ? 1e-9 : 1e-6);
    EXPECT_NEAR(p.y, 2.0, exact ? 1e-9 : 1e-6);
    EXPECT_NEAR(p.yaw, M_PI / 2.0, 1e-12);
  }
  // One big step: the arc is exact, the mid-way heading is not.
  const PlanarPose arc = integrate_unicycle({}, M_PI, M_PI, true);  // half circle of radius 1
  EXPECT_NEAR(arc.x, 0.0, 1e-12);
  EXPECT_NEAR(arc.y, 2.0, 1e-12);
  const PlanarPose mid = integrate_unicycle({}, M_PI, M_PI, false);
  EXPECT_NEAR(mid.x, 0.0, 1e-12);
  EXPECT_NEAR(mid.y, M_PI, 1e-12);
  // Straight: both the same.
  const PlanarPose straight = integrate_unicycle({1.0, 0.0, M_PI / 2.0}, 2.0, 0.0, true);
  EXPECT_NEAR(straight.x, 1.0, 1e-12);
  EXPECT_NEAR(straight.y, 2.0, 1e-12);
}

TEST(DiffDriveKinematics, RollingMeanOverItsWindow) {
  RollingMean m;
  m.init(3);
  EXPECT_DOUBLE_EQ(m.mean(), 0.0);
  m.push(3.0);
  EXPECT_DOUBLE_EQ(m.mean(), 3.0);
  m.push(6.0);
  m.push(9.0);
  EXPECT_DOUBLE_EQ(m.mean(), 6.0);
  m.push(12.0);  // 3.0 leaves
  EXPECT_DOUBLE_EQ(m.mean(), 9.0);
  m.reset();
  EXPECT_DOUBLE_EQ(m.mean(), 0.0);
}

TEST(DiffDriveOdometry, FollowsTheWheelsAroundACircle) {
  // Wheels 0.5 m apart, radii 0.1 m (left 0.11: a radius multiplier). The body follows a circle of
  // radius 1 m at 0.5 m/s: the left wheel runs 0.75 m per 1 m of the centre's path, the right 1.25.
  DiffDriveOdometry odom;
  odom.init(0.5, 0.11, 0.1, 10);
  odom.reset(0.0, 0.0, 0.0);
  const double v = 0.5, w = 0.5, dt = 0.001;
  double left = 0.0, right = 0.0, t = 0.0;
  for (int i = 0; i < 2000; ++i) {
    t += dt;
    left += (v - w * 0.25) * dt / 0.11;
    right += (v + w * 0.25) * dt / 0.1;
    ASSERT_TRUE(odom.update(left, right, t));
  }
  // After 2 s: 1 rad around the circle centred at (0, 1).
  EXPECT_NEAR(odom.pose().x, std::sin(1.0), 1e-9);
  EXPECT_NEAR(odom.pose().y, 1.0 - std::cos(1.0), 1e-9);
  EXPECT_NEAR(odom.pose().yaw, 1.0, 1e-9);
  EXPECT_NEAR(odom.linear(), v, 1e-9);
  EXPECT_NEAR(odom.angular(), w, 1e-9);
  // A step shorter than 0.1 ms changes nothing.
  EXPECT_FALSE(odom.update(left + 1.0, right + 1.0, t + 5e-5));
  EXPECT_NEAR(odom.pose().yaw, 1.0, 1e-9);
}

TEST(DiffDriveOdometry, OpenLoopIntegratesTheCommand) {
  DiffDriveOdometry odom;
  odom.init(0.5, 0.1, 0.1, 5);
  odom.reset(3.0, -2.0, 10.0);  // wheels anywhere: open loop ignores them
  double t = 10.0;
  for (int i = 0; i < 1000; ++i) odom.update_open_loop(0.2, 0.0, t += 0.001);
  EXPECT_NEAR(odom.pose().x, 0.2, 1e-9);
  EXPECT_NEAR(odom.pose().y, 0.0, 1e-12);
}

TEST(EncoderOdometry, IntegratesWheelVelocitiesAlongTheMidwayHeading) {
  EncoderOdometry e;
  // Turning in place: 1 rad/s with wheels 0.4 apart, radius 0.05.
  for (int i = 0; i < 1000; ++i) e.update(-0.2 / 0.05, 0.2 / 0.05, 0.05, 0.4, 0.001);
  EXPECT_NEAR(e.pose.yaw, 1.0, 1e-9);
  EXPECT_NEAR(e.pose.x, 0.0, 1e-12);
  EXPECT_NEAR(e.angular, 1.0, 1e-9);
  EXPECT_NEAR(e.linear, 0.0, 1e-12);
  // Backwards: the linear speed keeps the sign of the travel.
  e.reset();
  e.update(-10.0, -10.0, 0.05, 0.4, 0.01);
  EXPECT_NEAR(e.linear, -0.5, 1e-12);
  EXPECT_NEAR(e.pose.x, -0.005, 1e-12);
}

TEST(SpeedLimiter, VelocityAccelerationAndJerk) {
  SpeedLimiter s;
  EXPECT_DOUBLE_EQ(s.limit(5.0, 0.0, 0.0, 0.01), 5.0);  // nothing set: nothing limited
  s.has_velocity_limits = true;
  s.min_velocity = -1.0;
  s.max_velocity = 2.0;
  EXPECT_DOUBLE_EQ(s.limit(5.0, 0.0, 0.0, 0.01), 2.0);
  EXPECT_DOUBLE_EQ(s.limit(-5.0, 0.0, 0.0, 0.01), -1.0);
  s.has_acceleration_limits = true;
  s.min_acceleration = -4.0;
  s.max_acceleration = 3.0;
  EXPECT_DOUBLE_EQ(s.limit(5.0, 1.0, 1.0, 0.01), 1.03);
  EXPECT_DOUBLE_EQ(s.limit(-5.0, 1.0, 1.0, 0.01), 0.96);
  s.has_jerk_limits = true;
  s.min_jerk = -100.0;
  s.max_jerk = 100.0;
  // From rest (v0 = v1 = 0): the change of velocity change over dt is at most jerk * 2 dt^2.
  EXPECT_NEAR(s.limit(5.0, 0.0, 0.0, 0.01), 0.02, 1e-12);
}

TEST(SpeedLimiter, ReadsRosControllersKeysAndRefusesMinAboveMax) {
  const Params p = Params::from_yaml_string(R"(x:
  has_velocity_limits: true
  max_velocity: 1.5
  has_acceleration_limits: true
  max_acceleration: 2.0
  min_acceleration: -0.5
  has_jerk_limits: false
  max_jerk: 5.0
)");
  const SpeedLimiter s = read_speed_limiter(p.child("x"));
  EXPECT_TRUE(s.has_velocity_limits);
  EXPECT_DOUBLE_EQ(s.min_velocity, -1.5);  // min defaults to -max
  EXPECT_DOUBLE_EQ(s.max_acceleration, 2.0);
  EXPECT_DOUBLE_EQ(s.min_acceleration, -0.5);
  EXPECT_FALSE(s.has_jerk_limits);
  const Params bad = Params::from_yaml_string("x: {has_velocity_limits: true, max_velocity: 1.0, min_velocity: 2.0}\n");
  try {
    read_speed_limiter(bad.child("x"));
    FAIL() << "min above max accepted";
  } catch (const ControllerConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/x/min_velocity"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mechsim::control
