#pragma once
// ros2_controllers' types, for robots described with <ros2_control> tags and configured with ROS 2
// parameter files (control/ros2_params.hpp). register_ros2_controllers adds them over mechsim's
// built-in (ROS 1) types in a registry, replacing the types both name alike with ROS 2's
// parameters and semantics:
//
//   joint_state_broadcaster/JointStateBroadcaster       joint_state_broadcaster.hpp
//   imu_sensor_broadcaster/IMUSensorBroadcaster         imu_sensor_broadcaster.hpp
//   forward_command_controller/ForwardCommandController joints, interface_name
//   position_controllers/JointGroupPositionController   joints (position)
//   velocity_controllers/JointGroupVelocityController   joints (velocity)
//   effort_controllers/JointGroupEffortController       joints (effort)
//   joint_trajectory_controller/JointTrajectoryController  controllers/trajectory/trajectory_controller.hpp (ros2())
//   diff_drive_controller/DiffDriveController           ros2_diff_drive_params.hpp
//   tricycle_controller/TricycleController              tricycle_controller.hpp
//
// Their ports (what the wire layer binds to ROS 2 topics):
//   JointStateBroadcaster      "joint_states"  JointStates
//   IMUSensorBroadcaster       "imu"           ImuState
//   forward / group commands   "command"       ArrayCommand (one value per joint), "state" (not bound)
//   JointTrajectoryController  "command" TrajectoryCommand, "follow_joint_trajectory"
//                              TrajectoryGoal, "state" TrajectoryState, "query_state"
//                              TrajectoryQuery, "gains/<joint>" (not bound)
//   DiffDriveController        "cmd_vel" TwistCommand, "odom" Odometry, "cmd_vel_out" TwistState
//                              (publish_limited_velocity)
//   TricycleController         "cmd_vel" TwistCommand, "odom" Odometry

#include "control/controller_registry.hpp"
#include "control/controller_plugins.hpp"

namespace mechsim::control {

inline constexpr const char* kForwardCommandControllerType = "forward_command_controller/ForwardCommandController";

// The ros2_controllers types mechsim simulates (the list above), in a sorted list.
const std::vector<std::string>& ros2_controller_types();

// Adds (or replaces) the types above in `registry`.
void register_ros2_controllers(ControllerRegistry& registry);

// The registry a ros2_control robot's controller manager uses: mechsim's built-in types, the
// controller plugins found (controller_registry_with_plugins), then register_ros2_controllers.
ControllerRegistry ros2_controller_registry(const ControllerPluginSet& plugins = find_controller_plugins());

}  // namespace mechsim::control
