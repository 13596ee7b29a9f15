#include "sim/soil_config.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "sim/scenario.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const control::Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? at.path() : at.location() + ": " + at.path();
  throw ScenarioError(where + ": " + what);
}

std::string soil_names() {
  std::string out;
  for (const physics::SoilParameters& s : physics::named_soils()) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

bool is_soil_file(const std::string& name) {
  const std::string ext = fs::path(name).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

physics::SoilParameters from_file(const std::string& name, const fs::path& base, const std::string& where);

physics::SoilParameters named(const control::Params& node, const std::string& name, const fs::path& base) {
  if (is_soil_file(name)) {
    try {
      return from_file(name, base, node.location());
    } catch (const ScenarioError&) {
      throw;
    } catch (const std::exception& e) {
      fail(node, e.what());
    }
  }
  const std::optional<physics::SoilParameters> soil = physics::find_soil(name);
  if (!soil) fail(node, "no soil named '" + name + "' (named soils: " + soil_names() + "; or a soil file, NAME.yaml)");
  return *soil;
}

physics::SoilParameters read_map(const control::Params& node, const fs::path& base, bool file,
                                 const physics::SoilParameters* start = nullptr) {
  static const char* const kKeys[] = {"base",       "name",          "source",     "model", "n",  "k_c", "k_phi",
                                      "cohesion",   "friction_angle_deg", "shear_modulus", "c1", "c2", "exit_ratio",
                                      "rear_ratio", "n1",            "n2",         "bedrock_depth", "multi_pass"};
  for (const std::string& k : node.keys()) {
    bool known = false;
    for (const char* key : kKeys) known = known || k == key;
    if (file && k == "base") known = false;
    if (!file && (k == "name" || k == "source")) known = false;
    if (!known) {
      std::string list;
      for (const char* key : kKeys)
        if (!(file && std::string(key) == "base") && !(!file && (std::string(key) == "name" || std::string(key) == "source")))
          list += (list.empty() ? "" : ", ") + std::string(key);
      fail(node.child(k), "unknown key '" + k + "' (expected one of: " + list + ")");
    }
  }
  physics::SoilParameters soil;
  if (start != nullptr) soil = *start;
  if (node.has("base")) soil = named(node.child("base"), node.get<std::string>("base"), base);
  const std::string base_name = soil.name;
  soil.name = base_name.empty() ? "custom" : base_name + " (modified)";
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
  set("rear_ratio", soil.rear_ratio);
  set("n1", soil.n1);
  set("n2", soil.n2);
  set("bedrock_depth", soil.bedrock_depth);
  if (node.has("model")) {
    const auto model = physics::find_model(node.get<std::string>("model"));
    if (!model) fail(node.child("model"), "unknown model '" + node.get<std::string>("model") + "' (wong_reece or ding)");
    modified = modified || *model != soil.model;
    soil.model = *model;
  }
  // The model's switch, not a property of the soil: the set keeps its name.
  if (node.has("multi_pass")) soil.multi_pass = node.get<bool>("multi_pass");
  if (file) {
    soil.name = node.get<std::string>("name", "");
    soil.source = node.get<std::string>("source", "");
    if (soil.name.empty()) fail(node, "a soil file needs a name");
  } else {
    if (!modified && !base_name.empty()) soil.name = base_name;
    if (modified) soil.source = "user values" + (base_name.empty() ? std::string() : " on " + soil.source);
  }
  if (const std::string problem = physics::check_soil(soil); !problem.empty()) fail(node, problem);
  return soil;
}

physics::SoilParameters from_file(const std::string& name, const fs::path& base, const std::string& where) {
  const fs::path path = fs::path(name).is_absolute() || base.empty() ? fs::path(name) : base / name;
  if (!fs::exists(path))
    throw ScenarioError((where.empty() ? std::string() : where + ": ") + "soil file '" + path.string() + "' not found");
  const control::Params file = control::Params::from_yaml_file(path.string());
  if (!file.is_map()) throw ScenarioError(path.string() + ": a soil file is a map (name, source, n, k_c, ...)");
  return read_map(file, path.parent_path(), true);
}

std::string num(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace

physics::SoilParameters read_soil(const control::Params& node, const fs::path& base) {
  if (!node.is_map()) return named(node, node.as<std::string>(), base);
  return read_map(node, base, false);
}

physics::SoilParameters read_soil_over(const control::Params& node, const physics::SoilParameters& start) {
  if (!node.is_map()) fail(node, "expected a map of soil keys (n, k_c, cohesion, friction_angle_deg, ...)");
  if (node.has("base")) fail(node.child("base"), "not here: the values are laid over the fit's base");
  return read_map(node, {}, false, &start);
}

physics::SoilParameters soil_by_name(const std::string& name, const fs::path& base) {
  if (is_soil_file(name)) return from_file(name, base, "");
  const std::optional<physics::SoilParameters> soil = physics::find_soil(name);
  if (!soil) throw ScenarioError("no soil named '" + name + "' (named soils: " + soil_names() + "; or a soil file, NAME.yaml)");
  return *soil;
}

std::string soil_yaml(const physics::SoilParameters& s, const std::string& comment) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "#" << (line.empty() ? "" : " ") << line << "\n";
  const auto quoted = [](const std::string& text) {
    std::string q = "\"";
    for (char c : text) q += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    return q + "\"";
  };
  out << "name: " << quoted(s.name) << "\n";
  out << "source: " << quoted(s.source) << "\n";
  out << "model: " << physics::model_name(s.model) << "\n";
  out << "n: " << num(s.n) << "\n";
  out << "k_c: " << num(s.k_c) << "                # N/m^(n+1)\n";
  out << "k_phi: " << num(s.k_phi) << "            # N/m^(n+2)\n";
  out << "cohesion: " << num(s.cohesion) << "             # Pa\n";
  out << "friction_angle_deg: " << num(s.friction_angle * 180.0 / M_PI) << "\n";
  out << "shear_modulus: " << num(s.shear_modulus) << "      # K, m\n";
  out << "c1: " << num(s.c1) << "\n";
  out << "c2: " << num(s.c2) << "\n";
  out << "exit_ratio: " << num(s.exit_ratio) << "        # wong_reece\n";
  out << "rear_ratio: " << num(s.rear_ratio) << "        # ding\n";
  out << "n1: " << num(s.n1) << "\n";
  out << "n2: " << num(s.n2) << "\n";
  out << "bedrock_depth: " << num(s.bedrock_depth) << "     # m\n";
  out << "multi_pass: " << (s.multi_pass ? "true" : "false") << "\n";
  return out.str();
}

}  // namespace mechsim::sim
