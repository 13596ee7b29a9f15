// `mechsim xacro` (being written).
#include "apps/commands.hpp"

namespace mechsim::apps {

void add_xacro_command(CLI::App& app, CommandResult& /*result*/) {
  CLI::App* cmd = app.add_subcommand("xacro", "(not yet available)");
  cmd->callback([] { throw UserError("'xacro' is not implemented yet"); });
}

}  // namespace mechsim::apps
