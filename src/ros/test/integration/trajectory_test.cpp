// A trajectory controller on the CC8's steering joints through ROS: the FollowJointTrajectory
// action (goal accepted, feedback, SUCCEEDED; an invalid goal REJECTED with INVALID_JOINTS), the
// `command` topic, and the JointTrajectoryControllerState `state` topic.
#include <gmock/gmock.h>

#include <atomic>
#include <cmath>
#include <mutex>

#include <actionlib/client/simple_action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/JointTrajectoryControllerState.h>
#include <control_msgs/QueryTrajectoryState.h>
#include <controller_manager_msgs/ListControllers.h>
#include <trajectory_msgs/JointTrajectory.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

const std::vector<std::string> kSteering = {"steering_FL", "steering_FR", "steering_RL", "steering_RR"};

trajectory_msgs::JointTrajectory to(double angle, double seconds) {
  trajectory_msgs::JointTrajectory t;
  t.joint_names = kSteering;
  trajectory_msgs::JointTrajectoryPoint p;
  p.positions.assign(kSteering.size(), angle);
  p.velocities.assign(kSteering.size(), 0.0);
  p.time_from_start = ::ros::Duration(seconds);
  t.points.push_back(p);
  return t;
}

TEST_F(CC8Node, SteeringTrajectoryControllerServesTheActionTheCommandTopicAndState) {
  const std::string yaml = write_file("steering.yaml", R"(
steering_trajectory_controller:
  type: effort_controllers/JointTrajectoryController
  joints: [steering_FL, steering_FR, steering_RL, steering_RR]
  gains:
    steering_FL: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
    steering_FR: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
    steering_RL: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
    steering_RR: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
  constraints:
    goal_time: 2.0
    stopped_velocity_tolerance: 0.2  # the steering settles slowly on these gains
)");
  ChildProcess& sp = spawner({yaml}, "trajectory_spawner");
  ASSERT_TRUE(wait_until(
      [&] {
        controller_manager_msgs::ListControllers list;
        if (!call("/cc8/controller_manager/list_controllers", list)) return false;
        return list.response.controller.size() == 1 && list.response.controller[0].state == "running";
      },
      20.0))
      << sp.log();

  std::mutex m;
  std::vector<double> desired, actual;
  ::ros::Subscriber state = nh_.subscribe<control_msgs::JointTrajectoryControllerState>(
      "/cc8/steering_trajectory_controller/state", 10,
      [&](const control_msgs::JointTrajectoryControllerState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        desired = msg->desired.positions;
        actual = msg->actual.positions;
      });

  actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction> client(
      "/cc8/steering_trajectory_controller/follow_joint_trajectory", true);
  ASSERT_TRUE(client.waitForServer(::ros::Duration(10.0)));
  // Feedback and result arrive on separate topics (separate connections, callbacks on the
  // spinner's two threads): the last feedback may be handled after the result.
  std::atomic<int> feedback_count{0};
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = to(0.3, 1.0);
  client.sendGoal(goal, {}, {}, [&](const control_msgs::FollowJointTrajectoryFeedbackConstPtr&) { ++feedback_count; });
  ASSERT_TRUE(client.waitForResult(::ros::Duration(15.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::SUCCEEDED) << client.getState().getText();
  EXPECT_EQ(client.getResult()->error_code, control_msgs::FollowJointTrajectoryResult::SUCCESSFUL);
  EXPECT_TRUE(wait_until([&] { return feedback_count.load() > 0; }, 2.0)) << "no feedback for the goal";
  EXPECT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return actual.size() == 4 && std::abs(actual[0] - 0.3) < 0.05 && std::abs(actual[3] - 0.3) < 0.05;
      },
      5.0));

  // A goal naming a joint the controller does not have is rejected with INVALID_JOINTS.
  control_msgs::FollowJointTrajectoryGoal bad;
  bad.trajectory = to(0.1, 1.0);
  bad.trajectory.joint_names[0] = "no_such_joint";
  client.sendGoal(bad);
  ASSERT_TRUE(client.waitForResult(::ros::Duration(10.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::REJECTED);
  EXPECT_EQ(client.getResult()->error_code, control_msgs::FollowJointTrajectoryResult::INVALID_JOINTS);

  // The command topic: back to -0.2 rad.
  ::ros::Publisher cmd =
      nh_.advertise<trajectory_msgs::JointTrajectory>("/cc8/steering_trajectory_controller/command", 1, true);
  cmd.publish(to(-0.2, 0.5));
  EXPECT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return desired.size() == 4 && std::abs(desired[1] + 0.2) < 1e-3 && std::abs(actual[1] + 0.2) < 0.05;
      },
      10.0))
      << "steering_FR desired " << (desired.size() > 1 ? desired[1] : NAN) << ", actual "
      << (actual.size() > 1 ? actual[1] : NAN);

  // query_state: the trajectory at a later time is the command's end point; a new command
  // changes what it answers.
  control_msgs::QueryTrajectoryState query;
  query.request.time = ::ros::Time(clock_now() + 5.0);
  ASSERT_TRUE(call("/cc8/steering_trajectory_controller/query_state", query));
  EXPECT_EQ(query.response.name, kSteering);
  ASSERT_EQ(query.response.position.size(), 4u);
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_NEAR(query.response.position[j], -0.2, 1e-9) << kSteering[j];
    EXPECT_NEAR(query.response.velocity[j], 0.0, 1e-9) << kSteering[j];
  }
  cmd.publish(to(0.25, 2.0));
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return desired.size() == 4 && desired[1] > -0.19;
      },
      10.0));
  const double now = clock_now();
  query.request.time = ::ros::Time(now + 10.0);
  ASSERT_TRUE(call("/cc8/steering_trajectory_controller/query_state", query));
  EXPECT_NEAR(query.response.position[2], 0.25, 1e-9);
  query.request.time = ::ros::Time(now);
  ASSERT_TRUE(call("/cc8/steering_trajectory_controller/query_state", query));
  EXPECT_GT(query.response.velocity[2], 0.0) << "under way at " << now << " s";
  std::printf("query_state at t=%.3f s: steering_RL %.4f rad, %.4f rad/s\n", now, query.response.position[2],
              query.response.velocity[2]);
}

}  // namespace
}  // namespace mechsim::ros::test
