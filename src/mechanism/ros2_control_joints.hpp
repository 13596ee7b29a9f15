#pragma once
// The joints of a description's <ros2_control> tags (description/ros2_control.hpp) in the
// mechanism, as Gazebo's system plugins (gazebo_ros2_control/GazeboSystem,
// gz_ros2_control/GazeboSimSystem) expose them to ros2_control:
//
//   - every <ros2_control> joint is a mechanism joint, in the tags' order; a joint no
//     transmission drives gets a SimpleTransmission of reduction 1 (Gazebo's systems ignore
//     transmissions: commands reach the joint as given), named "<joint>_ros2_control" with an
//     actuator of that name; a joint a <transmission> already drives (the PR2's wrists) keeps it;
//   - its command interfaces ("position", "velocity", "effort") are what controllers may claim
//     (JointInfo::interfaces, replacing a transmission's), with each one's min/max
//     (JointInfo::command_min/max); its state interfaces are what they may read
//     (JointInfo::state_interfaces);
//   - a joint without command interfaces, or a mimic joint (Jazzy: a URDF <mimic>; Humble:
//     <param name="mimic">), is passive: no controller commands it; the physics moves it (a mimic
//     joint is a constraint on its leader, description/urdf sets its URDF mimic from the param);
//   - with the plugin's <hold_joints> (default true), a joint with command interfaces that no
//     running controller claims holds still (JointInfo::hold_when_unclaimed).
// Joints with unsimulated interfaces ("position_pid", "acceleration") are left without them.

#include "description/robot_model.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

// Adds (or completes) the joints of every <ros2_control> tag of `robot`. build_mechanism calls
// it after the transmissions. Throws MechanismError naming the joint, the tag and the line for a
// joint the robot lacks or that cannot move (the URDF reader has refused those already).
void add_ros2_control_joints(MechanismModel& model, const description::RobotModel& robot);

}  // namespace mechsim::mechanism
