#pragma once
// Maps the controller type names users have in their YAML ("effort_controllers/
// JointPositionController") to implementations. A plain object, owned by each controller
// manager: no global registry. The core names no controller type: whoever builds a manager
// fills its registry (mechsim's families: controllers/builtin_controllers.hpp).

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

}  // namespace mechsim::control
