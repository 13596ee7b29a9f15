#include "control/ros2_params.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>

#include "control/params_edit.hpp"
#include "control/params_yaml.hpp"

namespace mechsim::control {

namespace {

constexpr const char* kRosParameters = "ros__parameters";

std::string where(const Params& p) {
  const std::string at = p.location();
  return at.empty() ? p.path() : at;
}

[[noreturn]] void refuse(const Params& p, const std::string& what) { throw ParamsError(where(p) + ": " + what, p.path()); }

std::string join_name(const std::string& prefix, const std::string& key) {
  if (prefix.empty()) return key;
  if (prefix.back() == '/' || (!key.empty() && key.front() == '/')) return prefix + key;
  return prefix + "/" + key;
}

std::vector<std::string> split_dots(const std::string& key) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    out.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return out;
}

// Copies the ros__parameters block `block` into `into`, turning "a.b.c: v" into a/b/c.
void expand_dotted(const Params& block, Params into) {
  for (const std::string& key : block.keys()) {
    const Params value = block.child(key);
    const std::vector<std::string> parts = split_dots(key);
    for (const std::string& part : parts) {
      if (part.empty()) refuse(value, "parameter name '" + key + "' has an empty part between dots");
    }
    std::string nested;
    for (const std::string& part : parts) nested += (nested.empty() ? "" : "/") + part;
    if (value.is_map()) {
      // A map may hold dotted names too; expand it level by level.
      Params target = into.child_or_create(nested);
      expand_dotted(value, target);
    } else {
      merge(into, nested, value);
    }
  }
}

// Walks the node-name levels of a file (yaml-cpp: the names hold '/', which Params keys may not)
// down to each ros__parameters.
void collect(const YAML::Node& node, const std::string& prefix, const std::string& source,
             std::vector<Ros2NodeEntry>& out, bool& found) {
  for (const auto& entry : node) {
    const YAML::Node& key = entry.first;
    const YAML::Node& value = entry.second;
    if (!key.IsScalar()) throw ParamsError(yaml_where(source, key.Mark()) + ": a node name must be a plain name", prefix);
    const std::string name = key.Scalar();
    const std::string at = yaml_where(source, key.Mark());
    if (name == kRosParameters) {
      if (prefix.empty()) throw ParamsError(at + ": ros__parameters at the top level: it must sit under a node name", "/");
      Ros2NodeEntry e;
      e.pattern = prefix.front() == '/' ? prefix : "/" + prefix;
      e.source = source + ":" + std::to_string(key.Mark().line + 1);
      if (value.IsMap()) {
        expand_dotted(params_from_yaml_map(value, source), e.parameters);
      } else if (!value.IsNull()) {
        // `ros__parameters:` with nothing under it reads as empty (rcl accepts it).
        throw ParamsError(at + ": ros__parameters of node '" + prefix + "' is not a map", e.pattern);
      }
      out.push_back(std::move(e));
      found = true;
      continue;
    }
    if (name.empty()) throw ParamsError(at + ": an empty node name", prefix);
    if (!value.IsMap()) {
      throw ParamsError(yaml_where(source, value.Mark()) + ": '" + name + "' under node name '" +
                            (prefix.empty() ? std::string("/") : prefix) +
                            "' is not a map: a value is only allowed under ros__parameters (ROS 2 parameter files are "
                            "NODE_NAME: {ros__parameters: {...}})",
                        prefix);
    }
    collect(value, join_name(prefix, name), source, out, found);
  }
}

void add_document(const YAML::Node& doc, const std::string& source, std::vector<Ros2NodeEntry>& entries) {
  if (!doc.IsMap()) throw ParamsError(source + ": a ROS 2 parameter file is a map of node names", "/");
  bool found = false;
  std::vector<Ros2NodeEntry> read;
  collect(doc, "", source, read, found);
  if (!found) {
    throw ParamsError(source + ": no ros__parameters in the file: not a ROS 2 parameter file (NODE_NAME: "
                               "{ros__parameters: {...}}; ROS 1 controller files are loaded without ros__parameters)",
                      "/");
  }
  entries.insert(entries.end(), std::make_move_iterator(read.begin()), std::make_move_iterator(read.end()));
}

std::regex pattern_regex(const std::string& pattern) {
  std::string rx;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const char c = pattern[i];
    if (c == '/' && pattern.compare(i, 3, "/**") == 0) {
      rx += "(/[^/]+)*";
      i += 2;
    } else if (c == '*') {
      rx += "[^/]+";
    } else if (std::string(".^$|()[]{}+?\\").find(c) != std::string::npos) {
      rx += '\\';
      rx += c;
    } else {
      rx += c;
    }
  }
  return std::regex(rx);
}

}  // namespace

bool ros2_node_name_matches(const std::string& pattern, const std::string& fqn) {
  if (pattern == fqn) return true;
  if (pattern.find('*') == std::string::npos) return false;
  return std::regex_match(fqn, pattern_regex(pattern));
}

Ros2ParameterSet Ros2ParameterSet::from_files(const std::vector<std::string>& files) {
  Ros2ParameterSet set;
  for (const std::string& f : files) set.add_file(f);
  return set;
}

