#pragma once
// Internal to control/: Params from one node of a YAML document parsed elsewhere, keeping the
// document's file and lines (ros2_params.cpp: ROS 2 parameter files, whose node names hold '/',
// which a Params key may not, so their top levels are walked in yaml-cpp).

#include <yaml-cpp/yaml.h>

#include <string>

#include "control/params.hpp"

namespace mechsim::control {

// The file's YAML document. Throws ParamsError naming the file (and the line of a syntax error).
YAML::Node load_yaml_file(const std::string& file_path);
YAML::Node load_yaml_string(const std::string& yaml, const std::string& source_name);

// `node` (a map) as a Params tree of its own (root path "/"), lines from `source`. Throws
// ParamsError as Params::from_yaml_file does (a key with '/', duplicate keys, not UTF-8).
Params params_from_yaml_map(const YAML::Node& node, const std::string& source);

// "source:line:column" of a mark.
std::string yaml_where(const std::string& source, const YAML::Mark& mark);

}  // namespace mechsim::control
