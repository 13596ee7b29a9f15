#pragma once
// ROS 2 parameter files (rcl's YAML format) and what ros2_control's controller manager reads from
// them. A file maps node names to their parameters:
//
//   controller_manager:                   # node "/controller_manager"
//     ros__parameters:
//       update_rate: 100                  # Hz
//       arm_controller:
//         type: joint_trajectory_controller/JointTrajectoryController
//   arm_controller:                       # the controller's own node
//     ros__parameters:
//       joints: [joint1, joint2]
//       gains.joint1.p: 10.0              # dotted names are nested maps: gains: {joint1: {p: 10}}
//   /**:                                  # every node
//     ros__parameters: {use_sim_time: true}
//   /my_ns/controller_manager: ...        # a namespaced node; "/**/controller_manager" any namespace
//   my_ns:                                # nested maps before ros__parameters join into the name
//     arm_controller: {ros__parameters: {...}}
//
// Node names follow rclcpp: a name without a leading '/' is in the root namespace; "*" matches
// one name token, "/**" any number of namespace levels. Every entry that matches a node applies,
// in file order (files in the order given): later values win, maps merge key by key.
// Configuration time only: allocates and throws ParamsError naming the file and line.
//
// This header compiles as C++17 (the bridge's header includes it).

#include <string>
#include <vector>

#include "control/params.hpp"

namespace mechsim::control {

// One node entry of a file: the name as written (normalised with a leading '/') and its
// ros__parameters, dotted names expanded into maps.
struct Ros2NodeEntry {
  std::string pattern;  // "/controller_manager", "/**/arm_controller", "/my_ns/*"
  Params parameters;    // a tree of its own, path "/", nodes keep the file's lines
  std::string source;   // "file:line" of the ros__parameters key
};

class Ros2ParameterSet {
 public:
  Ros2ParameterSet() = default;
  // Throws ParamsError naming the file and line: unreadable or malformed YAML; a top level that
  // is not a map; a node name whose value is not a map (rcl: "cannot have a value before
  // ros__parameters"); ros__parameters that is not a map; a file without any ros__parameters.
  static Ros2ParameterSet from_files(const std::vector<std::string>& files);
  void add_file(const std::string& path);
  void add_yaml(const std::string& yaml, const std::string& source_name);

  bool empty() const { return entries_.empty(); }
  const std::vector<std::string>& sources() const { return sources_; }  // files, in the order added
  const std::vector<Ros2NodeEntry>& entries() const { return entries_; }

  // The parameters of node `fqn` ("/controller_manager", "/my_ns/arm_controller"): every
  // matching entry merged in order. An empty map when none matches. Each call builds a new tree
  // (path "/", each node's file and line kept for messages).
  Params parameters_for(const std::string& fqn) const;
  bool has_node(const std::string& fqn) const;  // some entry matches it

 private:
  std::vector<std::string> sources_;
  std::vector<Ros2NodeEntry> entries_;
};

// Whether `pattern` (an entry's node name) matches the fully qualified node name `fqn`.
bool ros2_node_name_matches(const std::string& pattern, const std::string& fqn);

// Whether the YAML file holds a "ros__parameters" key (ROS 2's format) in its first levels of
// maps. False for unreadable files (from_files reports those).
bool is_ros2_parameter_file(const std::string& path);

// What ros2_control's controller manager (node `controller_manager_fqn`) is configured with.
struct Ros2ControlSetup {
  std::string controller_manager;  // its fully qualified node name
  std::string node_namespace;      // its namespace ("/" or "/ns"): its controllers' namespace
  // update_rate (Hz): the manager's and, unless they set their own, its controllers' rate.
  // ros2_control's default 100 when not set.
  double update_rate = 100.0;
  bool update_rate_given = false;
  // One child per controller the manager declares (`<name>: {type: ...}` in its parameters): the
  // type, then that controller node's own parameters (node_namespace/<name>) merged over it; and
  // one per node in its namespace whose own parameters give a `type` (Jazzy's spawner reads the
  // type there).
  // ControllerManager loads from it (its path "/", "/<name>/type", ...).
  Params controllers;
  std::vector<std::string> controller_names;  // in the order declared
  std::vector<std::string> notes;             // warnings: an undeclared controller's parameters, ...
};

// Throws ParamsError (file:line) for an update_rate that is not a positive number, or a
// controller whose type is not a string. A manager the set does not mention gets the defaults
// and no controllers (a note says so).
Ros2ControlSetup ros2_control_setup(const Ros2ParameterSet& set, const std::string& controller_manager_fqn);

}  // namespace mechsim::control
