// `mechsim run SCENARIO.yaml`: runs a scenario headless and writes its report.

#include <unistd.h>

#include <atomic>
#include <csignal>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include "apps/commands.hpp"
#include "apps/stop_on_signals.hpp"
#include "live/live_stream.hpp"
#include "live/scenario_stream.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::apps {
namespace {

struct RunArgs {
  std::string scenario;
  std::string output;
  bool no_plots = false;
  double duration = 0.0;
  std::string integrator;  // empty: the scenario's own
  double timing = 0.0;     // s of simulated time per timing.csv row; 0: no timing
  double real_time_factor = -1.0;  // < 0: not given (1 with --live, else unbounded)
  bool live = false;
  live::ServerOptions server;
  double live_rate = 30.0;  // Hz of /tf, /joint_states and /odom
};

// A one-line progress bar on a terminal; a plain line every 10 % of the run otherwise.
std::function<void(const sim::RunProgress&)> progress_printer() {
  const bool tty = isatty(fileno(stderr)) != 0;
  auto last_decile = std::make_shared<int>(-1);
  return [tty, last_decile](const sim::RunProgress& p) {
    const double fraction = p.duration > 0 ? p.time / p.duration : 1.0;
    if (tty) {
      const int width = 40;
      const int filled = static_cast<int>(fraction * width + 0.5);
      std::fprintf(stderr, "\r[%.*s%*s] %6.1f / %.1f s  real-time factor %.2f ", filled,
                   "########################################", width - filled, "", p.time, p.duration, p.real_time_factor);
      if (fraction >= 1.0) std::fprintf(stderr, "\n");
      std::fflush(stderr);
      return;
    }
    const int decile = static_cast<int>(fraction * 10.0 + 1e-9);
    if (decile != *last_decile) {
      *last_decile = decile;
      std::fprintf(stderr, "t = %.1f / %.1f s, real-time factor %.2f\n", p.time, p.duration, p.real_time_factor);
    }
  };
}

void run(const RunArgs& args, CommandResult& result) {
  sim::Scenario scenario = sim::load_scenario(args.scenario);
  if (args.duration > 0.0) scenario.duration = args.duration;
  if (!args.integrator.empty()) scenario.integrator = *physics::parse_integrator(args.integrator);  // checked by CLI11
  sim::RunOptions options;
  options.output_dir = args.output.empty() ? (std::filesystem::path("out") / scenario.name).string() : args.output;
  options.plots = !args.no_plots;
  options.timing_window = args.timing;
  options.progress = progress_printer();
  // Warnings as they arise (at spawn, before a long run), each printed once.
  auto printed = std::make_shared<std::vector<std::string>>();
  options.warning = [printed](const std::string& text) {
    std::cerr << "warning: " << text << "\n" << std::flush;
    printed->push_back(text);
  };
  std::cout << "scenario " << scenario.name << ": " << scenario.duration << " s of simulated time, "
            << physics::integrator_name(scenario.integrator) << " integrator\n" << std::flush;
  options.interrupt = &g_stop_signal;
  options.real_time_factor = args.real_time_factor >= 0.0 ? args.real_time_factor : (args.live ? 1.0 : 0.0);
  // Live view: listen before anything is built, so that a busy port fails at once.
  std::unique_ptr<live::FoxgloveServer> server;
  std::unique_ptr<live::LiveStream> stream;  // outlives the run's simulation (its observer)
  if (args.live) {
    server = std::make_unique<live::FoxgloveServer>(args.server);
    std::cout << "live: " << live::live_url(*server)
              << " (Foxglove WebSocket protocol: open it in Foxglove Studio or Lichtblick)\n" << std::flush;
    options.on_start = [&](sim::Simulation& sim) {
      live::StreamRates rates;
      rates.tf = rates.joint_states = rates.odometry = args.live_rate;
      stream = std::make_unique<live::LiveStream>(std::move(server), sim, live::scenario_urdf(scenario),
                                                  live::scenario_waypoints(scenario), rates);
    };
  }
  const StopOnSignals stop_on_signals;
  const sim::ScenarioResult r = sim::run_scenario(scenario, options);
  if (stream) {
    stream->stop();
    const live::StreamStats st = stream->stats();
    std::cout << "live: " << st.server.clients_accepted << " clients, " << st.server.messages_sent << " messages sent, "
              << st.server.messages_dropped << " dropped, peak client queue " << st.server.peak_queued_bytes
              << " bytes, snapshots " << st.snapshots_taken << " of " << st.snapshots_published << " taken\n";
  }
  std::cout << "distance " << r.distance << " m, final pose (" << r.final_x << ", " << r.final_y << ") yaw "
            << r.final_yaw * 180.0 / 3.141592653589793 << " deg, real-time factor " << r.real_time_factor << "\n";
  if (!r.completed) std::cout << "did not complete: " << r.error << "\n";
  if (scenario.world.soil) {
    // Which wheels met the soil, and, once, what looks like a wheel but did not.
    std::cout << "soil wheels (" << scenario.world.soil->name << "):";
    for (const sim::WheelOutcome& w : r.wheels) std::cout << " " << w.link << (w.narrow ? " (narrow)" : "");
    std::cout << (r.wheels.empty() ? " none\n" : "\n");
    for (const std::string& n : r.not_wheels) std::cout << "  " << n << "\n";
  }
  for (const sim::CheckOutcome& c : r.checks) std::cout << (c.passed ? "  PASS " : "  FAIL ") << c.detail << "\n";
  for (const std::string& w : r.warnings) {
    if (std::find(printed->begin(), printed->end(), w) == printed->end()) std::cerr << "warning: " << w << "\n";
  }
  std::cout << "report: " << std::filesystem::absolute(options.output_dir).lexically_normal().string() << "/summary.json";
  for (const std::string& f : r.files) {
    if (f.ends_with(".png")) std::cout << ", " << f;
  }
  std::cout << "\n" << (r.passed ? "PASSED" : "FAILED") << "\n";
  // The shell's convention for a process ended by a signal, though this one ended cleanly.
  result.exit_code = r.interrupted_by != 0 ? 128 + r.interrupted_by : (r.passed ? 0 : 1);
}

}  // namespace

