#include "mechanism/hardware_interface.hpp"

namespace mechsim::mechanism {

namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

std::optional<InterfaceName> parse_hardware_interface(std::string_view text) {
  std::string_view s = trim(text);
  constexpr std::string_view prefix = "hardware_interface/";
  if (s.substr(0, prefix.size()) == prefix) s.remove_prefix(prefix.size());
  if (s == "EffortJointInterface" || s == "effort") return InterfaceName::Effort;
  if (s == "PositionJointInterface" || s == "position") return InterfaceName::Position;
  if (s == "VelocityJointInterface" || s == "velocity") return InterfaceName::Velocity;
  if (s == "JointStateInterface") return InterfaceName::StateOnly;
  return std::nullopt;
}

std::optional<HardwareInterface> command_interface(InterfaceName name) {
  switch (name) {
    case InterfaceName::Effort: return HardwareInterface::Effort;
    case InterfaceName::Position: return HardwareInterface::Position;
    case InterfaceName::Velocity: return HardwareInterface::Velocity;
    case InterfaceName::StateOnly: return std::nullopt;
  }
  return std::nullopt;
}

const char* to_string(HardwareInterface hw) {
  switch (hw) {
    case HardwareInterface::Effort: return "effort";
    case HardwareInterface::Position: return "position";
    case HardwareInterface::Velocity: return "velocity";
  }
  return "?";
}

}  // namespace mechsim::mechanism
