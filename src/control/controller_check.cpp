#include "control/controller_check.hpp"

#include <map>

#include "control/controller_manager.hpp"

namespace mechsim::control {
namespace {

struct Found {
  Params ns;
  std::string name;
};

void find_controllers(const Params& ns, const Params& node, const std::string& prefix, std::vector<Found>& out) {
  for (const std::string& key : node.keys()) {
    Params child = node.child(key);
    if (!child.is_map()) continue;
    if (child.has("type")) {
      out.push_back(Found{ns, prefix + key});
    } else {
      // A namespace of its own: controllers below it are loaded relative to it.
      find_controllers(child, child, "", out);
    }
  }
}

}  // namespace

std::string describe(const ControllerCheck& check) {
  std::string out = check.path + " (" + (check.type.empty() ? std::string("no type") : check.type) + "): ";
  if (!check.ok()) return out + "ERROR " + check.error;
  std::string sensors;
  for (const SensorUse& use : check.sensors) {
    const std::string_view iface = use.interface;
    sensors += "; reads " + std::string(iface.substr(iface.find("::") == std::string_view::npos ? 0 : iface.find("::") + 2)) + " [";
    for (std::size_t j = 0; j < use.sensors.size(); ++j) sensors += (j > 0 ? ", " : "") + use.sensors[j];
    sensors += "]";
  }
  if (check.claims.empty()) {
    return out + (check.sensors.empty() ? "claims nothing (reads every joint)" : "claims nothing" + sensors);
  }
  for (std::size_t c = 0; c < check.claims.size(); ++c) {
    if (c > 0) out += "; ";
    out += interface_short_name(check.claims[c].interface);
    out += " [";
    for (std::size_t j = 0; j < check.claims[c].joints.size(); ++j) {
      if (j > 0) out += ", ";
      out += check.claims[c].joints[j];
    }
    out += "]";
  }
  return out + sensors;
}

std::vector<ControllerCheck> check_controllers(const mechanism::MechanismModel& model, const Params& root,
                                               const ControllerRegistry& registry, const SensorHardware* sensors) {
  std::vector<Found> found;
  find_controllers(root, root, "", found);

  std::vector<ControllerCheck> out;
  // One manager (and one fresh state) per namespace, as one controller_manager per robot.
  mechanism::MechanismState state = mechanism::make_state(model);
  std::map<std::string, std::unique_ptr<ControllerManager>> managers;
  for (const Found& f : found) {
    auto& manager = managers[f.ns.path()];
    if (!manager) {
      manager = std::make_unique<ControllerManager>(model, state, f.ns, registry);
      manager->set_sensor_hardware(sensors);
    }
    ControllerCheck check;
    check.name = f.name;
    check.ns = f.ns.path();
    check.path = join_param_path(f.ns.path(), f.name);
    try {
      check.type = f.ns.child(f.name).get<std::string>("type", "");
    } catch (const ParamsError&) {
      check.type.clear();  // load_controller reports it
    }
    ControlResult result = manager->load_controller(f.name);
    if (result.ok) {
      const std::optional<ControllerInfo> info = manager->controller_info(f.name);
      check.claims = info->claims;
      check.sensors = info->sensors;
    } else {
      check.error = result.error;
    }
    out.push_back(std::move(check));
  }
  return out;
}

std::vector<ControllerCheck> check_controllers_file(const mechanism::MechanismModel& model,
                                                    const std::string& yaml_path,
                                                    const ControllerRegistry& registry) {
  return check_controllers(model, Params::from_yaml_file(yaml_path), registry);
}

}  // namespace mechsim::control
