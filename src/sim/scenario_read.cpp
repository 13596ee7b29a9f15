#include "sim/scenario_read.hpp"

#include <cmath>
#include <exception>

#include "control/params_keys.hpp"

namespace mechsim::sim::scenario_read {

namespace fs = std::filesystem;

[[noreturn]] void fail(const Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? at.path() : at.location() + ": " + at.path();
  throw ScenarioError(where + ": " + what);
}

std::string scalar_text(const Params& p) {
  try {
    return p.as<std::string>();
  } catch (const std::exception&) {
  }
  try {
    const double v = p.as<double>();
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  } catch (const std::exception&) {
  }
  try {
    return p.as<bool>() ? "true" : "false";
  } catch (const std::exception&) {
  }
  fail(p, "expected a scalar value");
}

void only_keys(const Params& p, std::initializer_list<const char*> allowed) {
  if (!p.is_map()) fail(p, "expected a map");
  if (const auto unknown = control::unknown_key(p, allowed)) fail(p.child(unknown->key), unknown->message);
}

std::string resolve_path(const fs::path& base, const std::string& file) {
  const fs::path p(file);
  return (p.is_absolute() ? p : (base / p)).lexically_normal().string();
}

double finite(const Params& p, std::string_view key, double fallback) {
  if (!p.has(key)) return fallback;
  const double v = p.get<double>(key);
  if (!std::isfinite(v)) fail(p.child(key), "must be finite");
  return v;
}

std::vector<double> values_of(const Params& point, const char* key, std::size_t expected) {
  const Params v = point.child(key);
  const auto values = v.as<std::vector<double>>();
  if (expected != 0 && values.size() != expected) {
    fail(v, "has " + std::to_string(values.size()) + " values, expected " + std::to_string(expected) + " (one per joint)");
  }
  for (double x : values) {
    if (!std::isfinite(x)) fail(v, "values must be finite");
  }
  return values;
}

}  // namespace mechsim::sim::scenario_read
