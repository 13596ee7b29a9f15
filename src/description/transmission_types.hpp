#pragma once
// The transmission types mechsim simulates, by the names descriptions give them (ros_control's
// transmission_interface, the PR2's pr2_mechanism_model and its pre-Electric spellings). The
// mechanism layer builds each (mechanism/transmission_factory.cpp; its test checks that both
// lists agree). A lenient parse leaves out a transmission of any other type with a warning
// (urdf_parser.hpp): Gazebo's gazebo_ros_control reads transmissions without instantiating their
// types, so vendor types (franka_hw/FrankaStateInterface, ...) load there.

#include <array>
#include <string_view>

namespace mechsim::description {

inline constexpr std::array<std::string_view, 9> kTransmissionTypes{
    "transmission_interface/SimpleTransmission",
    "pr2_mechanism_model/SimpleTransmission",
    "SimpleTransmission",
    "transmission_interface/DifferentialTransmission",
    "transmission_interface/FourBarLinkageTransmission",
    "pr2_mechanism_model/WristTransmission",
    "WristTransmission",
    "pr2_mechanism_model/PR2GripperTransmission",
    "PR2GripperTransmission",
};

}  // namespace mechsim::description
