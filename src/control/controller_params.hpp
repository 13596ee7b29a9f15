#pragma once
// Reading the parameters every joint controller shares (`joint`, `joints`), with errors that
// name the parameter path.

#include <string>
#include <vector>

#include "control/hardware.hpp"
#include "control/params.hpp"

namespace mechsim::control {

// The `joint` parameter: a non-empty string. Throws ControllerConfigError / ParamsError.
std::string read_joint_name(const Params& params);
// The `joints` parameter: a non-empty list of distinct joint names.
std::vector<std::string> read_joint_names(const Params& params);

}  // namespace mechsim::control
