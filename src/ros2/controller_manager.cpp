// ros2_control's controller manager services over mechsim's controller manager
// (controller_manager.hpp). Names, fields and refusals as controller_manager.cpp of ros2_control
// gives them (Humble 2.x and Jazzy 4.x).
#include "ros2/controller_manager.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <mechsim_ros2_msgs/controller_manager_msgs.hpp>
#include <mechsim_ros2_msgs/humble/controller_manager_msgs.hpp>
#include <mechsim_ros2_msgs/jazzy/controller_manager_msgs.hpp>
#include <mechsim_ros2_msgs/lifecycle_msgs.hpp>

#include "ros2/parameters.hpp"
#include "ros2/service.hpp"
#include "ros2/sim_node.hpp"

namespace mechsim::ros2 {

namespace cm = controller_manager_msgs::srv;
using lifecycle_msgs::msg::State;

namespace {

// ros2_control's interface name of a claim: "position", "velocity", "effort" (mechsim's ROS 1
// robots claim ros_control's class names: hardware_interface::EffortJointInterface -> effort).
std::string interface_name(const std::string& hardware_interface) {
  if (hardware_interface.find("Effort") != std::string::npos) return "effort";
  if (hardware_interface.find("Position") != std::string::npos) return "position";
  if (hardware_interface.find("Velocity") != std::string::npos) return "velocity";
  const auto colon = hardware_interface.rfind(':');
  return colon == std::string::npos ? hardware_interface : hardware_interface.substr(colon + 1);
}

// A deferred server whose requests run on `worker` in order; a full queue answers the default
// response (ok false).
template <class Srv, class Run>
std::shared_ptr<void> serve(Node& node, const std::string& name, Worker& worker, Run run) {
  auto holder = std::make_shared<std::weak_ptr<ServiceServer<Srv>>>();
  auto made = std::make_shared<ServiceServer<Srv>>(
      node, name,
      typename ServiceServer<Srv>::DeferredHandler([holder, &worker, run](const typename Srv::Request& request, const ReplyTo& to) {
        std::weak_ptr<ServiceServer<Srv>> weak = *holder;
        const bool queued = worker.post([weak, request, to, run] {
          typename Srv::Response response;
          run(request, response);
          if (auto s = weak.lock()) s->reply(to, response);
        });
        if (!queued)
          if (auto s = weak.lock()) s->reply(to, typename Srv::Response{});
      }));
  *holder = made;
  return made;
}

double seconds_of(const builtin_interfaces::msg::Duration& d) { return d.sec + 1e-9 * d.nanosec; }

// controller_manager_msgs/srv/SwitchController's strictness constants (both distros).
constexpr int kBestEffort = 1, kStrict = 2;

}  // namespace

ControllerManagerNode::ControllerManagerNode(SimNode& model) : model_(model), bridge_(model.bridge()) {
  node_ = std::make_unique<Node>(model_.participant(), model_.options().robot_namespace, "controller_manager");
  worker_ = std::make_unique<Worker>();
  // The manager's parameters: update_rate and `<controller>.type` of every declared controller;
  // undeclared ones are taken (the spawner sets <controller>.type and .params_file).
  std::map<std::string, ParameterValue> initial;
  const control::Params params = bridge_.controller_params();
  for (const std::string& name : params.keys()) {
    const control::Params c = params.child(name);
    if (c.is_map() && c.has("type")) {
      ParameterValue t;
      t.type = rcl_interfaces::msg::ParameterType::PARAMETER_STRING;
      t.string_value = c.get<std::string>("type", "");
      initial[name + ".type"] = t;
    } else if (c.is_scalar() && name == "update_rate") {
      initial[name] = parameter_value_of(c);
    }
  }
  if (initial.count("update_rate") == 0) {
    ParameterValue rate;
    rate.type = rcl_interfaces::msg::ParameterType::PARAMETER_INTEGER;
    rate.integer_value = static_cast<std::int64_t>(std::lround(1.0 / bridge_.period()));
    initial["update_rate"] = rate;
  }
  ParameterServer::Options options;
  options.allow_undeclared = true;
  options.read_only = {"update_rate"};  // mechsim's tick: the world's period
  control::Params store = params;
  options.on_set = [store](const std::string& name, const ParameterValue& value) mutable {
    // `<controller>.type`: the controller is declared (the spawner's --controller-type).
    const auto dot = name.rfind(".type");
    if (dot != std::string::npos && dot + 5 == name.size() && value.type == rcl_interfaces::msg::ParameterType::PARAMETER_STRING) {
      store.child_or_create(name.substr(0, dot)).set("type", value.string_value);
    }
  };
  parameters_ = std::make_unique<ParameterServer>(*node_, initial, std::nullopt, options);
  advertise_common();
  if (model_.participant().distro() == Distro::Humble) advertise_distro<humble::controller_manager_msgs::srv::ListControllers>();
  else advertise_distro<jazzy::controller_manager_msgs::srv::ListControllers>();
  lines_.push_back(node_->fq_name() + "/{list_controllers, list_controller_types, list_hardware_interfaces, "
                   "list_hardware_components, load_controller, configure_controller, switch_controller, "
                   "unload_controller, reload_controller_libraries, set_hardware_component_state} and parameters "
                   "(controller_manager_msgs, " + std::string(distro_name(model_.participant().distro())) + " layout)");
}

ControllerManagerNode::~ControllerManagerNode() {
  servers_.clear();
  worker_.reset();
  std::lock_guard<std::mutex> lock(mutex_);
  controller_parameters_.clear();
  controller_nodes_.clear();
  parameters_.reset();
}

std::vector<std::string> ControllerManagerNode::service_lines() const { return lines_; }

void ControllerManagerNode::forget_all() {
  std::lock_guard<std::mutex> lock(mutex_);
  records_.clear();
  controller_parameters_.clear();
  controller_nodes_.clear();
}

void ControllerManagerNode::on_tick(double) {}

std::string ControllerManagerNode::declared_type(const std::string& name) const {
  const control::Params params = bridge_.controller_params();
  if (auto c = params.find(name); c && c->is_map() && c->has("type")) {
    try {
      return c->get<std::string>("type");
    } catch (const std::exception&) {
    }
  }
  return "";
}

void ControllerManagerNode::sync() {
  std::set<std::string> loaded;
  for (const bridge::ControllerSummary& c : bridge_.list_controllers()) {
    loaded.insert(c.name);
    Record& r = records_[c.name];
    r.type = c.type;
    r.state = c.state == "running" ? "active" : "inactive";
  }
  for (auto it = records_.begin(); it != records_.end();) {
    if (it->second.state != "unconfigured" && loaded.count(it->first) == 0) it = records_.erase(it);
    else ++it;
  }
}

void ControllerManagerNode::make_controller_node(const std::string& name) {
  if (controller_nodes_.count(name) > 0) return;
  auto node = std::make_unique<Node>(model_.participant(), model_.options().robot_namespace, name, model_.options().controller_remaps);
  control::Params store = bridge_.controller_params().child_or_create(name);
  ParameterServer::Options options;
  options.read_only = {"type"};
  // ros2_controllers declare every parameter of their type at load (generate_parameter_library),
  // so the spawner's --param-file (Humble: set_parameters after load_controller) sets declared
  // ones; mechsim knows no type's declarations, so a loaded controller's node takes any name.
  options.allow_undeclared = true;
  controller_parameters_[name] = std::make_unique<ParameterServer>(*node, flatten_parameters(store, {}), store, options);
  controller_nodes_[name] = std::move(node);
}

ControllerManagerNode::Result ControllerManagerNode::load(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  sync();
  if (records_.count(name) > 0) return {false, "Controller already loaded, skipping load_controller: " + name};
  try {
    check_node_name(name);
  } catch (const NameError& e) {
    return {false, "'" + name + "' cannot be a controller's node name: " + e.what()};
  }
  const std::string type = declared_type(name);
  if (type.empty()) return {false, "The 'type' param was not defined for '" + name + "'."};
  // A type mechsim does not have fails here, as pluginlib fails ros2_control's load.
  const std::vector<std::string> types = bridge_.list_controller_types();
  if (std::find(types.begin(), types.end(), type) == types.end())
    return {false, "Loader for controller '" + name + "' (type '" + type + "') not found (mechsim has no controller of that type)"};
  records_[name] = {"unconfigured", type};
  try {
    make_controller_node(name);
  } catch (const std::exception& e) {
    records_.erase(name);
    return {false, "controller '" + name + "': its node could not be made: " + e.what()};
  }
  return {};
}

ControllerManagerNode::Result ControllerManagerNode::configure(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  sync();
  const auto it = records_.find(name);
  if (it == records_.end()) return {false, "Controller '" + name + "' is not loaded"};
  if (it->second.state == "active")
    return {false, "Controller '" + name + "' can not be configured from 'active' state."};
  if (it->second.state == "inactive") {
    // ros2_control cleans it up and configures it again: mechsim builds it again.
    const bridge::BridgeResult r = model_.unload_controller(name);
    if (!r.ok) return {false, "Controller '" + name + "' could not be cleaned up: " + r.error};
    it->second.state = "unconfigured";
  }
  const bridge::BridgeResult r = model_.load_controller(name);
  if (!r.ok) return {false, "Failed to configure controller '" + name + "': " + r.error};
  it->second.state = "inactive";
  return {};
}

ControllerManagerNode::Result ControllerManagerNode::unload(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  sync();
  const auto it = records_.find(name);
  if (it == records_.end()) return {false, "Could not find controller with name '" + name + "'"};
  if (it->second.state == "active") return {false, "Controller '" + name + "' can not be unloaded while in active state."};
  if (it->second.state == "inactive") {
    const bridge::BridgeResult r = model_.unload_controller(name);
    if (!r.ok) return {false, "Controller '" + name + "' could not be unloaded: " + r.error};
  }
  records_.erase(it);
  controller_parameters_.erase(name);
  controller_nodes_.erase(name);
  return {};
}

ControllerManagerNode::Result ControllerManagerNode::switch_controllers(std::vector<std::string> activate,
                                                                         std::vector<std::string> deactivate,
                                                                         int strictness, double timeout) {
  std::lock_guard<std::mutex> lock(mutex_);
  sync();
  std::string notes;
  if (strictness != kStrict && strictness != kBestEffort) {
    notes = "strictness " + std::to_string(strictness) + " is neither STRICT (2) nor BEST_EFFORT (1): BEST_EFFORT; ";
    strictness = kBestEffort;
  }
  const bool strict = strictness == kStrict;
  const bool asked = !activate.empty() || !deactivate.empty();
  std::string refusal;
  auto keep = [&](std::vector<std::string>& list, bool activating) {
    std::vector<std::string> kept;
    for (const std::string& n : list) {
      const auto it = records_.find(n);
      std::string why;
      if (it == records_.end()) why = "Could not find controller with name '" + n + "'";
      else if (activating && it->second.state == "unconfigured") why = "Controller '" + n + "' is not configured";
      else if (activating && it->second.state == "active") why = "Controller '" + n + "' is already active";
      else if (!activating && it->second.state != "active") why = "Controller '" + n + "' is not active";
      if (why.empty()) kept.push_back(n);
      else if (strict) refusal += (refusal.empty() ? "" : "; ") + why;
      else notes += why + " (skipped); ";
    }
    list = kept;
  };
  keep(activate, true);
  keep(deactivate, false);
  if (!refusal.empty()) return {false, notes + refusal};
  if (activate.empty() && deactivate.empty()) {
    // Jazzy's manager fails a switch that asked for something and has nothing left to do;
    // Humble's answers ok.
    if (asked && model_.participant().distro() == Distro::Jazzy) return {false, notes + "nothing to switch"};
    return {true, notes};
  }
  // ros2_control's timeout 0 waits for ever; mechsim's switch waits at most 30 s.
  const double wait = timeout > 0.0 && std::isfinite(timeout) ? timeout : 30.0;
  const bridge::BridgeResult r = bridge_.switch_controllers(activate, deactivate, strict, wait);
  sync();
  if (!r.ok) return {false, notes + r.error};
  return {true, notes};
}

ControllerManagerNode::Result ControllerManagerNode::reload_libraries(bool force_kill) {
  std::unique_lock<std::mutex> lock(mutex_);
  sync();
  if (!records_.empty() && !force_kill)
    return {false, "Controller manager: Cannot reload controller libraries because there are still " +
                       std::to_string(records_.size()) + " controllers running. Unload them first or use force_kill"};
  std::vector<std::string> active, all;
  for (const auto& [name, r] : records_) {
    all.push_back(name);
    if (r.state == "active") active.push_back(name);
  }
  lock.unlock();
  if (!active.empty()) {
    const Result r = switch_controllers({}, active, kStrict, 5.0);
    if (!r.ok) return r;
  }
  for (const std::string& n : all) {
    const Result r = unload(n);
    if (!r.ok) return r;
  }
  return {};
}

std::vector<ControllerManagerNode::ControllerRow> ControllerManagerNode::list() {
  std::lock_guard<std::mutex> lock(mutex_);
  sync();
  std::map<std::string, bridge::ControllerSummary> built;
  for (const bridge::ControllerSummary& c : bridge_.list_controllers()) built[c.name] = c;
  std::vector<ControllerRow> rows;
  for (const auto& [name, r] : records_) {
    ControllerRow row;
    row.name = name;
    row.state = r.state;
    row.type = r.type;
    if (const auto b = built.find(name); b != built.end()) {
      for (const bridge::ClaimedResources& claim : b->second.claims) {
        for (const std::string& joint : claim.resources) {
          const std::string iface = joint + "/" + interface_name(claim.hardware_interface);
          row.required_command.push_back(iface);
          if (r.state == "active") row.claimed.push_back(iface);
          row.required_state.push_back(joint + "/position");
          row.required_state.push_back(joint + "/velocity");
        }
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void ControllerManagerNode::hardware_interfaces(std::vector<InterfaceRow>& command, std::vector<InterfaceRow>& state) {
  std::set<std::string> claimed, commanded;
  for (const ControllerRow& row : list()) {
    for (const std::string& c : row.claimed) claimed.insert(c);
    for (const std::string& c : row.required_command) commanded.insert(c);
  }
  for (const description::Joint& j : bridge_.robot().joints) {
    if (j.type == description::JointType::Fixed) continue;
    for (const char* kind : {"position", "velocity", "effort"}) state.push_back({j.name + "/" + kind, true, false});
    // Each moving joint takes effort (mechsim's actuators); position and velocity where a
    // controller of this robot commands them.
    for (const char* kind : {"effort", "position", "velocity"}) {
      const std::string name = j.name + "/" + kind;
      if (std::string(kind) != "effort" && commanded.count(name) == 0) continue;
      command.push_back({name, true, claimed.count(name) > 0});
    }
  }
}

std::string ControllerManagerNode::component_name() const { return bridge_.robot().name; }
std::string ControllerManagerNode::component_plugin() const { return "gazebo_ros2_control/GazeboSystem"; }

void ControllerManagerNode::advertise_common() {
  Node& n = *node_;
  Worker& w = *worker_;
  auto log = [this](const std::string& service, const Result& r) {
    if (!r.ok) model_.participant().log(node_->fq_name() + "/" + service + ": " + r.why);
    else if (!r.why.empty()) model_.participant().log(node_->fq_name() + "/" + service + ": " + r.why);
  };
  servers_.push_back(serve<cm::LoadController>(n, "~/load_controller", w, [this, log](const cm::LoadController::Request& q, cm::LoadController::Response& a) {
    const Result r = load(q.name);
    log("load_controller", r);
    a.ok = r.ok;
  }));
  servers_.push_back(serve<cm::ConfigureController>(n, "~/configure_controller", w, [this, log](const cm::ConfigureController::Request& q, cm::ConfigureController::Response& a) {
    const Result r = configure(q.name);
    log("configure_controller", r);
    a.ok = r.ok;
  }));
  servers_.push_back(serve<cm::UnloadController>(n, "~/unload_controller", w, [this, log](const cm::UnloadController::Request& q, cm::UnloadController::Response& a) {
    const Result r = unload(q.name);
    log("unload_controller", r);
    a.ok = r.ok;
  }));
  servers_.push_back(serve<cm::ReloadControllerLibraries>(n, "~/reload_controller_libraries", w, [this, log](const cm::ReloadControllerLibraries::Request& q, cm::ReloadControllerLibraries::Response& a) {
    const Result r = reload_libraries(q.force_kill);
    log("reload_controller_libraries", r);
    a.ok = r.ok;
  }));
  servers_.push_back(serve<cm::ListControllerTypes>(n, "~/list_controller_types", w, [this](const cm::ListControllerTypes::Request&, cm::ListControllerTypes::Response& a) {
    a.types = bridge_.list_controller_types();
    a.base_classes.assign(a.types.size(), "controller_interface::ControllerInterface");
  }));
  servers_.push_back(serve<cm::ListHardwareInterfaces>(n, "~/list_hardware_interfaces", w, [this](const cm::ListHardwareInterfaces::Request&, cm::ListHardwareInterfaces::Response& a) {
    std::vector<InterfaceRow> command, state;
    hardware_interfaces(command, state);
    for (const InterfaceRow& r : command) a.command_interfaces.push_back({r.name, r.available, r.claimed});
    for (const InterfaceRow& r : state) a.state_interfaces.push_back({r.name, r.available, r.claimed});
  }));
  servers_.push_back(serve<cm::SetHardwareComponentState>(n, "~/set_hardware_component_state", w, [this](const cm::SetHardwareComponentState::Request& q, cm::SetHardwareComponentState::Response& a) {
    a.state.id = State::PRIMARY_STATE_ACTIVE;
    a.state.label = "active";
    if (q.name != component_name()) {
      model_.participant().log(node_->fq_name() + "/set_hardware_component_state: hardware component '" + q.name +
                               "' not found (this robot's is '" + component_name() + "')");
      a.ok = false;
      a.state.id = State::PRIMARY_STATE_UNKNOWN;
      a.state.label = "unknown";
      return;
    }
    a.ok = q.target_state.id == State::PRIMARY_STATE_ACTIVE;
    if (!a.ok)
      model_.participant().log(node_->fq_name() + "/set_hardware_component_state: '" + q.name +
                               "' stays active: mechsim's simulated hardware cannot be deactivated, cleaned up or shut down");
  }));
}

template <class ListControllers>
void ControllerManagerNode::advertise_distro() {
  // The three services whose layout differs between Humble and Jazzy.
  using ListControllersReq = ListControllers;
  using Namespace = std::conditional_t<std::is_same_v<ListControllers, humble::controller_manager_msgs::srv::ListControllers>,
                                       std::integral_constant<int, 0>, std::integral_constant<int, 1>>;
  Node& n = *node_;
  Worker& w = *worker_;
  servers_.push_back(serve<ListControllersReq>(n, "~/list_controllers", w, [this](const typename ListControllersReq::Request&, typename ListControllersReq::Response& a) {
    for (const ControllerRow& row : list()) {
      auto& s = a.controller.emplace_back();
      s.name = row.name;
      s.state = row.state;
      s.type = row.type;
      s.claimed_interfaces = row.claimed;
      s.required_command_interfaces = row.required_command;
      s.required_state_interfaces = row.required_state;
    }
  }));
  if constexpr (Namespace::value == 0) {
    namespace d = humble::controller_manager_msgs::srv;
    servers_.push_back(serve<d::ListHardwareComponents>(n, "~/list_hardware_components", w, [this](const d::ListHardwareComponents::Request&, d::ListHardwareComponents::Response& a) {
      auto& c = a.component.emplace_back();
      c.name = component_name();
      c.type = "system";
      c.class_type = component_plugin();
      c.state.id = State::PRIMARY_STATE_ACTIVE;
      c.state.label = "active";
      std::vector<InterfaceRow> command, state;
      hardware_interfaces(command, state);
      for (const InterfaceRow& r : command) c.command_interfaces.push_back({r.name, r.available, r.claimed});
      for (const InterfaceRow& r : state) c.state_interfaces.push_back({r.name, r.available, r.claimed});
    }));
    servers_.push_back(serve<d::SwitchController>(n, "~/switch_controller", w, [this](const d::SwitchController::Request& q, d::SwitchController::Response& a) {
      // Humble still takes the deprecated start/stop lists (with a warning).
      std::vector<std::string> activate = q.activate_controllers, deactivate = q.deactivate_controllers;
      activate.insert(activate.end(), q.start_controllers.begin(), q.start_controllers.end());
      deactivate.insert(deactivate.end(), q.stop_controllers.begin(), q.stop_controllers.end());
      const Result r = switch_controllers(activate, deactivate, q.strictness, seconds_of(q.timeout));
      if (!r.why.empty()) model_.participant().log(node_->fq_name() + "/switch_controller: " + r.why);
      a.ok = r.ok;
    }));
  } else {
    namespace d = jazzy::controller_manager_msgs::srv;
    servers_.push_back(serve<d::ListHardwareComponents>(n, "~/list_hardware_components", w, [this](const d::ListHardwareComponents::Request&, d::ListHardwareComponents::Response& a) {
      auto& c = a.component.emplace_back();
      c.name = component_name();
      c.type = "system";
      c.plugin_name = component_plugin();
      c.state.id = State::PRIMARY_STATE_ACTIVE;
      c.state.label = "active";
      std::vector<InterfaceRow> command, state;
      hardware_interfaces(command, state);
      for (const InterfaceRow& r : command) c.command_interfaces.push_back({r.name, r.available, r.claimed});
      for (const InterfaceRow& r : state) c.state_interfaces.push_back({r.name, r.available, r.claimed});
    }));
    servers_.push_back(serve<d::SwitchController>(n, "~/switch_controller", w, [this](const d::SwitchController::Request& q, d::SwitchController::Response& a) {
      const Result r = switch_controllers(q.activate_controllers, q.deactivate_controllers, q.strictness, seconds_of(q.timeout));
      if (!r.why.empty()) model_.participant().log(node_->fq_name() + "/switch_controller: " + r.why);
      a.ok = r.ok;
    }));
  }
}

}  // namespace mechsim::ros2
