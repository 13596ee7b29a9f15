#pragma once
// Building the mechanism of a robot from its description.

#include "description/robot_model.hpp"
#include "mechanism/mechanism_error.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

// One MechanismModel holding every transmission of `robot` in document order, the joints they
// name (actuated, passive and simulated ones, in the order the transmissions name them) and
// their actuators. Throws MechanismError naming the transmission, the joint/actuator/parameter
// and the URDF line: unknown transmission type, a joint not in the robot or not movable, an
// actuator or joint claimed twice, a zero or missing reduction, an unknown hardware interface,
// missing or bad type-specific parameters.
MechanismModel build_mechanism(const description::RobotModel& robot);

}  // namespace mechsim::mechanism
