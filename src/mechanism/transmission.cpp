#include "mechanism/transmission.hpp"

#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

Transmission::Transmission(std::string name, std::string type, std::vector<int> joints,
                           std::vector<int> actuators)
    : name_(std::move(name)), type_(std::move(type)), joints_(std::move(joints)), actuators_(std::move(actuators)) {}

HardwareInterface Transmission::common_mode(const MechanismState& state, std::span<const int> actuated) const {
  if (actuated.empty()) return HardwareInterface::Effort;
  const HardwareInterface first = state.joints[actuated[0]].command_mode;
  for (int j : actuated)
    if (state.joints[j].command_mode != first) return HardwareInterface::Effort;
  return first;
}

}  // namespace mechsim::mechanism
