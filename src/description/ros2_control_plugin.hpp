#pragma once
// The ros2_control model plugin of a description: gazebo_ros2_control's (Gazebo classic, Humble:
// <plugin filename="libgazebo_ros2_control.so">) or gz_ros2_control's (modern Gazebo, Humble and
// Jazzy: filename "gz_ros2_control-system", name gz_ros2_control::GazeboSimROS2ControlPlugin; its
// old name ign_ros2_control-system). What its elements say, with the plugins' defaults:
//
//   <parameters>FILE.yaml</parameters>   controller YAML, ROS 2 parameter format; may be repeated
//                                        (xacro has expanded $(find pkg) already); also
//                                        <ros><argument>--params-file</argument><argument>F</argument>
//   <robot_param>robot_description</robot_param>          where the URDF is (older releases)
//   <robot_param_node>robot_state_publisher</robot_param_node>
//   <controller_manager_name>controller_manager</controller_manager_name>
//   <hold_joints>true</hold_joints>     joints no controller claims hold their position
//   <ros><namespace>ns</namespace><remapping>from:=to</remapping>...</ros>
//                                        the controller manager's and its controllers' namespace
//                                        and remappings (rcl's --remap rules)
//   <e_stop_topic>, <position_proportional_gain>   read and reported (not simulated)
//
// The wire layer (src/ros2) names the controller manager's and the controllers' topics from the
// namespace and remappings; the simulation reads the parameter files.

#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

// libgazebo_ros2_control.so, gz_ros2_control-system, libgz_ros2_control-system.so,
// ign_ros2_control-system, libign_ros2_control-system.so.
bool is_ros2_control_plugin(const std::string& filename);

struct Ros2Remapping {
  std::string from, to;  // rcl's "from:=to"
};

struct Ros2ControlPlugin {
  std::string origin;  // "file:line" of the <plugin> element
  std::string name, filename;
  bool modern_gazebo = false;  // gz_ros2_control (or ign_) rather than gazebo_ros2_control
  // Parameter files in the order given (<parameters> elements, then <ros><argument>
  // --params-file pairs), as written, and each resolved to a path that exists when one does (as
  // written when absolute or found from the working directory, else beside the description),
  // "" when none does.
  std::vector<std::string> parameters;
  std::vector<std::string> parameter_paths;
  std::string robot_param = "robot_description";
  std::string robot_param_node = "robot_state_publisher";
  std::string controller_manager_name = "controller_manager";
  bool hold_joints = true;
  std::string ros_namespace;  // <ros><namespace> as written ("" when absent)
  std::vector<Ros2Remapping> remappings;  // <ros><remapping>, in order
  std::vector<std::string> arguments;     // <ros><argument>, in order
  std::string e_stop_topic;               // "" when absent
  std::optional<double> position_proportional_gain;

  // The namespace as a ROS 2 node namespace: "/" for none, else "/ns" (leading '/', no trailing).
  std::string node_namespace() const;
  // The controller manager's fully qualified node name: node_namespace() + "/" + name.
  std::string controller_manager_node() const;
};

// The first ros2_control model plugin of `robot`, or nullopt. Throws DescriptionError naming the
// file, line and element for a <hold_joints> that is not a boolean, a <remapping> without ":=",
// a --params-file argument without a file, or a <position_proportional_gain> that is not a number.
std::optional<Ros2ControlPlugin> find_ros2_control_plugin(const RobotModel& robot);

// "/" + trimmed ns without trailing '/' ("/" for "" or "/").
std::string normalize_ros2_namespace(const std::string& ns);

}  // namespace mechsim::description
