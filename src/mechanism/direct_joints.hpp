#pragma once
// Joints that no transmission drives but a Gazebo model plugin drives or reads. The plugins call
// Gazebo's Joint API directly (SetParam("vel"), SetForce, Position), whatever the transmissions
// say, so the mechanism gives such a joint a JointInfo of its own with role Direct: no
// transmission, no actuator, and no hardware interface (gazebo_ros_control exposes transmission
// joints only, so no ros_control controller may claim it; control::RobotHardware lets model
// plugins command it in every mode).

#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

// Appends a Direct joint for each of `joints` not in `model` yet (joints a transmission drives
// stay as they are; order kept, repeats ignored). Throws MechanismError naming the joint when
// `robot` has no such joint or it is not revolute, continuous or prismatic.
void add_direct_joints(MechanismModel& model, const description::RobotModel& robot, const std::vector<std::string>& joints);

}  // namespace mechsim::mechanism
