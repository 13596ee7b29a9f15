// `mechsim spawner [ARGS...]`: ros_control's controller spawner. The spawner itself is the ROS
// layer's mechsim_spawner (src/ros/apps/spawner.cpp, built with -DMECHSIM_ROS=ON); this command
// replaces itself with it (exec), passing ARGS unchanged, so that `mechsim` builds without ROS.

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/commands.hpp"

namespace mechsim::apps {

void add_spawner_command(CLI::App& app, CommandResult& /*result*/) {
  CLI::App* cmd = app.add_subcommand(
      "spawner", "Load and start controllers like ros_control's spawner (ROS builds: runs mechsim_spawner)");
  cmd->prefix_command();  // every argument goes to mechsim_spawner
  cmd->callback([cmd] {
    namespace fs = std::filesystem;
    const fs::path exe = fs::canonical("/proc/self/exe").parent_path() / "mechsim_spawner";
    if (!fs::exists(exe)) {
      throw UserError("mechsim_spawner not found at " + exe.string() +
                      " (it is built with the ROS layer: -DMECHSIM_ROS=ON, scripts/install-deps.sh --with-ros)");
    }
    std::vector<std::string> args{exe.string()};
    for (const std::string& a : cmd->remaining()) args.push_back(a);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    throw UserError("cannot run " + exe.string() + ": " + std::strerror(errno));
  });
}

}  // namespace mechsim::apps
