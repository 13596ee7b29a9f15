// Goal validation: each FollowJointTrajectory rejection code, with a message that names what is
// wrong, given at submit time by the goal port (no tick needed); the command port's rejections.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "controllers/trajectory/trajectory_goal.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;
using Code = TrajectoryResultCode;

TrajectoryChannelConfig config(bool partial = false, std::size_t max_points = 4) {
  TrajectoryChannelConfig c;
  c.joints = {"a", "b"};
  c.max_points = max_points;
  c.allow_partial_joints_goal = partial;
  c.default_tolerances = read_default_tolerances(std::nullopt, c.joints);
  return c;
}

FollowJointTrajectoryGoal valid_goal() {
  FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = {"b", "a"};
  g.trajectory.points = {{{0.1, 0.2}, {}, {}, {}, 0.5}, {{0.3, 0.4}, {0.0, 0.0}, {}, {}, 1.0}};
  return g;
}

struct GoalPortTest : ::testing::Test {
  TrajectoryChannel channel{config()};
  TrajectoryGoalPort port{"follow_joint_trajectory", &channel};
  GoalPortTest() { channel.set_running_from_rt(true); }

  void expect_rejected(const FollowJointTrajectoryGoal& goal, Code code, const std::string& text) {
    const GoalSubmission s = port.submit(goal);
    EXPECT_FALSE(s.accepted);
    EXPECT_EQ(s.result.error_code, code) << s.result.error_string;
    EXPECT_THAT(s.result.error_string, HasSubstr(result_code_name(code)));
    EXPECT_THAT(s.result.error_string, HasSubstr(text));
    EXPECT_EQ(port.status(s.id), GoalStatus::Rejected);
    ASSERT_TRUE(port.result(s.id).has_value());
    EXPECT_EQ(port.result(s.id)->error_code, code);
  }
};

TEST_F(GoalPortTest, AValidGoalIsPendingUntilTheTickTakesIt) {
  const GoalSubmission s = port.submit(valid_goal());
  EXPECT_TRUE(s.accepted);
  EXPECT_GT(s.id, 0u);
  EXPECT_EQ(port.status(s.id), GoalStatus::Pending);
  EXPECT_FALSE(port.result(s.id).has_value());
  const TrajectoryRequest* r = channel.take_from_rt();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->goal_id, s.id);
  EXPECT_EQ(r->point_count, 2u);
  // Laid out in the controller's joint order.
  EXPECT_DOUBLE_EQ(r->positions[r->index(0, 0)], 0.2);
  EXPECT_DOUBLE_EQ(r->positions[r->index(1, 0)], 0.1);
  EXPECT_EQ(r->point_order[0], SplineOrder::Linear);
  EXPECT_EQ(r->point_order[1], SplineOrder::Cubic);
  EXPECT_EQ(channel.take_from_rt(), nullptr);  // taken once
  EXPECT_FALSE(port.status(12345).has_value());
}

TEST_F(GoalPortTest, NothingIsTakenWhileTheControllerIsNotRunning) {
  channel.set_running_from_rt(false);
  expect_rejected(valid_goal(), Code::InvalidGoal, "the controller is not running");
  EXPECT_EQ(channel.take_from_rt(), nullptr);
}

TEST_F(GoalPortTest, InvalidJoints) {
  auto g = valid_goal();
  g.trajectory.joint_names = {"a", "zz"};
  expect_rejected(g, Code::InvalidJoints, "'zz' is not a joint of this controller");
  g.trajectory.joint_names = {"a", "a"};
  expect_rejected(g, Code::InvalidJoints, "named twice");
  g = FollowJointTrajectoryGoal{};
  g.trajectory.joint_names = {"a"};
  g.trajectory.points = {{{0.1}, {}, {}, {}, 0.5}};
  expect_rejected(g, Code::InvalidJoints, "allow_partial_joints_goal");
  g.trajectory.joint_names.clear();
  expect_rejected(g, Code::InvalidJoints, "names no joints");
}

// A goal without points asks the controller to stop and hold; its joint names must still be the
// controller's (joint_trajectory_controller checks them before anything else).
TEST_F(GoalPortTest, AGoalWithoutPointsIsAStopRequestOnlyForTheControllersJoints) {
  FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = {"zz"};
  expect_rejected(g, Code::InvalidJoints, "'zz' is not a joint of this controller");
  g.trajectory.joint_names.clear();
  expect_rejected(g, Code::InvalidJoints, "names no joints");
  g.trajectory.joint_names = {"b", "a"};
  const GoalSubmission s = port.submit(g);
  EXPECT_TRUE(s.accepted) << s.result.error_string;
  const TrajectoryRequest* r = channel.take_from_rt();
  ASSERT_NE(r, nullptr);
  EXPECT_TRUE(r->stop);
}

