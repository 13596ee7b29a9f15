// `mechsim check` (being written).
#include "apps/commands.hpp"

namespace mechsim::apps {

void add_check_command(CLI::App& app, CommandResult& /*result*/) {
  CLI::App* cmd = app.add_subcommand("check", "(not yet available)");
  cmd->callback([] { throw UserError("'check' is not implemented yet"); });
}

}  // namespace mechsim::apps
