#include "control/controller_registry.hpp"

namespace mechsim::control {

void ControllerRegistry::add(const std::string& type, ControllerFactory factory) {
  factories_[type] = std::move(factory);
}

std::unique_ptr<Controller> ControllerRegistry::create(const std::string& type) const {
  auto it = factories_.find(type);
  if (it == factories_.end()) return nullptr;
  return it->second();
}

std::vector<std::string> ControllerRegistry::types() const {
  std::vector<std::string> out;
  for (const auto& entry : factories_) out.push_back(entry.first);
  return out;
}

}  // namespace mechsim::control
