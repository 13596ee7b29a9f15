#pragma once
// Number parameters every controller family checks the same way: a value at `key` that must be
// finite and > 0, or finite and >= 0; absent, `fallback` as it is (0 may mean "from the URDF",
// infinity "no limit"). A value given but out of range is a ControllerConfigError
// naming the parameter's full path and the value ("parameter /cc8/x/k must be finite and > 0
// (got -1.000000)").

#include "control/params.hpp"

namespace mechsim::control {

double positive_param(const Params& params, const char* key, double fallback);
double non_negative_param(const Params& params, const char* key, double fallback);

}  // namespace mechsim::control
