// mechsim: the command-line entry point. Exit status: 0 success, 1 user error, never a crash.

#include <exception>
#include <iostream>

#include "apps/commands.hpp"

int main(int argc, char** argv) {
  using namespace mechsim::apps;
  CLI::App app{"mechsim: a MuJoCo-based simulator for ros_control robots described in xacro/URDF"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mechsim 0.1.0");
  CommandResult result;
  add_xacro_command(app, result);
  add_check_command(app, result);
  add_world_command(app, result);
  add_run_command(app, result);
  add_tune_command(app, result);
  add_spawner_command(app, result);
  add_bench_command(app, result);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::string command = "mechsim";
    for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
    std::cerr << command << ": error: " << e.what() << "\n";
    return 1;
  }
  return result.exit_code;
}