void Ros2ParameterSet::add_file(const std::string& path) {
  add_document(load_yaml_file(path), path, entries_);
  sources_.push_back(path);
}

void Ros2ParameterSet::add_yaml(const std::string& yaml, const std::string& source_name) {
  add_document(load_yaml_string(yaml, source_name), source_name, entries_);
  sources_.push_back(source_name);
}

Params Ros2ParameterSet::parameters_for(const std::string& fqn) const {
  Params out;
  for (const Ros2NodeEntry& e : entries_) {
    if (ros2_node_name_matches(e.pattern, fqn)) merge(out, "", e.parameters);
  }
  return out;
}

bool Ros2ParameterSet::has_node(const std::string& fqn) const {
  for (const Ros2NodeEntry& e : entries_)
    if (ros2_node_name_matches(e.pattern, fqn)) return true;
  return false;
}

bool is_ros2_parameter_file(const std::string& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path);
    // Node names nest a few levels at most before ros__parameters.
    std::vector<YAML::Node> level{root};
    for (int depth = 0; depth < 6 && !level.empty(); ++depth) {
      std::vector<YAML::Node> next;
      for (const YAML::Node& n : level) {
        if (!n.IsMap()) continue;
        for (const auto& kv : n) {
          if (kv.first.IsScalar() && kv.first.Scalar() == kRosParameters) return true;
          next.push_back(kv.second);
        }
      }
      level = std::move(next);
    }
  } catch (const std::exception&) {
    return false;
  }
  return false;
}

Ros2ControlSetup ros2_control_setup(const Ros2ParameterSet& set, const std::string& controller_manager_fqn) {
  Ros2ControlSetup out;
  out.controller_manager = controller_manager_fqn;
  const std::size_t slash = controller_manager_fqn.rfind('/');
  out.node_namespace = slash == 0 || slash == std::string::npos ? "/" : controller_manager_fqn.substr(0, slash);
  const std::string prefix = out.node_namespace == "/" ? "" : out.node_namespace;
  if (!set.has_node(controller_manager_fqn)) {
    std::string files;
    for (const std::string& s : set.sources()) files += (files.empty() ? "" : ", ") + s;
    out.notes.push_back("no parameters for the controller manager " + controller_manager_fqn + " in " +
                        (files.empty() ? std::string("(no parameter file)") : files) +
                        ": update_rate 100 Hz, no controllers declared");
  }
  const Params cm = set.parameters_for(controller_manager_fqn);
  if (auto rate = cm.find("update_rate")) {
    double hz = 0.0;
    try {
      hz = rate->as<double>();
    } catch (const ParamsError&) {
      refuse(*rate, "update_rate of " + controller_manager_fqn + " is not a number");
    }
    if (!(hz > 0.0) || !std::isfinite(hz)) refuse(*rate, "update_rate of " + controller_manager_fqn + " must be > 0 Hz");
    out.update_rate = hz;
    out.update_rate_given = true;
  }
  for (const std::string& key : cm.keys()) {
    const Params entry = cm.child(key);
    if (!entry.is_map() || !entry.has("type")) continue;
    const Params type = entry.child("type");
    if (!type.is_scalar()) refuse(type, "type of controller '" + key + "' is not a string");
    // The controller's own node parameters, then its type from the manager's (the manager sets
    // it on the controller's node; ros2_control refuses a type that disagrees, mechsim takes the
    // manager's).
    merge(out.controllers, key, set.parameters_for(prefix + "/" + key));
    graft(out.controllers.child(key), "type", type);
    out.controller_names.push_back(key);
  }
  // Parameters for a controller the manager does not declare (a typo in either name).
  for (const Ros2NodeEntry& e : set.entries()) {
    if (e.pattern.find('*') != std::string::npos) continue;
    const std::size_t at = e.pattern.rfind('/');
    const std::string ns = at == 0 ? "/" : e.pattern.substr(0, at);
    const std::string name = e.pattern.substr(at + 1);
    if (ns != out.node_namespace || e.pattern == controller_manager_fqn) continue;
    const bool declared = std::find(out.controller_names.begin(), out.controller_names.end(), name) != out.controller_names.end();
    if (!declared && e.parameters.has("type")) {
      // Jazzy: a controller's type may be in its own parameters (the spawner's --param-file).
      merge(out.controllers, name, set.parameters_for(e.pattern));
      out.controller_names.push_back(name);
      continue;
    }
    if (!declared) {
      // Only nodes that look like controllers (ros2_control's own keys) are reported.
      const bool looks_like_controller = e.parameters.has("joints") || e.parameters.has("interface_name") ||
                                         e.parameters.has("left_wheel_names") || e.parameters.has("sensor_name") ||
                                         e.parameters.has("traction_joint_name");
      if (looks_like_controller) {
        out.notes.push_back(e.source + ": parameters of node " + e.pattern + ", which controller manager " +
                            controller_manager_fqn + " does not declare (no '" + name + ": {type: ...}' in its parameters)");
      }
    }
  }
  return out;
}

}  // namespace mechsim::control
