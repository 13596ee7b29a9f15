// Shared by the scenario readers (scenario.cpp, scenario_checks.cpp, scenario_world.cpp): errors
// that name file, line and key path, and the value readers they all use. Internal to the sim layer.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "control/params.hpp"
#include "physics/physics_options.hpp"
#include "sim/scenario.hpp"

namespace mechsim::sim::scenario_read {

using control::Params;

inline constexpr double kDeg = std::numbers::pi / 180.0;

// Throws ScenarioError naming the file, line and key path of `at`.
[[noreturn]] void fail(const Params& at, const std::string& what);
// A scalar's text whatever its YAML type (xacro arguments are strings on the command line).
std::string scalar_text(const Params& p);
// Rejects keys outside `allowed` (a misspelt bound must not be ignored).
void only_keys(const Params& p, std::initializer_list<const char*> allowed);
// `file` relative to `base` unless absolute, normalised.
std::string resolve_path(const std::filesystem::path& base, const std::string& file);
// p[key] (finite) or `fallback` when absent.
double finite(const Params& p, std::string_view key, double fallback);
// p[key] as a list of finite numbers, `expected` long unless 0.
std::vector<double> values_of(const Params& point, const char* key, std::size_t expected);

Check read_check(const Params& c);
std::vector<physics::WorldBox> read_boxes(const Params& list, const std::filesystem::path& base);

}  // namespace mechsim::sim::scenario_read
