#pragma once
// The PR2's own action interfaces over the controllers' goal ports, beside the generic
// follow_joint_trajectory (trajectory_action.hpp), with the same polling design: goals are
// submitted to the port at once, and a wall timer (20 Hz) relays feedback and finishes goal
// handles as the tick reports them.
//
//   Pr2TrajectoryActionServer  <controller>/joint_trajectory_action
//       pr2_controllers_msgs/JointTrajectoryAction of robot_mechanism_controllers/
//       JointTrajectoryActionController: the goal is a bare trajectory checked against the
//       controller's own constraints (joint_trajectory_action_node/constraints); the result is
//       empty. SUCCEEDED when the joints are within the goal constraints by the end time plus
//       goal_time; ABORTED on a violated constraint or a late goal; PREEMPTED by a newer goal or
//       a `command` trajectory; REJECTED when the controller refuses it (wrong joints, stopped).
//   GripperActionServer        <gripper>/gripper_action
//       pr2_controllers_msgs/Pr2GripperCommandAction with pr2_gripper_action's semantics:
//       SUCCEEDED with reached_goal = true once the gap is within goal_threshold; ABORTED with
//       stalled = true when the gap stops moving short of it (the gripper keeps squeezing);
//       PREEMPTED by a cancel, a newer goal or a plain `command`. Feedback: position, effort,
//       stalled, reached_goal at the timer's rate.

#include <memory>
#include <mutex>
#include <vector>

#include <actionlib/server/action_server.h>
#include <pr2_controllers_msgs/JointTrajectoryAction.h>
#include <pr2_controllers_msgs/Pr2GripperCommandAction.h>

#include "ros/bridge/sim_bridge.hpp"

namespace mechsim::ros {

class Pr2TrajectoryActionServer {
 public:
  // `port` is the controller's follow_joint_trajectory goal port.
  Pr2TrajectoryActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port);
  ~Pr2TrajectoryActionServer();
  // After this returns the port is never touched again; active goals are aborted.
  void shutdown();

 private:
  using Server = actionlib::ActionServer<pr2_controllers_msgs::JointTrajectoryAction>;
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
  std::unique_ptr<Server> server_;
  ::ros::WallTimer timer_;
};

class GripperActionServer {
 public:
  // `port` is the gripper controller's gripper_action goal port.
  GripperActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port);
  ~GripperActionServer();
  void shutdown();  // as Pr2TrajectoryActionServer::shutdown

 private:
  using Server = actionlib::ActionServer<pr2_controllers_msgs::Pr2GripperCommandAction>;
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
  std::unique_ptr<Server> server_;
  ::ros::WallTimer timer_;
};

}  // namespace mechsim::ros
