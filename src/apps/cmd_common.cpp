#include "apps/cmd_common.hpp"

#include <filesystem>

#include "apps/commands.hpp"

namespace mechsim::apps {

void add_robot_options(CLI::App* cmd, RobotArgs& args) {
  cmd->add_option("file", args.file, "Robot description (URDF or xacro)")->required();
  cmd->add_option("mappings", args.mappings, "xacro arguments, name:=value");
  cmd->add_option("--package", args.packages, "NAME=DIR: where package NAME is (for $(find NAME) and package://NAME)")
      ->allow_extra_args(false);
  cmd->add_flag("--lenient", args.lenient,
                "report physical-plausibility problems (mass, inertia, limits) as warnings");
}

description::LoadOptions load_options(const RobotArgs& args) {
  description::LoadOptions load;
  load.lenient = args.lenient;
  for (const std::string& m : args.mappings) {
    const std::size_t sep = m.find(":=");
    if (sep == std::string::npos || sep == 0) throw UserError("argument '" + m + "' is not a name:=value mapping");
    load.xacro_args[m.substr(0, sep)] = m.substr(sep + 2);
  }
  for (const std::string& p : args.packages) {
    const std::size_t sep = p.find('=');
    if (sep == std::string::npos || sep == 0 || sep + 1 == p.size()) {
      throw UserError("--package '" + p + "' is not NAME=DIR");
    }
    // Absolute, so that includes resolve the same from every file that names the package.
    load.packages[p.substr(0, sep)] = std::filesystem::absolute(p.substr(sep + 1)).lexically_normal().string();
  }
  return load;
}

control::Params controller_namespace(const std::string& yaml_file, const std::string& ns) {
  control::Params root = control::Params::from_yaml_file(yaml_file);
  if (!ns.empty()) return root.child(ns);
  const std::vector<std::string> keys = root.keys();
  if (keys.size() == 1 && root.child(keys[0]).is_map() && !root.child(keys[0]).has("type")) return root.child(keys[0]);
  return root;
}

}  // namespace mechsim::apps
