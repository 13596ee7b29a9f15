#pragma once
// The actions of ros2_controllers over mechsim's goal ports (action_server.hpp serves them):
//
//   TrajectoryGoal port  control_msgs/action/FollowJointTrajectory  `~/follow_joint_trajectory`
//                        (joint_trajectory_controller; the PR2's JointTrajectoryActionController
//                        and every ros_control trajectory controller mechsim has)
//   GripperGoal port     control_msgs/action/GripperCommand         `~/gripper_cmd`
//                        (gripper_action_controller; the PR2's Pr2GripperController)
//
// Results as ros2_controllers gives them (joint_trajectory_controller.cpp, Jazzy and Humble):
//   SUCCEEDED  error_code SUCCESSFUL (0), "Goal successfully reached!"
//   ABORTED    PATH_TOLERANCE_VIOLATED (-4), "Aborted due to path tolerance violation" (mechsim
//              adds which joint and by how much); GOAL_TOLERANCE_VIOLATED (-5) when the goal
//              time tolerance passed outside the goal tolerances; OLD_HEADER_TIMESTAMP (-3)
//   CANCELED   by cancel_goal: an empty result (0, "");
//              by a newer goal: INVALID_GOAL (-1), "Current goal cancelled due to new incoming action."
//              by the controller's deactivation (or unloading): INVALID_GOAL (-1), "Current goal
//              cancelled during deactivate transition."
//              by a trajectory on ~/joint_trajectory: INVALID_GOAL (-1), mechsim's reason
//              (ros2_controllers would let the goal run on against the new trajectory)
// A goal the controller refuses (not active, joints, sizes, times: ros2_controllers'
// validate_trajectory_msg) is rejected; why is logged, as ros2_controllers logs it.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <mechsim_ros2_msgs/trajectory_msgs.hpp>

#include "bridge/sim_bridge.hpp"
#include "ros2/action_server.hpp"
#include "ros2/node.hpp"

namespace mechsim::ros2 {

// An action server on a goal port of a loaded controller, as a Pollable the SimNode's poller
// polls; `shutdown` ends its goals (the controller is going).
struct ControllerAction {
  std::shared_ptr<Pollable> server;
  std::function<void(const std::string& why)> shutdown;
  std::function<ActionStats()> stats;
  std::string name;  // the action's resolved name
  std::string type;  // control_msgs/action/...
};

// The action of `port` (TrajectoryGoal or GripperGoal) under `name` in `node`; `now`: simulated
// time. Throws NameError or std::runtime_error when the endpoints cannot be made.
ControllerAction make_controller_action(Node& node, const std::string& name, const bridge::PortRef& port,
                                        std::function<double()> now);
// The action's default name for a goal port ("~/follow_joint_trajectory", "~/gripper_cmd").
std::string default_action_name(const bridge::PortRef& port);
// trajectory_msgs/msg/JointTrajectory as mechsim's trajectory controllers take it (the stamp 0:
// "now", the controller's next update).
control::JointTrajectory trajectory_of(const trajectory_msgs::msg::JointTrajectory& msg);
// rcl_action's default result_timeout in `distro` (s): Humble 900, Jazzy 10.
double result_timeout(Distro distro);

}  // namespace mechsim::ros2