void add_run_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Run a scenario headless and write its report (CSV, summary.json, plots)");
  cmd->add_option("scenario", args->scenario, "Scenario file (YAML)")->required();
  cmd->add_option("-o,--output", args->output, "Report folder (default: out/<scenario name>)");
  cmd->add_flag("--no-plots", args->no_plots, "Do not draw PNG plots");
  cmd->add_option("--duration", args->duration, "Override the scenario's duration (s)");
  cmd->add_option("--timing", args->timing,
                  "Write timing.csv: tick time p50/p99/max, CPU time and resident memory per this many s of simulated time")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--integrator", args->integrator, "Override the scenario's integrator: implicit, euler or rk4")
      ->check(CLI::IsMember({"implicit", "euler", "rk4"}));
  cmd->add_option("--real-time-factor", args->real_time_factor,
                  "Pace the run: simulated time runs this many times as fast as wall time (default: as fast as it "
                  "goes; 1 with --live); 0: unbounded")
      ->check(CLI::NonNegativeNumber);
  CLI::Option* live = cmd->add_flag("--live", args->live,
                "Serve the run live over the Foxglove WebSocket protocol (Foxglove Studio, Lichtblick): /tf, "
                "/joint_states, /odom, laser scans, /robot_description, /markers");
  cmd->add_option("--port", args->server.port, "--live: TCP port (default 8765; 0: any free port, printed)")->needs(live);
  cmd->add_option("--live-address", args->server.address,
                  "--live: address to listen on (default 127.0.0.1; 0.0.0.0 for every interface)")
      ->needs(live);
  cmd->add_option("--live-rate", args->live_rate, "--live: Hz of /tf, /joint_states and /odom (default 30)")
      ->check(CLI::PositiveNumber)
      ->needs(live);
  cmd->callback([args, &result] { run(*args, result); });
}

}  // namespace mechsim::apps
