#pragma once
// Each `mechsim` subcommand lives in its own cmd_<name>.cpp and registers itself here.
// A command reports a user error by throwing UserError (or any std::exception): main prints
// "mechsim <command>: error: <message>" on stderr and exits with status 1.

#include <CLI/CLI.hpp>
#include <stdexcept>

namespace mechsim::apps {

struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Exit status a command wants when it did not throw (e.g. `check` found errors: 1).
struct CommandResult {
  int exit_code = 0;
};

void add_xacro_command(CLI::App& app, CommandResult& result);
// The xacro command's arguments and action on `app` itself: the lean `xacro` program's top level.
void add_xacro_options(CLI::App& app);
void add_check_command(CLI::App& app, CommandResult& result);
void add_world_command(CLI::App& app, CommandResult& result);
void add_soil_command(CLI::App& app, CommandResult& result);
void add_run_command(CLI::App& app, CommandResult& result);
void add_render_command(CLI::App& app, CommandResult& result);
void add_tune_command(CLI::App& app, CommandResult& result);
void add_spawner_command(CLI::App& app, CommandResult& result);  // ROS builds: mechsim_spawner
void add_bench_command(CLI::App& app, CommandResult& result);
void add_sweep_command(CLI::App& app, CommandResult& result);
void add_view_command(CLI::App& app, CommandResult& result);
void add_ros2_command(CLI::App& app, CommandResult& result);  // ROS 2 builds: src/ros2

}  // namespace mechsim::apps
