#pragma once
// Finding ROS packages by name, as `$(find pkg)` and `package://pkg/...` need: first the explicit
// NAME=DIR map (the CLI's --package), then every directory under ROS_PACKAGE_PATH holding a
// package.xml whose <name> is NAME (or, lacking one, a directory so named).

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mechsim::description {

using PackageMap = std::map<std::string, std::string>;

// The package's directory, or nullopt when it cannot be found.
std::optional<std::string> find_package(const std::string& name, const PackageMap& explicit_packages);

// Resolves `package://pkg/rel` and `file://abs` URIs and plain paths (relative ones against
// `base_dir`). Returns nullopt when the package is unknown.
std::optional<std::string> resolve_uri(const std::string& uri, const PackageMap& explicit_packages,
                                       const std::string& base_dir);

// gazebo_ros' exports: the `attribute` (gazebo_model_path, gazebo_media_path, gazebo_plugin_path)
// of the <gazebo_ros> element in the <export> of every package.xml under ROS_PACKAGE_PATH, with
// ${prefix} replaced by the package's folder, as `rospack plugins --attrib=ATTRIBUTE gazebo_ros`
// gives them to gazebo_ros' launch scripts (which add them to GAZEBO_MODEL_PATH and
// GAZEBO_RESOURCE_PATH). ROS_PACKAGE_PATH order, then the order its folders are crawled in; a
// package found twice counts once. rospack lists only packages that depend on gazebo_ros; mechsim
// takes every package that exports the attribute.
std::vector<std::string> gazebo_ros_exports(const std::string& attribute);

// The same for any exporting element: `attribute` of every <element> in the <export> of every
// package.xml under ROS_PACKAGE_PATH, ${prefix} replaced, in the same order. Controller plugin
// descriptions are ("controller_interface", "plugin"), as pluginlib finds them.
std::vector<std::string> package_exports(const std::string& element, const std::string& attribute);

}  // namespace mechsim::description
