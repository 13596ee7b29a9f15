#include "control/controller_params.hpp"

#include <algorithm>

namespace mechsim::control {

std::string read_joint_name(const Params& params) {
  const std::string path = join_param_path(params.path(), "joint");
  if (!params.has("joint")) throw ControllerConfigError("no joint given: parameter " + path + " not found");
  std::string joint = params.get<std::string>("joint");
  if (joint.empty()) throw ControllerConfigError("parameter " + path + " is empty");
  return joint;
}

std::vector<std::string> read_joint_names(const Params& params) {
  const std::string path = join_param_path(params.path(), "joints");
  if (!params.has("joints")) throw ControllerConfigError("no joints given: parameter " + path + " not found");
  auto joints = params.get<std::vector<std::string>>("joints");
  if (joints.empty()) throw ControllerConfigError("parameter " + path + ": the list of joint names is empty");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].empty()) throw ControllerConfigError("parameter " + path + "[" + std::to_string(i) + "] is empty");
    if (std::count(joints.begin(), joints.end(), joints[i]) > 1) {
      throw ControllerConfigError("parameter " + path + ": joint '" + joints[i] + "' is listed twice");
    }
  }
  return joints;
}

}  // namespace mechsim::control