TEST_F(GoalPortTest, InvalidGoalSizes) {
  auto g = valid_goal();
  g.trajectory.points[1].positions = {1.0};
  expect_rejected(g, Code::InvalidGoal, "points[1].positions has 1 values for 2 joints");
  g = valid_goal();
  g.trajectory.points[0].velocities = {1.0, 2.0, 3.0};
  expect_rejected(g, Code::InvalidGoal, "points[0].velocities has 3 values");
  g = valid_goal();
  g.trajectory.points[0].accelerations = {1.0, 2.0};
  expect_rejected(g, Code::InvalidGoal, "accelerations without velocities");
}

TEST_F(GoalPortTest, InvalidGoalValuesAndTimes) {
  auto g = valid_goal();
  g.trajectory.points[1].positions[0] = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(g, Code::InvalidGoal, "points[1] holds a value that is not finite");
  g = valid_goal();
  g.trajectory.points[1].velocities[1] = std::numeric_limits<double>::infinity();
  expect_rejected(g, Code::InvalidGoal, "not finite");
  g = valid_goal();
  g.trajectory.points[1].time_from_start = 0.5;
  expect_rejected(g, Code::InvalidGoal, "times must increase strictly");
  g.trajectory.points[1].time_from_start = 0.2;
  expect_rejected(g, Code::InvalidGoal, "is not after points[0]");
  g = valid_goal();
  g.trajectory.points[0].time_from_start = -1.0;
  expect_rejected(g, Code::InvalidGoal, "points[0].time_from_start");
  g = valid_goal();
  g.trajectory.start_time = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(g, Code::InvalidGoal, "header.stamp");
}

TEST_F(GoalPortTest, InvalidGoalTooManyPoints) {
  auto g = valid_goal();
  for (int k = 0; k < 3; ++k) g.trajectory.points.push_back({{0.0, 0.0}, {}, {}, {}, 2.0 + k});
  expect_rejected(g, Code::InvalidGoal, "has 5 points; this controller holds at most 4 (parameter max_trajectory_points)");
}

TEST_F(GoalPortTest, InvalidGoalTolerances) {
  auto g = valid_goal();
  g.path_tolerance = {{"elbow", 0.1, 0.0, 0.0}};
  expect_rejected(g, Code::InvalidGoal, "path_tolerance[0] names joint 'elbow'");
  g = valid_goal();
  g.goal_tolerance = {{"a", std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}};
  expect_rejected(g, Code::InvalidGoal, "goal_tolerance[0] (joint 'a') is not finite");
}

TEST_F(GoalPortTest, OldHeaderTimestampAgainstTheTickClock) {
  channel.set_time_from_rt(10.0);
  auto g = valid_goal();
  g.trajectory.start_time = 8.0;  // ends at 9.0
  expect_rejected(g, Code::OldHeaderTimestamp, "at or before the current time 10");
  g.trajectory.start_time = 9.5;  // ends at 10.5: accepted
  EXPECT_TRUE(port.submit(g).accepted);
}

TEST_F(GoalPortTest, GoalTolerancesResolveAgainstTheDefaults) {
  TrajectoryChannelConfig c = config();
  c.default_tolerances.path[0].position = 0.2;
  c.default_tolerances.goal[1].position = 0.05;
  c.default_tolerances.goal_time = 0.5;
  TrajectoryChannel ch(c);
  ch.set_running_from_rt(true);
  TrajectoryGoalPort p("g", &ch);
  auto g = valid_goal();
  g.path_tolerance = {{"a", 0.0, 0.3, 0.0}, {"b", 0.1, 0.0, 0.0}};
  g.goal_tolerance = {{"b", -1.0, 0.0, 0.0}};
  g.goal_time_tolerance = 2.0;
  ASSERT_TRUE(p.submit(g).accepted);
  const TrajectoryRequest* r = ch.take_from_rt();
  ASSERT_NE(r, nullptr);
  EXPECT_DOUBLE_EQ(r->tolerances.path[0].position, 0.2);  // 0 keeps the default
  EXPECT_DOUBLE_EQ(r->tolerances.path[0].velocity, 0.3);
  EXPECT_DOUBLE_EQ(r->tolerances.path[1].position, 0.1);
  EXPECT_DOUBLE_EQ(r->tolerances.goal[1].position, 0.0);  // < 0 removes it
  EXPECT_DOUBLE_EQ(r->tolerances.goal[0].velocity, kDefaultStoppedVelocityTolerance);
  EXPECT_DOUBLE_EQ(r->tolerances.goal_time, 2.0);
}

