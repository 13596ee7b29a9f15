// `mechsim check FILE [name:=value ...] [--package NAME=DIR ...] [--lenient]`: expands (when the
// file is xacro), parses and validates a robot description and prints a summary, like ROS's
// check_urdf. Problems go to stderr through main's error path (exit status 1); warnings go to
// stderr with exit status 0.
//
// The command is a list of steps over one CheckContext: options are gathered in CheckOptions,
// the robot is loaded once, then each check of the loaded robot runs in turn. A further check
// (e.g. `--controllers FILE.yaml`) adds its option in add_check_command and a step in run_check.
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "description/robot_loader.hpp"
#include "description/robot_summary.hpp"

namespace mechsim::apps {

namespace {

struct CheckOptions {
  std::string file;
  std::vector<std::string> mappings;  // name:=value
  std::vector<std::string> packages;  // NAME=DIR
  bool lenient = false;
};

struct CheckContext {
  description::LoadedRobot robot;
  std::vector<std::string> warnings;  // from every step, printed at the end
};

std::map<std::string, std::string> parse_mappings(const std::vector<std::string>& mappings) {
  std::map<std::string, std::string> out;
  for (const std::string& m : mappings) {
    const std::size_t sep = m.find(":=");
    if (sep == std::string::npos || sep == 0)
      throw UserError("argument '" + m + "' is not a name:=value mapping");
    out[m.substr(0, sep)] = m.substr(sep + 2);
  }
  return out;
}

description::PackageMap parse_packages(const std::vector<std::string>& packages) {
  description::PackageMap out;
  for (const std::string& p : packages) {
    const std::size_t sep = p.find('=');
    if (sep == std::string::npos || sep == 0 || sep + 1 == p.size())
      throw UserError("--package '" + p + "' is not NAME=DIR");
    // Absolute, so that includes resolve the same from every file that names the package.
    out[p.substr(0, sep)] = std::filesystem::absolute(p.substr(sep + 1)).lexically_normal().string();
  }
  return out;
}

void load_step(const CheckOptions& options, CheckContext& context) {
  description::LoadOptions load;
  load.xacro_args = parse_mappings(options.mappings);
  load.packages = parse_packages(options.packages);
  load.lenient = options.lenient;
  context.robot = description::load_robot(options.file, load);
  context.warnings.insert(context.warnings.end(), context.robot.warnings.begin(),
                          context.robot.warnings.end());
}

void summary_step(const CheckContext& context, std::ostream& out) {
  out << description::summarize_robot(context.robot.model);
}

void run_check(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  CheckContext context;
  load_step(options, context);
  summary_step(context, out);
  for (const std::string& w : context.warnings) err << "warning: " << w << "\n";
  out << "OK: " << options.file << " is a valid robot description";
  if (!context.warnings.empty()) out << " (" << context.warnings.size() << " warnings)";
  out << "\n";
}

}  // namespace

void add_check_command(CLI::App& app, CommandResult& /*result*/) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check", "Expand (if xacro), parse and validate a robot description; print a summary");
  cmd->add_option("file", options->file, "URDF or xacro file")->required();
  cmd->add_option("mappings", options->mappings, "xacro arguments, name:=value");
  cmd->add_option("--package", options->packages,
                  "NAME=DIR: where package NAME is (for $(find NAME) and package://NAME)")
      ->allow_extra_args(false);
  cmd->add_flag("--lenient", options->lenient,
                "report physical-plausibility problems (mass, inertia, limits) as warnings");
  cmd->callback([options] { run_check(*options, std::cout, std::cerr); });
}

}  // namespace mechsim::apps
