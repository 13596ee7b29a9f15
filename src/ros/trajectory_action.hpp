#pragma once
// <controller>/follow_joint_trajectory: control_msgs/FollowJointTrajectoryAction over a trajectory
// controller's goal port. Goals are submitted to the port at once (rejected goals answered with
// the controller's error code); a wall timer (20 Hz) relays feedback and finishes goal handles
// as the tick reports them (succeeded, aborted, preempted -> canceled). Conversions between the
// ROS messages and control/trajectory_msgs.hpp live here too.

#include <memory>
#include <mutex>
#include <vector>

#include <actionlib/server/action_server.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/JointTrajectoryControllerState.h>
#include <trajectory_msgs/JointTrajectory.h>

#include "ros/bridge/sim_bridge.hpp"

namespace mechsim::ros {

control::JointTrajectory from_msg(const trajectory_msgs::JointTrajectory& msg);
control_msgs::JointTrajectoryControllerState to_msg(const control::JointTrajectoryControllerState& state);

class TrajectoryActionServer {
 public:
  TrajectoryActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port);
  ~TrajectoryActionServer();
  // After this returns the port is never touched again; active goals are aborted.
  void shutdown();

 private:
  using Server = actionlib::ActionServer<control_msgs::FollowJointTrajectoryAction>;
  using GoalHandle = Server::GoalHandle;
  struct Tracked {
    GoalHandle handle;
    std::uint64_t id;
  };
  void on_goal(GoalHandle handle);
  void on_cancel(GoalHandle handle);
  void poll();

  PortRef port_;
  std::mutex mutex_;
  bool alive_ = true;
  std::vector<Tracked> goals_;
  std::uint64_t feedback_sequence_ = 0;
  control::FollowJointTrajectoryFeedback feedback_;
  std::unique_ptr<Server> server_;
  ::ros::WallTimer timer_;
};

}  // namespace mechsim::ros