TEST_F(GoalPortTest, AGoalOverwrittenBeforeTheTickIsPreemptedUnrun) {
  const GoalSubmission first = port.submit(valid_goal());
  const GoalSubmission second = port.submit(valid_goal());
  ASSERT_TRUE(first.accepted && second.accepted);
  const TrajectoryRequest* r = channel.take_from_rt();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->goal_id, second.id);
  TrajectoryEvent taken;
  taken.kind = TrajectoryEvent::Kind::Taken;
  taken.sequence = r->sequence;
  taken.goal_id = r->goal_id;
  channel.report_from_rt(taken);
  EXPECT_EQ(port.status(first.id), GoalStatus::Preempted);
  EXPECT_EQ(port.status(second.id), GoalStatus::Active);
  EXPECT_FALSE(port.cancel(first.id));  // already finished
  EXPECT_TRUE(port.cancel(second.id));
  std::uint64_t id = 0;
  ASSERT_TRUE(channel.next_cancel_from_rt(id));
  EXPECT_EQ(id, second.id);
}

TEST_F(GoalPortTest, RemembersABoundedNumberOfFinishedGoals) {
  auto g = valid_goal();
  g.trajectory.joint_names = {"a", "nope"};
  const std::uint64_t first = port.submit(g).id;
  std::uint64_t last = first;
  for (std::size_t k = 0; k < TrajectoryChannel::kMaxGoalRecords + 10; ++k) last = port.submit(g).id;
  EXPECT_FALSE(port.status(first).has_value());
  EXPECT_EQ(port.status(last), GoalStatus::Rejected);
  const GoalSubmission pending = port.submit(valid_goal());
  for (std::size_t k = 0; k < TrajectoryChannel::kMaxGoalRecords + 10; ++k) (void)port.submit(g);
  EXPECT_EQ(port.status(pending.id), GoalStatus::Pending);  // unfinished goals are never forgotten
}

TEST(TrajectoryCommandPort, RejectsWhatTheGoalPortRejectsAndCountsIt) {
  TrajectoryChannel channel(config(true));
  channel.set_running_from_rt(true);
  TrajectoryCommandPort port("command", &channel);
  JointTrajectory t;
  t.joint_names = {"a"};
  t.points = {{{std::numeric_limits<double>::quiet_NaN()}, {}, {}, {}, 1.0}};
  std::string error;
  EXPECT_FALSE(port.write(t, &error));
  EXPECT_THAT(error, HasSubstr("port 'command': INVALID_GOAL"));
  EXPECT_EQ(port.count(), 1u);
  EXPECT_EQ(channel.take_from_rt(), nullptr);
  t.points[0].positions[0] = 0.5;
  EXPECT_TRUE(port.write(t, &error));  // partial goals allowed here
  EXPECT_EQ(port.accepted(), 1u);
  const TrajectoryRequest* r = channel.take_from_rt();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->goal_id, 0u);
  EXPECT_EQ(r->joint_in_request, (std::vector<std::uint8_t>{1, 0}));
  // An empty trajectory is a stop request.
  EXPECT_TRUE(port.write(JointTrajectory{}, &error));
  r = channel.take_from_rt();
  ASSERT_NE(r, nullptr);
  EXPECT_TRUE(r->stop);
}

TEST(TrajectoryTolerances, DefaultsFromParametersWithPathsInErrors) {
  const Params p = Params::from_yaml_string(R"(
c:
  constraints:
    goal_time: 0.6
    stopped_velocity_tolerance: 0.05
    a: {trajectory: 0.2, goal: 0.02}
)");
  const TrajectoryTolerances t = read_default_tolerances(p.find("c/constraints"), {"a", "b"});
  EXPECT_DOUBLE_EQ(t.goal_time, 0.6);
  EXPECT_DOUBLE_EQ(t.path[0].position, 0.2);
  EXPECT_DOUBLE_EQ(t.goal[0].position, 0.02);
  EXPECT_DOUBLE_EQ(t.goal[0].velocity, 0.05);
  EXPECT_DOUBLE_EQ(t.path[1].position, 0.0);
  EXPECT_DOUBLE_EQ(t.goal[1].velocity, 0.05);
  const Params bad = Params::from_yaml_string("c: {constraints: {a: {goal: -1}}}");
  try {
    (void)read_default_tolerances(bad.find("c/constraints"), {"a"});
    FAIL() << "accepted a negative tolerance";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("/c/constraints/a/goal"));
  }
}

TEST(TrajectoryTolerances, WithinToleranceReportsTheFirstQuantityExceeded) {
  ToleranceViolation v;
  EXPECT_TRUE(within_tolerance({0.1, 0.0, 0.0}, 0.09, 5.0, 5.0, &v));  // unchecked quantities
  EXPECT_FALSE(within_tolerance({0.1, 0.2, 0.0}, 0.05, -0.3, 0.0, &v));
  EXPECT_EQ(v.quantity, ToleranceQuantity::Velocity);
  EXPECT_DOUBLE_EQ(v.error, -0.3);
  EXPECT_DOUBLE_EQ(v.tolerance, 0.2);
  EXPECT_FALSE(within_tolerance({0.0, 0.0, 1.0}, 0.0, 0.0, std::numeric_limits<double>::quiet_NaN(), &v));
  EXPECT_EQ(v.quantity, ToleranceQuantity::Acceleration);
}

}  // namespace
}  // namespace mechsim::control
