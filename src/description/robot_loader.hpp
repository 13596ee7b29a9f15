#pragma once
// One call from a description file to a RobotModel: .xacro files (and any file holding xacro
// elements) are expanded first, then parsed and validated.

#include <map>
#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "description/xacro/xacro.hpp"

namespace mechsim::description {

struct LoadOptions {
  std::map<std::string, std::string> xacro_args;  // name:=value
  PackageMap packages;                             // --package NAME=DIR
  bool lenient = false;
};

struct LoadedRobot {
  RobotModel model;
  std::string urdf;                   // the expanded document
  std::vector<std::string> warnings;
};

// Throws XacroError (expansion) or DescriptionError (parsing/validation).
LoadedRobot load_robot(const std::string& path, const LoadOptions& options);

}  // namespace mechsim::description
