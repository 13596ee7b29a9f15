// `mechsim render SCENARIO --at T`: runs a scenario (its timeline, none of its checks) to time T and
// writes one frame of every camera of the robot there: cameras/<sensor>[_<camera>]_<T>s.png
// (depth sensors also ..._depth.png) and camera_sheet.png, in the output folder.

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <variant>

#include "apps/commands.hpp"
#include "apps/stop_on_signals.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::apps {
namespace {

struct RenderArgs {
  std::string scenario;
  std::string output;
  double at = 0.0;
};

void render(const RenderArgs& args, CommandResult& result) {
  sim::Scenario scenario = sim::load_scenario(args.scenario);
  // The frame is taken as the run reaches T: the run lasts T (and one period, so that the step
  // that reaches T samples the cameras before the run ends).
  scenario.duration = args.at + scenario.period;
  scenario.camera_picture_times = {args.at};
  scenario.laser_picture_times.clear();
  scenario.checks.clear();
  sim::RunOptions options;
  options.output_dir = args.output.empty() ? (std::filesystem::path("out") / (scenario.name + "_render")).string() : args.output;
  options.plots = false;
  options.warning = [](const std::string& text) { std::cerr << "warning: " << text << "\n" << std::flush; };
  options.interrupt = &g_stop_signal;
  const StopOnSignals stop_on_signals;
  const sim::ScenarioResult r = sim::run_scenario(scenario, options);
  if (r.interrupted_by != 0) {
    result.exit_code = 128 + r.interrupted_by;
    return;
  }
  if (!r.completed) throw UserError("the run did not reach t = " + std::to_string(args.at) + " s: " + r.error);
  int frames = 0;
  for (const std::string& f : r.files) {
    if (f.find("camera") == std::string::npos || !f.ends_with(".png")) continue;
    std::cout << f << "\n";
    ++frames;
  }
  if (frames == 0) {
    std::string why;
    for (const std::string& w : r.warnings) {
      if (w.find("camera") != std::string::npos) why += "\n  " + w;
    }
    throw UserError("no camera frame was written (does the robot have camera sensors? `mechsim check` lists them)" + why);
  }
}

}  // namespace

void add_render_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Run a scenario to a time and write one frame of every camera (PNG)");
  cmd->add_option("scenario", args->scenario, "Scenario file (YAML)")->required();
  cmd->add_option("--at", args->at, "Simulated time of the frame (s)")->required()->check(CLI::NonNegativeNumber);
  cmd->add_option("-o,--output", args->output, "Output folder (default: out/<scenario name>_render)");
  cmd->callback([args, &result] { render(*args, result); });
}

}  // namespace mechsim::apps
