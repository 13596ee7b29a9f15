#pragma once
// The joint hardware interfaces a <hardwareInterface> element names.

#include <optional>
#include <string>
#include <string_view>

#include "mechanism/joint_state.hpp"

namespace mechsim::mechanism {

enum class InterfaceName : std::uint8_t { Effort, Position, Velocity, StateOnly };

// Accepts the ros_control names with or without the "hardware_interface/" prefix
// (EffortJointInterface, PositionJointInterface, VelocityJointInterface, JointStateInterface)
// and the ros2_control short forms ("effort", "position", "velocity"). nullopt otherwise.
// Surrounding blanks are ignored.
std::optional<InterfaceName> parse_hardware_interface(std::string_view text);

// The command interface an InterfaceName gives; nullopt for JointStateInterface (read only).
std::optional<HardwareInterface> command_interface(InterfaceName name);

const char* to_string(HardwareInterface hw);  // "effort", "position", "velocity"

}  // namespace mechsim::mechanism
