#pragma once
// A sweep point's scenario: the base scenario file's YAML tree with values replaced at dotted
// paths before the scenario reader sees it, so that every scenario key can be varied and every
// value is checked as if it had been written in the file.

#include <string>
#include <vector>

#include "sim/scenario.hpp"

namespace mechsim::batch {

struct Override {
  std::string path;    // dotted: map keys and list indices (timeline.0.route.speed)
  std::string value;   // YAML scalar text
  std::string origin;  // where it was asked for ("sweep.yaml:12: axis spawn.yaw"), for errors
};

// Reads `scenario_file` with `overrides` applied. Throws SweepError naming the override's
// origin, its path and the scenario file when a path does not lead to a value (a list index out of
// range, a key under a scalar), when the scenario reader did not read the value (no such
// scenario key: world.sed), or when the value is refused (a seed of 2.5); other scenario errors
// as sim::ScenarioError.
sim::Scenario load_with_overrides(const std::string& scenario_file, const std::vector<Override>& overrides);

}  // namespace mechsim::batch
