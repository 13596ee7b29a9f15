#pragma once
// A human-readable summary of a RobotModel, as `mechsim check` prints it (in the spirit of
// ROS's check_urdf): name, root, link and joint counts, DOF, total mass, transmissions by type,
// gazebo extensions and plugins, sensors.

#include <string>

#include "description/robot_model.hpp"

namespace mechsim::description {

struct SensorSpec;

// Several lines, each ending in '\n'. Ends with the sensors (describe_sensor each).
std::string summarize_robot(const RobotModel& model);

// The <ros2_control> tags (hardware, joints with their command and state interfaces, min/max,
// initial values, mimic relations, sensors, GPIOs) and the ros2_control plugin's settings; ""
// for a robot without <ros2_control> tags. summarize_robot includes it.
std::string summarize_ros2_control(const RobotModel& model);

// One line: name, type, link, rate, and the ROS topic and frame it publishes, or why it is not
// simulated (NOT SIMULATED: reason) or not published.
std::string describe_sensor(const SensorSpec& sensor);

}  // namespace mechsim::description
