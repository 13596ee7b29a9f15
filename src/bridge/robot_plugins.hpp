#pragma once
// What a robot's <gazebo> plugins say about its ROS side (C++17-clean: the ROS 1 binding includes it).

#include <string>

#include "description/robot_model.hpp"

namespace mechsim::bridge {

// The gazebo_ros_control plugin's <robotNamespace> ("" when it names none); *pr2 is set when the
// PR2's own plugin (pr2_gazebo_plugins' gazebo_ros_controller_manager, which runs
// pr2_controller_manager) is there.
inline std::string plugin_namespace(const description::RobotModel& robot, bool* pr2) {
  std::string ns;
  for (const auto& plugin : robot.plugins) {
    if (plugin.filename.find("gazebo_ros_control") != std::string::npos) {
      if (auto it = plugin.parameters.find("robotNamespace"); it != plugin.parameters.end()) ns = it->second;
    }
    if (plugin.filename.find("gazebo_ros_controller_manager") != std::string::npos) *pr2 = true;
  }
  return ns;
}

// Whether the robot runs a controller manager in Gazebo: gazebo_ros_control's plugin or the PR2's.
inline bool has_controller_manager_plugin(const description::RobotModel& robot) {
  for (const auto& plugin : robot.plugins) {
    if (plugin.filename.find("gazebo_ros_control") != std::string::npos ||
        plugin.filename.find("gazebo_ros_controller_manager") != std::string::npos) {
      return true;
    }
  }
  return false;
}

}  // namespace mechsim::bridge
