#include "sim/wheel_config.hpp"

#include <cmath>
#include <string>

#include "sim/scenario.hpp"

namespace mechsim::sim {
namespace {

[[noreturn]] void fail(const control::Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? at.path() : at.location() + ": " + at.path();
  throw ScenarioError(where + ": " + what);
}

void only(const control::Params& node, std::initializer_list<const char*> keys) {
  for (const std::string& k : node.keys()) {
    bool known = false;
    std::string list;
    for (const char* key : keys) known = known || k == key, list += (list.empty() ? "" : ", ") + std::string(key);
    if (!known) fail(node.child(k), "unknown key '" + k + "' (expected one of: " + list + ")");
  }
}

double positive(const control::Params& node, const char* key) {
  const double v = node.get<double>(key);
  if (!std::isfinite(v) || !(v > 0.0)) fail(node.child(key), "must be > 0 (m)");
  return v;
}

}  // namespace

std::vector<physics::WheelOverride> read_wheel_overrides(const control::Params& node) {
  if (!node.is_map()) fail(node, "expected a map of link -> false, true or {radius, width, grousers}");
  std::vector<physics::WheelOverride> out;
  for (const std::string& link : node.keys()) {
    const control::Params entry = node.child(link);
    physics::WheelOverride o;
    o.link = link;
    o.origin = entry.location();
    if (entry.is_scalar()) {
      try {
        o.wheel = entry.as<bool>();
      } catch (const std::exception&) {
        fail(entry, "expected false (not a wheel), true, or a map {radius, width, grousers}");
      }
    } else if (entry.is_map()) {
      only(entry, {"radius", "width", "grousers"});
      if (entry.has("radius")) o.radius = positive(entry, "radius");
      if (entry.has("width")) o.width = positive(entry, "width");
      if (auto g = entry.find("grousers")) {
        if (!g->is_map()) fail(*g, "expected {height: m, count: N}");
        only(*g, {"height", "count"});
        o.grouser_height = positive(*g, "height");
        o.grouser_count = g->get<int>("count");
        if (o.grouser_count < 1) fail(g->child("count"), "must be >= 1");
      }
    } else {
      fail(entry, "expected false (not a wheel), true, or a map {radius, width, grousers}");
    }
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace mechsim::sim
