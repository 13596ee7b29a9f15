// Spline segments: the boundary conditions of each order hold exactly, the order follows the
// fields a waypoint carries, and sampling outside the segment rests at its ends.

#include <gtest/gtest.h>

#include <cmath>

#include "controllers/trajectory/trajectory_segment.hpp"

namespace mechsim::control {
namespace {

constexpr double kEps = 1e-12;

TEST(SplineOrder, FollowsTheFieldsGiven) {
  EXPECT_EQ(spline_order_for(false, false), SplineOrder::Linear);
  EXPECT_EQ(spline_order_for(true, false), SplineOrder::Cubic);
  EXPECT_EQ(spline_order_for(true, true), SplineOrder::Quintic);
  EXPECT_STREQ(spline_order_name(SplineOrder::Quintic), "quintic");
}

TEST(SplineSegment, LinearInterpolatesPositionsAtConstantVelocity) {
  const SplineSegment s(1.0, {0.5, 9.0, 9.0}, 3.0, {1.5, -9.0, 9.0}, SplineOrder::Linear);
  EXPECT_NEAR(s.sample(1.0).position, 0.5, kEps);
  EXPECT_NEAR(s.sample(3.0).position, 1.5, kEps);
  EXPECT_NEAR(s.sample(2.0).position, 1.0, kEps);
  for (double t : {1.0, 1.7, 2.5, 3.0}) {
    EXPECT_NEAR(s.sample(t).velocity, 0.5, kEps) << t;  // the given velocities are ignored
    EXPECT_NEAR(s.sample(t).acceleration, 0.0, kEps) << t;
  }
}

TEST(SplineSegment, CubicMatchesPositionsAndVelocitiesAtBothEnds) {
  const SplineState a{0.2, -0.4, 7.0}, b{-1.1, 0.9, -7.0};
  const SplineSegment s(2.0, a, 2.8, b, SplineOrder::Cubic);
  const SplineState s0 = s.sample(2.0), s1 = s.sample(2.8);
  EXPECT_NEAR(s0.position, a.position, kEps);
  EXPECT_NEAR(s0.velocity, a.velocity, kEps);
  EXPECT_NEAR(s1.position, b.position, kEps);
  EXPECT_NEAR(s1.velocity, b.velocity, kEps);
  // A cubic's acceleration is linear in time: check it against the central difference.
  const double t = 2.3, h = 1e-5;
  EXPECT_NEAR(s.sample(t).velocity, (s.sample(t + h).position - s.sample(t - h).position) / (2 * h), 1e-8);
  EXPECT_NEAR(s.sample(t).acceleration, (s.sample(t + h).velocity - s.sample(t - h).velocity) / (2 * h), 1e-6);
}

TEST(SplineSegment, QuinticMatchesPositionsVelocitiesAndAccelerationsAtBothEnds) {
  const SplineState a{1.0, 0.5, -2.0}, b{-0.3, -1.2, 3.5};
  const SplineSegment s(0.5, a, 1.75, b, SplineOrder::Quintic);
  const SplineState s0 = s.sample(0.5), s1 = s.sample(1.75);
  EXPECT_NEAR(s0.position, a.position, kEps);
  EXPECT_NEAR(s0.velocity, a.velocity, kEps);
  EXPECT_NEAR(s0.acceleration, a.acceleration, kEps);
  EXPECT_NEAR(s1.position, b.position, 1e-11);
  EXPECT_NEAR(s1.velocity, b.velocity, 1e-11);
  EXPECT_NEAR(s1.acceleration, b.acceleration, 1e-10);
  const double t = 1.1, h = 1e-5;
  EXPECT_NEAR(s.sample(t).velocity, (s.sample(t + h).position - s.sample(t - h).position) / (2 * h), 1e-8);
  EXPECT_NEAR(s.sample(t).acceleration, (s.sample(t + h).velocity - s.sample(t - h).velocity) / (2 * h), 1e-6);
}

TEST(SplineSegment, QuinticRestToRestIsSymmetric) {
  const SplineSegment s(0.0, {0.0, 0.0, 0.0}, 2.0, {1.0, 0.0, 0.0}, SplineOrder::Quintic);
  EXPECT_NEAR(s.sample(1.0).position, 0.5, kEps);
  EXPECT_NEAR(s.sample(1.0).acceleration, 0.0, 1e-12);
  EXPECT_NEAR(s.sample(1.0).velocity, 15.0 / 16.0, 1e-12);  // peak speed of the minimum-jerk profile
}

TEST(SplineSegment, RestsAtItsEndsOutsideItsTimeSpan) {
  const SplineSegment s(1.0, {0.0, 1.0, 0.0}, 2.0, {2.0, 1.0, 0.0}, SplineOrder::Cubic);
  EXPECT_DOUBLE_EQ(s.sample(0.5).position, 0.0);
  EXPECT_DOUBLE_EQ(s.sample(0.5).velocity, 0.0);
  EXPECT_NEAR(s.sample(5.0).position, 2.0, kEps);
  EXPECT_DOUBLE_EQ(s.sample(5.0).velocity, 0.0);
  EXPECT_DOUBLE_EQ(s.sample(5.0).acceleration, 0.0);
}

TEST(SplineSegment, ZeroDurationIsAStepToTheEndState) {
  const SplineSegment s(1.0, {0.0, 0.0, 0.0}, 1.0, {3.0, 0.5, 0.0}, SplineOrder::Cubic);
  EXPECT_DOUBLE_EQ(s.duration(), 0.0);
  EXPECT_DOUBLE_EQ(s.sample(1.0).position, 3.0);
  EXPECT_DOUBLE_EQ(s.sample(1.0).velocity, 0.5);
  EXPECT_DOUBLE_EQ(s.sample(2.0).position, 3.0);
  EXPECT_TRUE(std::isfinite(s.sample(1.0).acceleration));
}

TEST(SplineSegment, HoldKeepsAPositionAtRest) {
  const SplineSegment s = SplineSegment::hold(4.0, -0.25);
  for (double t : {0.0, 4.0, 100.0}) {
    EXPECT_DOUBLE_EQ(s.sample(t).position, -0.25);
    EXPECT_DOUBLE_EQ(s.sample(t).velocity, 0.0);
  }
}

}  // namespace
}  // namespace mechsim::control
