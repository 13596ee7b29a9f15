#pragma once
// What several subcommands share: the robot description arguments (FILE, name:=value mappings,
// --package NAME=DIR, --lenient) and the controllers YAML namespace rule.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "control/params.hpp"
#include "description/robot_loader.hpp"

namespace mechsim::apps {

struct RobotArgs {
  std::string file;
  std::vector<std::string> mappings;  // name:=value
  std::vector<std::string> packages;  // NAME=DIR
  bool lenient = false;
};

// Adds the positional robot FILE and mappings, --package and --lenient to `cmd`.
void add_robot_options(CLI::App* cmd, RobotArgs& args);
// Throws UserError naming a malformed mapping or --package.
description::LoadOptions load_options(const RobotArgs& args);

// The controllers of a YAML: under `ns` when given, else under the file's single top-level map
// when that map is not itself a controller (the `cc8:` of a ros_control YAML), else the root.
control::Params controller_namespace(const std::string& yaml_file, const std::string& ns);

}  // namespace mechsim::apps
