#pragma once
// Parameter server values -> control::Params: what the controller manager reads at load time.

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

#include "control/params.hpp"

namespace mechsim::ros {

// Copies `value` into `target` under `key` (nested structs become maps; arrays of numbers become
// lists of doubles, arrays of strings lists of strings). Ints stay ints. Returns false with
// `warning` set for what Params cannot hold (arrays of structs, binary, dates); the rest is kept.
bool set_param_from_xmlrpc(control::Params& target, const std::string& key, const XmlRpc::XmlRpcValue& value,
                           std::string* warning);

// Replaces what `target` holds for each key of the struct `value` (a whole namespace).
bool fill_params_from_xmlrpc(control::Params& target, const XmlRpc::XmlRpcValue& value, std::string* warning);

}  // namespace mechsim::ros
