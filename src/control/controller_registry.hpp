#pragma once
// Maps the controller type names users have in their YAML ("effort_controllers/
// JointPositionController") to implementations. A plain object, owned by each controller
// manager: no global registry.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "control/controller.hpp"

namespace mechsim::control {

using ControllerFactory = std::function<std::unique_ptr<Controller>()>;

class ControllerRegistry {
 public:
  // Adds or replaces a type.
  void add(const std::string& type, ControllerFactory factory);
  bool has(const std::string& type) const { return factories_.count(type) != 0; }
  // Null for an unknown type.
  std::unique_ptr<Controller> create(const std::string& type) const;
  std::vector<std::string> types() const;  // sorted

 private:
  std::map<std::string, ControllerFactory> factories_;
};

// Adds mechsim's built-in controller types (control/builtin_controllers.cpp).
void register_builtin_controllers(ControllerRegistry& registry);

}  // namespace mechsim::control
