#pragma once
// A human-readable summary of a RobotModel, as `mechsim check` prints it (in the spirit of
// ROS's check_urdf): name, root, link and joint counts, DOF, total mass, transmissions by type,
// gazebo extensions and plugins.

#include <string>

#include "description/robot_model.hpp"

namespace mechsim::description {

// Several lines, each ending in '\n'.
std::string summarize_robot(const RobotModel& model);

}  // namespace mechsim::description
