// `mechsim xacro FILE [name:=value ...] [-o OUT] [--package NAME=DIR ...]`: a drop-in for ROS's
// `xacro FILE name:=value ...` (in-order processing).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "apps/commands.hpp"
#include "description/xacro/xacro.hpp"

namespace mechsim::apps {

namespace {
struct XacroArgs {
  std::string input;
  std::vector<std::string> mappings;
  std::string output;
  std::vector<std::string> packages;
  bool inorder = false;
};
}  // namespace

void add_xacro_command(CLI::App& app, CommandResult& /*result*/) {
  add_xacro_options(*app.add_subcommand("xacro", "Expand a xacro file to URDF (like ROS's `xacro`)"));
}

void add_xacro_options(CLI::App& app) {
  auto args = std::make_shared<XacroArgs>();
  CLI::App* cmd = &app;
  cmd->add_option("file", args->input, "The xacro file")->required();
  cmd->add_option("mappings", args->mappings, "Substitution args as name:=value");
  cmd->add_option("-o,--output", args->output, "Write the result to this file instead of stdout");
  cmd->add_option("--package", args->packages, "Locate package NAME at DIR (NAME=DIR), before ROS_PACKAGE_PATH");
  cmd->add_flag("-i,--inorder", args->inorder, "Accepted for compatibility; processing is always in order");
  cmd->callback([args] {
    description::XacroOptions options;
    for (const std::string& m : args->mappings) {
      const auto pos = m.find(":=");
      if (pos == std::string::npos || pos == 0) {
        throw UserError("expected a mapping name:=value, got '" + m + "'");
      }
      options.args[m.substr(0, pos)] = m.substr(pos + 2);
    }
    for (const std::string& p : args->packages) {
      const auto pos = p.find('=');
      if (pos == std::string::npos || pos == 0) throw UserError("--package expects NAME=DIR, got '" + p + "'");
      options.packages[p.substr(0, pos)] = p.substr(pos + 1);
    }
    const std::string text = description::expand_xacro_file(args->input, options);
    if (args->output.empty()) {
      // xacro prints the document and then an empty line on stdout; with -o it writes the document only.
      std::cout << text << '\n';
      std::cout.flush();
      return;
    }
    const std::filesystem::path out_path(args->output);
    std::error_code ec;
    if (out_path.has_parent_path()) std::filesystem::create_directories(out_path.parent_path(), ec);
    std::ofstream out(out_path, std::ios::binary);
    if (!out) throw UserError("cannot open output file '" + args->output + "'");
    out << text;
    if (!out) throw UserError("failed writing output file '" + args->output + "'");
  });
}

}  // namespace mechsim::apps
