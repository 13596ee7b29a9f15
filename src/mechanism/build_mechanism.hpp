#pragma once
// Building the mechanism of a robot from its description.

#include "description/robot_model.hpp"
#include "mechanism/mechanism_error.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

// One MechanismModel holding every transmission of `robot` in document order, the joints they
// name (actuated, passive and simulated ones, in the order the transmissions name them) and
// their actuators. Several SimpleTransmissions naming one joint (one per hardware interface, as
// ros_control allows) make one transmission with all their interfaces (add_to_driven_joint);
// repeated transmission names are no error. Throws MechanismError naming the transmission, the
// joint/actuator/parameter and the URDF line: unknown transmission type, a joint not in the robot
// or not movable, a joint driven by two transmissions that are not both simple or disagree on
// reduction or offset, an actuator of two joints, a zero reduction (or a missing one in the PR2
// format), an unknown hardware interface, missing or bad type-specific parameters. Then the
// joints of the robot's <ros2_control> tags (mechanism/ros2_control_joints.hpp).
MechanismModel build_mechanism(const description::RobotModel& robot);

}  // namespace mechsim::mechanism
