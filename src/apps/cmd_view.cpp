// `mechsim view DIR [--port P] [--export page.html]`: replays a scenario report in 3D in a
// browser. Serves the replay page (built from web/ by the build) and the report's replay/ folder
// on 127.0.0.1 and prints the address; --export writes one self-contained HTML file instead.

#include <filesystem>
#include <iostream>

#include "apps/commands.hpp"
#include "apps/stop_on_signals.hpp"
#include "web/page_export.hpp"
#include "web/replay_folder.hpp"
#include "web/view_server.hpp"

namespace mechsim::apps {
namespace {

namespace fs = std::filesystem;

struct ViewArgs {
  std::string report;
  unsigned short port = 8765;
  std::string export_file;
  std::string page_dir = MECHSIM_WEB_PAGE_DIR;
};

void view(const ViewArgs& args) {
  const web::ReplayFolder folder = web::check_replay_folder(args.report);
  if (!folder.ok) throw UserError(folder.error);
  const fs::path page = args.page_dir;
  if (!fs::exists(page / "index.html") || !fs::exists(page / "app.js")) {
    throw UserError("the replay page is not built (no index.html and app.js in " + page.string() +
                    "): install node and npm (scripts/install-deps.sh runs npm ci in web/) and build again, "
                    "or point --page-dir at a built page");
  }
  if (!args.export_file.empty()) {
    web::export_page(folder, page, args.export_file);
    std::cout << "wrote " << args.export_file << " (" << fs::file_size(args.export_file) / 1024 << " KiB; opens offline)\n";
    return;
  }
  web::ViewServer server(args.report, page, args.port);
  const StopOnSignals stop_on_signals;
  std::cout << "mechsim view: replay of '" << folder.scenario << "' at http://127.0.0.1:" << server.port()
            << "/ (Ctrl-C stops)\n"
            << std::flush;
  server.run(g_stop_signal);
}

}  // namespace

void add_view_command(CLI::App& app, CommandResult&) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand("view", "Replay a scenario report in 3D in a browser (serves it on 127.0.0.1)");
  cmd->add_option("REPORT", args->report, "the report folder of `mechsim run` (or of a sweep point)")->required();
  cmd->add_option("--port", args->port, "TCP port on 127.0.0.1 (0: any free port)")->capture_default_str();
  cmd->add_option("--export", args->export_file, "write one self-contained HTML file instead of serving");
  cmd->add_option("--page-dir", args->page_dir, "the built replay page (index.html, app.js)")->capture_default_str();
  cmd->callback([args] { view(*args); });
}

}  // namespace mechsim::apps
