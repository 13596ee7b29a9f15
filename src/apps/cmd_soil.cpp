// `mechsim soil`: soils for the wheel-soil model (physics/terramechanics.hpp).
//   mechsim soil fit TESTS.yaml [-o DIR] [--name NAME] [--base SOIL] [--model ding|wong_reece]
//                    [--method two_stage|direct] [--no-plots]
// fits a soil's constants to plate-sinkage (and shear) tests (sim/soil_fit_report.hpp says what
// TESTS.yaml holds) and writes DIR/<name>.soil.yaml, which a scenario's world.soil or `mechsim
// bench --soil` can name, with the fit's residuals (plate_fit.tsv) and plot (plate_fit.png).
//   mechsim soil show SOIL
// prints a named soil or a soil file as the simulation reads it.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "physics/soil.hpp"
#include "sim/soil_config.hpp"
#include "sim/soil_fit_report.hpp"

namespace mechsim::apps {
namespace {

struct FitArgs {
  std::string tests, output = "soil_fit", name, base, model, method;
  bool no_plots = false;
};

void fit(const FitArgs& args) {
  sim::SoilFitSpec spec = sim::read_soil_fit_spec(args.tests);
  if (!args.name.empty()) spec.name = args.name;
  if (!args.base.empty()) {
    spec.base = args.base;
    spec.start = sim::soil_by_name(args.base);
    if (!spec.given.empty())
      std::cerr << "mechsim soil fit: warning: --base replaces the description's base; its values (" << spec.given.size()
                << " keys) are not laid over it\n";
    spec.given.clear();
  }
  if (!args.model.empty()) spec.model = *physics::find_model(args.model);
  if (args.method == "direct") spec.method = physics::PlateFitMethod::Direct;
  if (args.method == "two_stage") spec.method = physics::PlateFitMethod::TwoStage;
  const sim::SoilFitOutcome out = sim::run_soil_fit(spec, args.output, !args.no_plots);
  std::cout << out.summary;
  for (const std::string& w : out.warnings) std::cerr << "mechsim soil fit: warning: " << w << "\n";
  for (const std::string& f : out.files) std::cout << "wrote " << (std::filesystem::path(args.output) / f).string() << "\n";
}

void show(const std::string& name) {
  const physics::SoilParameters s = sim::soil_by_name(name);
  std::cout << sim::soil_yaml(s);
}

}  // namespace

void add_soil_command(CLI::App& app, CommandResult& /*result*/) {
  CLI::App* soil = app.add_subcommand("soil", "Soils for the wheel-soil model: fit one to plate-sinkage tests, show one");
  soil->require_subcommand(1);
  auto args = std::make_shared<FitArgs>();
  CLI::App* fit_cmd = soil->add_subcommand(
      "fit", "Fit a soil's constants (n, k_c, k_phi; c, phi, K) to plate-sinkage and shear tests; write a soil file");
  fit_cmd->add_option("TESTS", args->tests, "the tests: a YAML file naming the test files and plates (see docs/soil.md)")
      ->required()
      ->check(CLI::ExistingFile);
  fit_cmd->add_option("-o,--output", args->output, "folder for <name>.soil.yaml, plate_fit.tsv and plate_fit.png (default soil_fit)");
  fit_cmd->add_option("--name", args->name, "the soil's name (default: the tests file's name)");
  fit_cmd->add_option("--base", args->base, "named soil or soil file for what the tests do not give (default: the tests file's, else dry_sand)");
  fit_cmd->add_option("--model", args->model, "the wheel-soil model the soil uses")->check(CLI::IsMember({"ding", "wong_reece"}));
  fit_cmd->add_option("--method", args->method, "plate fit: two_stage (one K per plate size, then the line) or direct")
      ->check(CLI::IsMember({"two_stage", "direct"}));
  fit_cmd->add_flag("--no-plots", args->no_plots, "write no plot (no gnuplot needed)");
  fit_cmd->callback([args] { fit(*args); });

  auto name = std::make_shared<std::string>();
  CLI::App* show_cmd = soil->add_subcommand("show", "Print a named soil or a soil file as the simulation reads it");
  show_cmd->add_option("SOIL", *name, "a named soil (mechsim world soils) or a soil file (.yaml)")->required();
  show_cmd->callback([name] { show(*name); });
}

}  // namespace mechsim::apps
