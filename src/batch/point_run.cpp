#include "batch/point_run.hpp"

#include <chrono>
#include <iostream>

#include "batch/point_result.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::batch {

int run_point(const std::filesystem::path& dir, const Plan& plan, std::size_t index, const std::atomic<int>* interrupt) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path out = point_dir(dir, index);
  std::filesystem::remove(out / "point.json");
  PointResult result;
  result.index = index;
  sim::Scenario scenario;
  try {
    scenario = load_with_overrides(plan.scenario, point_overrides(plan, index));
    // A lean point (no plots) records no 3D replay either: on the Mars Yard that is ~2 MB a point.
    if (!plan.plots_per_point) scenario.replay_rate = 0.0;
    sim::RunOptions options;
    options.output_dir = out.string();
    options.plots = plan.plots_per_point;
    options.interrupt = interrupt;
    options.warning = [](const std::string& text) { std::cerr << "warning: " << text << "\n" << std::flush; };
    std::cout << "point " << index << " of sweep " << plan.name << ": scenario " << scenario.name << ", "
              << scenario.duration << " s\n" << std::flush;
    const sim::ScenarioResult run = sim::run_scenario(scenario, options);
    if (run.interrupted_by != 0) {
      std::cerr << "interrupted by signal " << run.interrupted_by << "\n";
      return 128 + run.interrupted_by;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result = result_of_run(scenario, run, wall);
    result.index = index;
    for (const sim::CheckOutcome& c : run.checks) std::cout << (c.passed ? "  PASS " : "  FAIL ") << c.detail << "\n";
    if (!run.completed) std::cout << "did not complete: " << run.error << "\n";
  } catch (const std::exception& e) {
    // The point's own outcome (its values refused, its world not made): recorded, not retried.
    std::cerr << "error: " << e.what() << "\n";
    result.status = PointStatus::Error;
    result.error = e.what();
  }
  std::cout << "point " << index << ": " << status_name(result.status) << "\n" << std::flush;
  write_point_result(out, result);
  return 0;
}

}  // namespace mechsim::batch
