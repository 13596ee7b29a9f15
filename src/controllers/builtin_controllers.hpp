#pragma once
// The controller library's entry point: the types of every family under controllers/ (joint/,
// trajectory/, drive/, gripper/, pr2/), by the names users have in their YAML. Whoever builds a
// controller manager (sim/, apps/, tests) hands it these; the control core names none of them.

#include "control/controller_registry.hpp"

namespace mechsim::control {

// Adds mechsim's built-in controller types to `registry` (replacing same-named ones).
void register_builtin_controllers(ControllerRegistry& registry);
// A registry holding exactly the built-in types.
ControllerRegistry builtin_controller_registry();

}  // namespace mechsim::control
