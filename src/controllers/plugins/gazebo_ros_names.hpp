#pragma once
// The names gazebo_plugins' GazeboRos helper (gazebo_ros_utils.h) gives the model plugins built on
// it: the diff drive, the tricycle drive and the joint state publisher.
//
//   namespace: <robotNamespace>; an empty one means the model's name. Without the element Gazebo
//     takes the model's name too, but a model spawned through gazebo_ros with a robot_namespace
//     has the element (walkChildAddRobotNamespace), spawn_model's default being its own namespace,
//     "/" at the root: mechsim_node's own robot stands where spawn_model at the root puts it, so a
//     plugin without the element is at the root here, and where Gazebo loads a model without a
//     spawn namespace (an SDF world's models, a spawn with an empty robot_namespace) the element is
//     written in first (model_plugins.hpp: add_model_name_namespaces).
//   TF prefix: the namespace without trailing '/' (gazebo_plugins reads a tf_prefix parameter
//     first; mechsim does not): "/r1" and "r1" give "r1/odom", "/" and the root none.
//   frame(name) is tf::resolve(prefix, name): a name with a leading '/' loses it and takes no
//     prefix; else "<prefix without its leading '/'>/<name>", or the name alone without a prefix.

#include <string>

#include "controllers/plugins/plugin_params.hpp"

namespace mechsim::control {

struct GazeboRosNames {
  std::string robot_namespace;  // "" for the root
  std::string tf_prefix;        // "" for none
  std::string frame(const std::string& name) const;
};

GazeboRosNames gazebo_ros_names(const PluginParams& params, const std::string& model_name);

// tf::resolve(prefix, name) as above.
std::string tf_resolve(const std::string& prefix, const std::string& name);

}  // namespace mechsim::control
