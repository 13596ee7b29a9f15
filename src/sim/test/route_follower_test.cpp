// The route follower: pure pursuit along waypoints, turning on the spot when far off heading.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/route_follower.hpp"

namespace mechsim::sim {
namespace {

TEST(WrapAngle, IntoMinusPiPi) {
  EXPECT_NEAR(wrap_angle(3 * M_PI / 2), -M_PI / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(-3 * M_PI / 2), M_PI / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(M_PI), M_PI, 1e-12);
  EXPECT_NEAR(wrap_angle(0.3), 0.3, 1e-12);
}

TEST(RouteFollower, DrivesStraightAtSpeedTowardsAPointAhead) {
  RouteFollower f({{{10.0, 0.0}}}, RouteParams{});
  const control::Twist t = f.update(0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(t.linear.x, 0.4);
  EXPECT_NEAR(t.angular.z, 0.0, 1e-12);
}

TEST(RouteFollower, TurnsOnTheSpotWhenTheGoalIsBehind) {
  RouteParams p;
  p.max_yaw_rate = 0.5;
  RouteFollower f({{{-5.0, 1.0}}}, p);
  const control::Twist t = f.update(0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(t.linear.x, 0.0);
  EXPECT_DOUBLE_EQ(t.angular.z, 0.5);  // the goal is to the left (y > 0)
}

TEST(RouteFollower, CurvatureSteersTowardsTheLookaheadPoint) {
  RouteParams p;
  p.lookahead = 1.0;
  p.max_yaw_rate = 10.0;
  RouteFollower f({{{0.0, 0.0}}, {{10.0, 0.0}}}, p);
  (void)f.update(0.0, 0.0, 0.0);  // reaches the first waypoint at once
  // Base 0.5 m left of the segment, heading along it: the look-ahead point is (1.0, 0) when the
  // projection is at x = 0; alpha = atan2(-0.5, 1), curvature 2 sin(alpha) / L.
  const control::Twist t = f.update(0.0, 0.5, 0.0);
  const double alpha = std::atan2(-0.5, 1.0);
  const double L = std::hypot(1.0, 0.5);
  EXPECT_NEAR(t.angular.z / t.linear.x, 2 * std::sin(alpha) / L, 1e-12);
  EXPECT_LT(t.angular.z, 0.0);
}

TEST(RouteFollower, SlowsDownToKeepTheYawRateLimit) {
  RouteParams p;
  p.speed = 1.0;
  p.max_yaw_rate = 0.1;
  p.lookahead = 0.5;
  RouteFollower f({{{0.0, 0.0}}, {{10.0, 0.0}}}, p);
  (void)f.update(0.0, 0.0, 0.0);
  const control::Twist t = f.update(0.0, 0.3, 0.0);
  EXPECT_NEAR(std::abs(t.angular.z), 0.1, 1e-12);
  EXPECT_LT(t.linear.x, 1.0);
}

TEST(RouteFollower, AdvancesThroughWaypointsAndStopsAtTheEnd) {
  RouteFollower f({{{1.0, 0.0}}, {{2.0, 0.0}}}, RouteParams{});
  EXPECT_EQ(f.next_waypoint(), 0u);
  (void)f.update(0.9, 0.0, 0.0);
  EXPECT_EQ(f.next_waypoint(), 1u);
  const control::Twist t = f.update(1.95, 0.0, 0.0);
  EXPECT_TRUE(f.done());
  EXPECT_DOUBLE_EQ(t.linear.x, 0.0);
  EXPECT_DOUBLE_EQ(t.angular.z, 0.0);
}

}  // namespace
}  // namespace mechsim::sim
