#pragma once
// mechsim_node's private parameters (~name): the one list the node reads, documents
// (`mechsim_node --params`) and reports at start. Launch files set every one of them (and clear
// the node's namespace: clear_params="true"), so that parameters left on the server by an earlier
// launch, e.g. a PR2's robot_namespace, never reach a later one; a node started by hand says which
// it took from the server and warns about any it does not know.

#include <string>
#include <vector>

#include <ros/ros.h>

#include "description/robot_model.hpp"

namespace mechsim::ros {

struct PrivateParam {
  const char* name;
  const char* type;           // "string", "bool", "double", "map"
  const char* default_value;  // as text
  const char* meaning;
};

const std::vector<PrivateParam>& private_params();

// "name<TAB>type<TAB>default<TAB>meaning" lines, for --params.
std::string describe_private_params();

// Logs (INFO) each parameter of the list that is set under `pnh` with its value, and warns about
// each name under `pnh` that is not in the list (stale from another node, or misspelt).
void report_private_params(const ::ros::NodeHandle& pnh);

// Applies ~camera_overrides (description/camera_override.hpp) to `robot` and logs each camera
// changed. Throws std::runtime_error naming the parameter for a malformed value, an unknown
// camera or an impossible rate/size.
void apply_camera_overrides_param(const ::ros::NodeHandle& pnh, description::RobotModel& robot);

}  // namespace mechsim::ros
