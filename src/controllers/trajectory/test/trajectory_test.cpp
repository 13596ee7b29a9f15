// Trajectories: sampling through several points, and ros_control's replacement at a time
// (future start, points in the past, desired-state continuity, partial joints, wrapping).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "controllers/trajectory/trajectory.hpp"

namespace mechsim::control {
namespace {

constexpr double kPi = std::numbers::pi;

// A request over `joints` joints with up to 8 points; `named` marks the joints it names.
struct RequestBuilder {
  TrajectoryRequest r;
  RequestBuilder(std::size_t joints, std::vector<std::uint8_t> named) : r(joints, 8) {
    r.joint_in_request = std::move(named);
    r.sequence = 1;
  }
  // Adds a point: positions of every joint (unnamed ones ignored), optional velocities.
  RequestBuilder& point(double t, std::vector<double> p, std::vector<double> v = {}, std::vector<double> a = {}) {
    const std::size_t k = r.point_count++;
    r.time_from_start[k] = t;
    r.point_order[k] = spline_order_for(!v.empty(), !a.empty());
    for (std::size_t j = 0; j < p.size(); ++j) {
      r.positions[r.index(j, k)] = p[j];
      r.velocities[r.index(j, k)] = v.empty() ? 0.0 : v[j];
      r.accelerations[r.index(j, k)] = a.empty() ? 0.0 : a[j];
    }
    return *this;
  }
  RequestBuilder& start_at(double t) {
    r.start_now = false;
    r.start_time = t;
    return *this;
  }
};

Trajectory holding(std::vector<double> positions, double time = 0.0) {
  Trajectory t(positions.size(), 20);
  for (std::size_t j = 0; j < positions.size(); ++j) t.hold(j, time, positions[j]);
  return t;
}

TEST(Trajectory, SamplesAMultiPointTrajectoryThroughItsPoints) {
  Trajectory current = holding({0.0});
  RequestBuilder b(1, {1});
  b.point(1.0, {1.0}, {0.5}).point(2.0, {1.5}, {0.0}).point(4.0, {-0.5}, {0.0});
  Trajectory out(1, 20);
  const std::vector<std::uint8_t> wraps{0};
  const ReplaceOutcome o = replace_trajectory(current, b.r, wraps, 0.0, out);
  ASSERT_EQ(o.code, TrajectoryResultCode::Successful) << o.reason;
  EXPECT_DOUBLE_EQ(o.start, 0.0);
  EXPECT_DOUBLE_EQ(o.end, 4.0);
  EXPECT_EQ(out.segment_count(0), 3u);  // the bridge and two segments (the hold ended at t0 = 0)
  EXPECT_NEAR(out.sample(0, 1.0).position, 1.0, 1e-12);
  EXPECT_NEAR(out.sample(0, 1.0).velocity, 0.5, 1e-12);
  EXPECT_NEAR(out.sample(0, 2.0).position, 1.5, 1e-12);
  EXPECT_NEAR(out.sample(0, 4.0).position, -0.5, 1e-12);
  EXPECT_DOUBLE_EQ(out.sample(0, 9.0).position, -0.5);
  EXPECT_DOUBLE_EQ(out.sample(0, 9.0).velocity, 0.0);
  EXPECT_EQ(out.segment(0, 2).order(), SplineOrder::Cubic);
  // Between points the spline moves continuously (no jumps over 1 ms steps).
  double last = out.sample(0, 0.0).position;
  for (int k = 1; k <= 5000; ++k) {
    const double p = out.sample(0, k * 0.001).position;
    EXPECT_LT(std::fabs(p - last), 0.01) << k;
    last = p;
  }
  EXPECT_DOUBLE_EQ(out.end_time(0), 4.0);
}

TEST(Trajectory, CopiesAreIndependentAndMovesKeepTheSegments) {
  // The segments live in raw storage (constructed as pushed): a copy must own its own.
  Trajectory current = holding({0.0, 0.2});
  RequestBuilder b(2, {1, 0});
  b.point(1.0, {1.0, 0.0}).point(2.0, {-1.0, 0.0});
  Trajectory original(2, 20);
  const std::vector<std::uint8_t> wraps{0, 0};
  ASSERT_EQ(replace_trajectory(current, b.r, wraps, 0.0, original).code, TrajectoryResultCode::Successful);
  Trajectory copy(original);
  EXPECT_EQ(copy.capacity(), 20u);
  EXPECT_EQ(copy.segment_count(0), original.segment_count(0));
  EXPECT_EQ(copy.segment_count(1), 1u);
  EXPECT_DOUBLE_EQ(copy.sample(0, 1.0).position, 1.0);
  EXPECT_DOUBLE_EQ(copy.sample(1, 5.0).position, 0.2);
  original.hold(0, 0.0, 3.0);  // the copy keeps its segments
  EXPECT_DOUBLE_EQ(original.sample(0, 1.0).position, 3.0);
  EXPECT_DOUBLE_EQ(copy.sample(0, 1.0).position, 1.0);
  Trajectory assigned(1, 1);
  assigned = copy;
  EXPECT_EQ(assigned.joint_count(), 2u);
  EXPECT_DOUBLE_EQ(assigned.sample(0, 2.0).position, -1.0);
  Trajectory moved(std::move(assigned));
  EXPECT_DOUBLE_EQ(moved.sample(0, 2.0).position, -1.0);
  EXPECT_DOUBLE_EQ(moved.sample(1, 0.0).position, 0.2);
}

TEST(Trajectory, SplineOrderIsTheLowerOfTheTwoEndsOfASegment) {
  Trajectory current = holding({0.0});
  RequestBuilder b(1, {1});
  b.point(1.0, {1.0}, {0.0}, {0.0}).point(2.0, {2.0}).point(3.0, {3.0}, {0.0}).point(4.0, {4.0}, {0.0}, {0.0});
  Trajectory out(1, 20);
  ASSERT_EQ(replace_trajectory(current, b.r, {0}, 0.0, out).code, TrajectoryResultCode::Successful);
  ASSERT_EQ(out.segment_count(0), 4u);
  EXPECT_EQ(out.segment(0, 0).order(), SplineOrder::Quintic);  // bridge: the current state has every field
  EXPECT_EQ(out.segment(0, 1).order(), SplineOrder::Linear);
  EXPECT_EQ(out.segment(0, 2).order(), SplineOrder::Linear);
  EXPECT_EQ(out.segment(0, 3).order(), SplineOrder::Cubic);
}

TEST(Trajectory, FutureStartKeepsTheCurrentTrajectoryUntilThenAndStartsFromItsState) {
  // Current: a linear move 0 -> 2 over [0, 2].
  Trajectory current = holding({0.0});
  {
    RequestBuilder first(1, {1});
    first.point(2.0, {2.0});
    Trajectory tmp(1, 20);
    ASSERT_EQ(replace_trajectory(current, first.r, {0}, 0.0, tmp).code, TrajectoryResultCode::Successful);
    current = tmp;
  }
  // At t = 0.5 a new trajectory arrives that starts at t = 1.0 and goes to -1 at t = 3.0.
  RequestBuilder next(1, {1});
  next.start_at(1.0).point(2.0, {-1.0}, {0.0}, {0.0});
  Trajectory out(1, 20);
  const ReplaceOutcome o = replace_trajectory(current, next.r, {0}, 0.5, out);
  ASSERT_EQ(o.code, TrajectoryResultCode::Successful) << o.reason;
  EXPECT_DOUBLE_EQ(o.start, 1.0);
  EXPECT_DOUBLE_EQ(o.end, 3.0);
  for (double t : {0.5, 0.75, 0.999}) EXPECT_NEAR(out.sample(0, t).position, current.sample(0, t).position, 1e-12) << t;
  // Continuity at the switch: position and velocity of the old trajectory at t = 1.
  EXPECT_NEAR(out.sample(0, 1.0).position, 1.0, 1e-12);
  EXPECT_NEAR(out.sample(0, 1.0).velocity, 1.0, 1e-12);
  EXPECT_NEAR(out.sample(0, 3.0).position, -1.0, 1e-12);
}

TEST(Trajectory, PointsInThePastAreDropped) {
  Trajectory current = holding({0.3}, 0.0);
  RequestBuilder b(1, {1});
  b.start_at(1.0).point(0.5, {5.0}).point(1.5, {6.0}).point(3.0, {7.0});  // at 1.5, 2.5, 4.0
  Trajectory out(1, 20);
  const ReplaceOutcome o = replace_trajectory(current, b.r, {0}, 2.0, out);
  ASSERT_EQ(o.code, TrajectoryResultCode::Successful);
  EXPECT_DOUBLE_EQ(o.start, 2.0);
  // From the current state at t = 2 (0.3) straight to the first point still ahead (6 at 2.5).
  EXPECT_NEAR(out.sample(0, 2.0).position, 0.3, 1e-12);
  EXPECT_NEAR(out.sample(0, 2.25).position, 0.3 + 0.5 * (6.0 - 0.3), 1e-12);
  EXPECT_NEAR(out.sample(0, 2.5).position, 6.0, 1e-12);
  EXPECT_NEAR(out.sample(0, 4.0).position, 7.0, 1e-12);
}

TEST(Trajectory, EveryPointInThePastIsOldHeaderTimestamp) {
  Trajectory current = holding({0.0});
  RequestBuilder b(1, {1});
  b.start_at(1.0).point(0.5, {1.0}).point(1.0, {2.0});
  Trajectory out(1, 20);
  const ReplaceOutcome o = replace_trajectory(current, b.r, {0}, 2.0, out);
  EXPECT_EQ(o.code, TrajectoryResultCode::OldHeaderTimestamp);
  EXPECT_NE(std::string(o.reason), "");
}

TEST(Trajectory, JointsNotNamedKeepTheirCurrentTrajectory) {
  Trajectory current(2, 20);
  current.hold(0, 0.0, 0.1);
  RequestBuilder first(2, {1, 1});
  first.point(4.0, {1.0, 2.0});
  Trajectory moving(2, 20);
  ASSERT_EQ(replace_trajectory(holding({0.0, 0.0}), first.r, {0, 0}, 0.0, moving).code, TrajectoryResultCode::Successful);
  RequestBuilder partial(2, {0, 1});
  partial.point(1.0, {0.0, -1.0});
  Trajectory out(2, 20);
  ASSERT_EQ(replace_trajectory(moving, partial.r, {0, 0}, 1.0, out).code, TrajectoryResultCode::Successful);
  for (double t : {1.0, 2.0, 4.0, 6.0}) EXPECT_DOUBLE_EQ(out.sample(0, t).position, moving.sample(0, t).position) << t;
  EXPECT_NEAR(out.sample(1, 2.0).position, -1.0, 1e-12);
  EXPECT_NEAR(out.sample(1, 1.0).position, 0.5, 1e-12);  // continuity from the old joint-1 path
}

TEST(Trajectory, ContinuousJointsGoTheShortWayRound) {
  // At 3.0 rad; the target -3.0 rad is 0.283 rad ahead the short way, not 6 rad back.
  Trajectory current = holding({3.0, 3.0});
  RequestBuilder b(2, {1, 1});
  b.point(1.0, {-3.0, -3.0}).point(2.0, {-2.9, -2.9});
  Trajectory out(2, 20);
  const std::vector<std::uint8_t> wraps{1, 0};
  ASSERT_EQ(replace_trajectory(current, b.r, wraps, 0.0, out).code, TrajectoryResultCode::Successful);
  EXPECT_NEAR(out.sample(0, 1.0).position, 2 * kPi - 3.0, 1e-12);
  EXPECT_NEAR(out.sample(0, 2.0).position, 2 * kPi - 2.9, 1e-12);  // later points shift with it
  EXPECT_NEAR(out.sample(0, 0.5).position, 3.0 + 0.5 * (2 * kPi - 6.0), 1e-12);
  EXPECT_NEAR(out.sample(1, 1.0).position, -3.0, 1e-12);           // a limited joint does not wrap
}

TEST(Trajectory, FullStorageIsReportedNotOverrun) {
  Trajectory current = holding({0.0});
  TrajectoryRequest r(1, 8);
  r.sequence = 1;
  r.joint_in_request = {1};
  r.point_count = 8;
  for (std::size_t k = 0; k < 8; ++k) r.time_from_start[k] = 1.0 + static_cast<double>(k);
  Trajectory small(1, 4);
  Trajectory small_current(1, 4);
  small_current.hold(0, 0.0, 0.0);
  const ReplaceOutcome o = replace_trajectory(small_current, r, {0}, 0.0, small);
  EXPECT_EQ(o.code, TrajectoryResultCode::InvalidGoal);
  EXPECT_LE(small.segment_count(0), 4u);
}

}  // namespace
}  // namespace mechsim::control
