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
  // Null for an unknown type. A factory may throw ControllerConfigError (a plugin library that
  // cannot be loaded, control/controller_plugins.hpp): the manager reports it for the controller.
  std::unique_ptr<Controller> create(const std::string& type) const;
  std::vector<std::string> types() const;  // sorted

  // Problems met while filling the registry (a malformed plugin description, file:line), one
  // line each: an unknown type's error ends with them, since the type may be one they lost.
  void add_note(std::string note) { notes_.push_back(std::move(note)); }
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  std::map<std::string, ControllerFactory> factories_;
  std::vector<std::string> notes_;
};

}  // namespace mechsim::control
