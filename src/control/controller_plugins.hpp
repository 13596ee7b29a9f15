#pragma once
// Controller plugins: controller types built outside mechsim as shared libraries against
// include/mechsim/controller_api.hpp, described in pluginlib's controller_plugins.xml form
//
//   <library path="lib/libmy_controllers">
//     <class name="my_pkg/MyController" type="my_pkg::MyController"
//            base_class_type="controller_interface::ControllerBase"/>
//   </library>
//
// (or several <library> inside <class_libraries>) and found, in this order, through
//   - MECHSIM_CONTROLLER_PLUGINS: a ':'-separated list of such files;
//   - every package.xml under ROS_PACKAGE_PATH whose <export> has
//     <controller_interface plugin="${prefix}/controller_plugins.xml"/>, as pluginlib finds them.
// A class is a controller type by its `name` (its `type` when it has no name), the name the
// controllers YAML gives as `type:`. The library's `path` is relative to the folder of its XML
// file (an absolute path as it is), ".so" added when it has no extension; a path that is not
// there is handed to the dynamic loader by its file name (LD_LIBRARY_PATH, the system's folders).
//
// A library is loaded when a controller of one of its types is first created, not when found:
// a broken library stops only the controllers that need it, with a one-line error naming the
// controller type, the library, where it was declared and the loader's reason.

#include <memory>
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "control/controller_registry.hpp"

namespace mechsim::control {

struct ControllerPluginClass {
  std::string name;     // the controller type users write: "my_pkg/MyController"
  std::string type;     // the C++ type the library lists: "my_pkg::MyController"
  std::string library;  // the library file as resolved
  std::string missing;  // the file beside the description that was not there ("" when found)
  std::string origin;   // where it was declared: "/path/controller_plugins.xml:3"
};

struct ControllerPluginSet {
  std::vector<ControllerPluginClass> classes;  // declaration order; a name declared twice counts once
  std::vector<std::string> files;              // the descriptions read
  std::vector<std::string> errors;             // one line each, naming file and line
};

// Reads one plugin description into `set`; problems (unreadable or malformed file, a <class>
// without `type`, a name declared twice) go to set.errors.
void read_controller_plugin_description(const std::string& xml_path, ControllerPluginSet& set);

// Every description MECHSIM_CONTROLLER_PLUGINS and ROS_PACKAGE_PATH's packages name.
ControllerPluginSet find_controller_plugins();

// Loads the class's library (dlopen; kept loaded for the life of the process) and creates one
// controller. Throws ControllerConfigError, one line, for a library that cannot be loaded, has no
// mechsim_controller_library entry point, was built against another controller API version, or
// lacks the class.
std::unique_ptr<Controller> create_plugin_controller(const ControllerPluginClass& plugin);

// Adds each class as a type of `registry` (loaded on first use, see above) and the set's errors as
// the registry's notes. A name the registry already has (a built-in type) is not replaced: a note
// says so.
void register_controller_plugins(ControllerRegistry& registry, const ControllerPluginSet& set);

}  // namespace mechsim::control
