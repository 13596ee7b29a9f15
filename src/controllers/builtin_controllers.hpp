#pragma once
// The controller library's entry point: the types of every family under controllers/ (joint/,
// trajectory/, drive/, gripper/, pr2/), by the names users have in their YAML. Whoever builds a
// controller manager (sim/, apps/, tests) hands it these; the control core names none of them.

#include "control/controller_plugins.hpp"
#include "control/controller_registry.hpp"

namespace mechsim::control {

// Adds mechsim's built-in controller types to `registry` (replacing same-named ones).
void register_builtin_controllers(ControllerRegistry& registry);
// A registry holding exactly the built-in types.
ControllerRegistry builtin_controller_registry();
// The built-in types and then the controller plugins of `plugins` (control/controller_plugins.hpp;
// a plugin never replaces a built-in type). The default, find_controller_plugins(), is what the
// simulation, `mechsim check` and the ROS node load from: MECHSIM_CONTROLLER_PLUGINS and the
// packages of ROS_PACKAGE_PATH, as they are when the registry is made.
ControllerRegistry controller_registry_with_plugins(const ControllerPluginSet& plugins = find_controller_plugins());

}  // namespace mechsim::control
