// The trajectory controller's update() allocates nothing: 1000 manager ticks with an active
// goal (taken from the goal port, sampled, tolerance-checked, state and feedback published), then
// a preempting goal and a cancel. The counting operator new is allocation_test.cpp's (one per
// test program).

#include <gtest/gtest.h>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"
#include "controllers/trajectory/trajectory_controller.hpp"
#include "controllers/test/allocation_counter.hpp"

namespace mechsim::control {
namespace {

FollowJointTrajectoryGoal goal_through(double scale, int points) {
  FollowJointTrajectoryGoal g;
  for (int j = 0; j < 7; ++j) g.trajectory.joint_names.push_back(std::string("j").append(std::to_string(j)));
  for (int k = 1; k <= points; ++k) {
    TrajectoryPoint p;
    for (int j = 0; j < 7; ++j) {
      p.positions.push_back(scale * (k % 2 == 0 ? 0.5 : -0.5) * (1.0 + 0.1 * j));
      p.velocities.push_back(0.0);
      p.accelerations.push_back(0.0);
    }
    p.time_from_start = 0.1 * k;
    g.trajectory.points.push_back(p);
  }
  g.path_tolerance = {{"j0", 10.0, 0.0, 0.0}};
  return g;
}

TEST(TrajectoryAllocation, UpdateAllocatesNothingWithAnActiveTrajectory) {
  auto robot = testing::make_robot(7);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(R"(
c:
  type: effort_controllers/JointTrajectoryController
  joints: [j0, j1, j2, j3, j4, j5, j6]
  gains: {j0: {p: 900, d: 60}, j1: {p: 900, d: 60}, j2: {p: 900, d: 60}, j3: {p: 900, d: 60},
          j4: {p: 900, d: 60}, j5: {p: 900, d: 60}, j6: {p: 900, d: 60}}
  constraints: {goal_time: 1.0, j0: {trajectory: 5.0, goal: 0.5}}
  state_publish_rate: 0
  action_monitor_rate: 0
  max_trajectory_points: 64
)"), builtin_controller_registry());
  ASSERT_TRUE(manager.load_controller("c").ok);
  ASSERT_TRUE(manager.switch_controllers({"c"}, {}, SwitchStrictness::Strict).ok);
  double time = testing::run(manager, *robot, 0.0, 2);
  auto* goals = manager.controller("c")->port_as<TrajectoryGoalPort>("follow_joint_trajectory");

  const GoalSubmission first = goals->submit(goal_through(1.0, 50));  // 5 s, 50 quintic points
  ASSERT_TRUE(first.accepted) << first.result.error_string;
  testing::start_counting_allocations();
  time = testing::run(manager, *robot, time, 1000);
  long allocations = testing::stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(goals->status(first.id), GoalStatus::Active);
  EXPECT_GT(goals->feedback_sequence(), 900u);

  const GoalSubmission second = goals->submit(goal_through(0.5, 60));
  ASSERT_TRUE(second.accepted);
  testing::start_counting_allocations();
  time = testing::run(manager, *robot, time, 100);
  allocations = testing::stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(goals->status(first.id), GoalStatus::Preempted);
  EXPECT_EQ(goals->status(second.id), GoalStatus::Active);

  ASSERT_TRUE(goals->cancel(second.id));
  testing::start_counting_allocations();
  time = testing::run(manager, *robot, time, 10);
  allocations = testing::stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(goals->status(second.id), GoalStatus::Preempted);
  EXPECT_EQ(manager.controller_info("c")->statistics.failures, 0u);
}

TEST(TrajectoryAllocation, TheSharedCounterSeesAllocations) {
  testing::start_counting_allocations();
  auto* v = new std::vector<double>(10);
  delete v;
  EXPECT_GE(testing::stop_counting_allocations(), 1);
}

}  // namespace
}  // namespace mechsim::control
