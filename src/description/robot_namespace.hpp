#pragma once
// What gazebo_ros' spawn services do to a model's XML before Gazebo reads it: every <plugin> that
// names no <robotNamespace> gets the spawn's robot_namespace (gazebo_ros_api_plugin's
// walkChildAddRobotNamespace), so that two robots spawned from one description under two
// namespaces publish and subscribe under their own.

#include <string>

namespace mechsim::description {

// `xml`: a URDF (<robot>) or SDF (<sdf>) document. Returns it with the namespace added to every
// <plugin> element at any depth that has no <robotNamespace> child; unchanged when `robot_namespace`
// is empty or the document is neither (the reader then says what is wrong with it). Throws
// nothing.
std::string with_robot_namespace(const std::string& xml, const std::string& robot_namespace);

}  // namespace mechsim::description
