#include "batch/scenario_override.hpp"

#include <cstdlib>
#include <filesystem>

#include "batch/sweep_spec.hpp"
#include "control/params_edit.hpp"

namespace mechsim::batch {
namespace {

using control::Params;

std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 10 && s.find_first_not_of("0123456789") == std::string::npos;
}

// The value as a YAML scalar: plain when YAML reads it back as written (numbers, booleans,
// words), else a string.
Params value_node(const std::string& text) {
  try {
    const Params doc = Params::from_yaml_string("v: " + text);
    const Params v = doc.child("v");
    if (v.is_scalar() && v.as<std::string>() == text) return v;
  } catch (const std::exception&) {
  }
  Params doc;
  doc.set("v", text);
  return doc.child("v");
}

// Puts `value` at `o.path` under `root`; returns the handle of the node replaced.
Params apply(Params root, const Override& o, const std::string& file) {
  const auto fail = [&](const std::string& what) -> void {
    throw SweepError(o.origin + ": path '" + o.path + "': " + what + " (in " + file + ")");
  };
  Params at = root;
  std::string walked;
  const std::vector<std::string> parts = split(o.path);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    if (at.is_list()) {
      if (!is_index(part)) fail("'" + walked + "' is a list: expected an item number, got '" + part + "'");
      const auto index = static_cast<std::size_t>(std::strtoul(part.c_str(), nullptr, 10));
      if (index >= at.size()) fail("'" + walked + "' has " + std::to_string(at.size()) + " items: no item " + part);
      at = at.at(index);
    } else if (at.is_map() || at.kind() == Params::Kind::Null) {
      // A missing key is created: the scenario reader decides whether it knows it.
      at = at.child_or_create(part);
    } else {
      fail("'" + walked + "' is a single value, it has no '" + part + "'");
    }
    walked += (walked.empty() ? "" : ".") + part;
    if (last) control::replace(at, "", value_node(o.value));
  }
  return at;
}

// Whether a scenario error names the parameter `path` ("/world/seed", not "/world/seed_x").
bool names(const std::string& message, const std::string& path) {
  for (std::size_t at = message.find(path); at != std::string::npos; at = message.find(path, at + 1)) {
    const std::size_t end = at + path.size();
    const bool starts = at == 0 || message[at - 1] == ' ';
    const bool ends = end == message.size() || message[end] == ':' || message[end] == ' ' || message[end] == '/' ||
                      message[end] == '[';
    if (starts && ends) return true;
  }
  return false;
}

}  // namespace

sim::Scenario load_with_overrides(const std::string& scenario_file, const std::vector<Override>& overrides) {
  if (!std::filesystem::exists(scenario_file)) throw sim::ScenarioError(scenario_file + ": no such scenario file");
  Params root;
  try {
    root = Params::from_yaml_file(scenario_file);
  } catch (const std::exception& e) {
    throw sim::ScenarioError(e.what());
  }
  std::vector<Params> nodes;
  for (const Override& o : overrides) nodes.push_back(apply(root, o, scenario_file));
  sim::Scenario scenario;
  try {
    scenario = sim::load_scenario(root, scenario_file);
  } catch (const sim::ScenarioError& e) {
    // Name the override whose value the reader refused (its parameter path is in the message).
    const std::string message = e.what();
    for (std::size_t i = 0; i < overrides.size(); ++i) {
      if (names(message, nodes[i].path())) {
        throw SweepError(overrides[i].origin + ": path '" + overrides[i].path + "' = " + overrides[i].value + ": " + message);
      }
    }
    throw;
  }
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    if (!control::was_read(nodes[i])) {
      throw SweepError(overrides[i].origin + ": path '" + overrides[i].path + "': no such scenario key (the scenario reader does not read " +
                       nodes[i].path() + "; in " + scenario_file + ")");
    }
  }
  return scenario;
}

}  // namespace mechsim::batch
