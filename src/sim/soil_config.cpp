#include "sim/soil_config.hpp"

#include <cmath>
#include <string>

#include "sim/scenario.hpp"

namespace mechsim::sim {
namespace {

[[noreturn]] void fail(const control::Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? at.path() : at.location() + ": " + at.path();
  throw ScenarioError(where + ": " + what);
}

std::string soil_names() {
  std::string out;
  for (const physics::SoilParameters& s : physics::named_soils()) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

physics::SoilParameters named(const control::Params& node, const std::string& name) {
  const std::optional<physics::SoilParameters> soil = physics::find_soil(name);
  if (!soil) fail(node, "no soil named '" + name + "' (named soils: " + soil_names() + ")");
  return *soil;
}

}  // namespace

physics::SoilParameters read_soil(const control::Params& node) {
  if (!node.is_map()) return named(node, node.as<std::string>());
  static const char* const kKeys[] = {"base",       "n",  "k_c", "k_phi",      "cohesion",     "friction_angle_deg",
                                      "shear_modulus", "c1", "c2", "exit_ratio", "bedrock_depth", "multi_pass"};
  for (const std::string& k : node.keys()) {
    bool known = false;
    for (const char* key : kKeys) known = known || k == key;
    if (!known) {
      std::string list;
      for (const char* key : kKeys) list += (list.empty() ? "" : ", ") + std::string(key);
      fail(node.child(k), "unknown key '" + k + "' (expected one of: " + list + ")");
    }
  }
  physics::SoilParameters soil;
  if (node.has("base")) soil = named(node.child("base"), node.get<std::string>("base"));
  const std::string base = soil.name;
  soil.name = base.empty() ? "custom" : base + " (modified)";
  bool modified = false;
  const auto set = [&](const char* key, double& value, double scale = 1.0) {
    if (!node.has(key)) return;
    const double v = node.get<double>(key);
    if (!std::isfinite(v)) fail(node.child(key), "must be finite");
    value = v * scale;
    modified = true;
  };
  set("n", soil.n);
  set("k_c", soil.k_c);
  set("k_phi", soil.k_phi);
  set("cohesion", soil.cohesion);
  set("friction_angle_deg", soil.friction_angle, M_PI / 180.0);
  set("shear_modulus", soil.shear_modulus);
  set("c1", soil.c1);
  set("c2", soil.c2);
  set("exit_ratio", soil.exit_ratio);
  set("bedrock_depth", soil.bedrock_depth);
  // The model's switch, not a property of the soil: the set keeps its name.
  if (node.has("multi_pass")) soil.multi_pass = node.get<bool>("multi_pass");
  if (!modified && !base.empty()) soil.name = base;
  if (modified) soil.source = "user values" + (base.empty() ? std::string() : " on " + soil.source);
  if (const std::string problem = physics::check_soil(soil); !problem.empty()) fail(node, problem);
  return soil;
}

}  // namespace mechsim::sim
