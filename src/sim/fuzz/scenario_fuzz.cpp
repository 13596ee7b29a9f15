// Fuzz target: a scenario file (YAML: robot, world, commands, goals, checks, sensors) read and
// validated as `mechsim run` does before it runs anything. An input may fail only with
// ScenarioError naming the file and the parameter.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_files.hpp"
#include "sim/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace s = mechsim::sim;
  auto& dir = mechsim::fuzz::scratch();
  dir.write(mechsim::fuzz::split_files(data, size, "scenario.yaml"));
  try {
    (void)s::load_scenario((dir.path() / "scenario.yaml").string());
  } catch (const s::ScenarioError&) {
  }
  return 0;
}
