#pragma once
// Hand-built robot descriptions for the mechanism unit tests.

#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism::test {

description::Joint make_joint(const std::string& name, description::JointType type,
                              std::optional<description::JointLimits> limits = std::nullopt,
                              std::optional<description::SafetyController> safety = std::nullopt, int line = 0);

// A robot with the given joints (a chain of links) and no transmissions; source "test.urdf".
description::RobotModel make_robot(std::vector<description::Joint> joints);

// An XML element with attributes, e.g. xml("joint", {{"name", "j1"}}, 12).
description::XmlNode xml(const std::string& name, std::vector<std::pair<std::string, std::string>> attributes = {},
                         int line = 0, std::string text = "");

// <transmission><type>transmission_interface/SimpleTransmission</type><joint name=J>
// <hardwareInterface>HW</hardwareInterface></joint><actuator name=A><mechanicalReduction>N...
description::Transmission ros_simple(const std::string& name, const std::string& joint, const std::string& actuator,
                                     std::optional<double> reduction, const std::string& hw = "EffortJointInterface",
                                     int line = 0);

// <transmission type="pr2_mechanism_model/SimpleTransmission"> with a top-level reduction.
description::Transmission pr2_simple(const std::string& name, const std::string& joint, const std::string& actuator,
                                     std::optional<double> reduction, int line = 0);

// Sum over the joints with the given role of effort * velocity (measured effort when `measured`,
// commanded effort otherwise), and the same over the actuators.
double joint_power(const MechanismModel& model, const MechanismState& state, bool measured,
                   JointRole role = JointRole::Actuated);
double actuator_power(const MechanismState& state, bool measured);

}  // namespace mechsim::mechanism::test

namespace mechsim::mechanism::test {

// Fills the actuated joints' state and commands with distinct values (from `seed`), then
// checks joint -> actuator -> joint for state and commands; returns the largest difference.
double joint_round_trip_error(const MechanismModel& model, MechanismState& state, double seed);
// The same from the actuator side: actuator -> joint -> actuator.
double actuator_round_trip_error(const MechanismModel& model, MechanismState& state, double seed);

}  // namespace mechsim::mechanism::test
