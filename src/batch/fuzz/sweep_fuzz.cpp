// Fuzz target: a sweep file with the scenario it varies, taken as far as `mechsim sweep` goes
// before it starts a point: the sweep read and checked, its points drawn, every axis's values
// laid over the scenario and checked by the scenario reader, the plan written and read back. An
// input may fail only with SweepError or ScenarioError naming the file; the plan read back must
// give the same points (anything else aborts, which libFuzzer reports).
//
// Input: the sweep file, then "=== scenario.yaml" and the scenario (and any file it names).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "batch/sweep_folder.hpp"
#include "batch/sweep_spec.hpp"
#include "fuzz_files.hpp"
#include "sim/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace b = mechsim::batch;
  auto& dir = mechsim::fuzz::scratch();
  dir.write(mechsim::fuzz::split_files(data, size, "sweep.yaml"));
  try {
    const b::SweepSpec spec = b::load_sweep((dir.path() / "sweep.yaml").string(), false);
    // A bound on the points (mechsim sweep's is kMaxPointsWithoutForce) keeps each input quick;
    // past it plan_points refuses with SweepError, the path a larger sweep takes too.
    const b::Plan plan = b::make_plan(spec, 2000);
    b::check_plan(plan);
    const auto folder = dir.path() / "plan";
    b::write_plan(folder, plan);
    if (!b::same_points(plan, b::read_plan(folder))) std::abort();
  } catch (const b::SweepError&) {
  } catch (const mechsim::sim::ScenarioError&) {
  }
  return 0;
}
