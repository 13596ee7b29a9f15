// controller_manager tool and unspawner: ros_control's `controller_manager` and `unspawner`
// scripts in C++, for the controller_manager compatibility package (one program; what it is
// follows the name it is run under).
//
//   controller_manager [--namespace NS] COMMAND [NAME ...]
//     list | list-types (lt) | load NAMES | unload NAMES | start NAMES | stop NAMES |
//     spawn NAMES (load + start) | kill NAMES (stop + unload) | reload-libraries [--restore]
//   unspawner [--namespace NS] [--shutdown-timeout S] NAMES
//     stops the controllers at start and starts them again when it is shut down (SIGINT).
//
// The services are <NS>/controller_manager/* (controller_manager_msgs), NS the --namespace or
// the node's own (roslaunch ns=, ROS_NAMESPACE), as ros_control's scripts resolve them. start and
// stop are STRICT switches. reload-libraries --restore stops and unloads every controller, reloads
// the libraries and loads them again, restarting those that ran (ros_control's behaviour).
// Exit status: 0 when every request succeeded, 1 when one failed (printed), 2 on bad arguments.
#include <csignal>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <ros/ros.h>

#include <controller_manager_msgs/ListControllerTypes.h>
#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/ReloadControllerLibraries.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>

namespace {

namespace cmm = controller_manager_msgs;

volatile std::sig_atomic_t g_signalled = 0;
extern "C" void on_signal(int) {
  if (g_signalled) ::ros::requestShutdown();
  g_signalled = 1;
}

[[noreturn]] void usage_error(const std::string& program, const std::string& what) {
  std::cerr << program << ": error: " << what << "\n";
  if (program == "unspawner") {
    std::cerr << "usage: unspawner [--namespace NS] [--shutdown-timeout S] CONTROLLER ...\n";
  } else {
    std::cerr << "usage: controller_manager [--namespace NS] {list|list-types|lt|load|unload|start|stop|spawn|kill|"
                 "reload-libraries [--restore]} [CONTROLLER ...]\n";
  }
  std::exit(2);
}

class Manager {
 public:
  explicit Manager(std::string ns) : ns_(std::move(ns)) {
    if (ns_.empty() || ns_.back() != '/') ns_ += "/";
  }
  std::string service(const std::string& name) const { return ns_ + "controller_manager/" + name; }

  template <class S>
  bool call(const std::string& name, S& srv, double timeout = 30.0) const {
    const std::string full = service(name);
    if (!::ros::service::waitForService(full, ::ros::Duration(timeout))) {
      std::cerr << "controller_manager: service " << full << " not available (is the controller manager up?)\n";
      return false;
    }
    if (!::ros::service::call(full, srv)) {
      std::cerr << "controller_manager: call to " << full << " failed\n";
      return false;
    }
    return true;
  }

  bool load(const std::string& name) const {
    cmm::LoadController srv;
    srv.request.name = name;
    const bool ok = call("load_controller", srv) && srv.response.ok;
    std::cout << (ok ? "Loaded " : "Error when loading ") << name << "\n";
    return ok;
  }
  bool unload(const std::string& name) const {
    cmm::UnloadController srv;
    srv.request.name = name;
    const bool ok = call("unload_controller", srv) && srv.response.ok;
    std::cout << (ok ? "Unloaded " : "Error when unloading ") << name << "\n";
    return ok;
  }
  bool switch_controllers(const std::vector<std::string>& start, const std::vector<std::string>& stop) const {
    cmm::SwitchController srv;
    srv.request.start_controllers = start;
    srv.request.stop_controllers = stop;
    srv.request.strictness = cmm::SwitchController::Request::STRICT;
    const bool ok = call("switch_controller", srv) && srv.response.ok;
    auto names = [](const std::vector<std::string>& v) {
      std::string s;
      for (const std::string& n : v) s += (s.empty() ? "" : ", ") + n;
      return s;
    };
    if (!start.empty()) std::cout << (ok ? "Started " : "Error when starting ") << names(start) << "\n";
    if (!stop.empty()) std::cout << (ok ? "Stopped " : "Error when stopping ") << names(stop) << "\n";
    return ok;
  }
  bool list(std::vector<cmm::ControllerState>& out) const {
    cmm::ListControllers srv;
    if (!call("list_controllers", srv)) return false;
    out = srv.response.controller;
    return true;
  }

 private:
  std::string ns_;
};

bool all(const std::vector<std::string>& names, const std::function<bool(const std::string&)>& each) {
  bool ok = true;
  for (const std::string& n : names) ok = each(n) && ok;
  return ok;
}

int run_tool(const Manager& m, const std::string& command, const std::vector<std::string>& names, bool restore) {
  if (command == "list") {
    std::vector<cmm::ControllerState> list;
    if (!m.list(list)) return 1;
    for (const cmm::ControllerState& c : list) std::cout << c.name << " - " << c.type << " ( " << c.state << " )\n";
    return 0;
  }
  if (command == "list-types" || command == "lt") {
    cmm::ListControllerTypes srv;
    if (!m.call("list_controller_types", srv)) return 1;
    for (const std::string& t : srv.response.types) std::cout << t << "\n";
    return 0;
  }
  if (command == "reload-libraries") {
    std::vector<cmm::ControllerState> before;
    if (restore) {
      if (!m.list(before)) return 1;
      std::vector<std::string> running;
      for (const cmm::ControllerState& c : before)
        if (c.state == "running") running.push_back(c.name);
      if (!running.empty() && !m.switch_controllers({}, running)) return 1;
      for (const cmm::ControllerState& c : before) m.unload(c.name);
    }
    cmm::ReloadControllerLibraries srv;
    srv.request.force_kill = false;
    const bool ok = m.call("reload_controller_libraries", srv) && srv.response.ok;
    std::cout << (ok ? "Successfully reloaded libraries" : "Failed to reload libraries") << "\n";
    if (!ok) return 1;
    if (restore) {
      std::vector<std::string> running;
      for (const cmm::ControllerState& c : before) {
        if (!m.load(c.name)) return 1;
        if (c.state == "running") running.push_back(c.name);
      }
      if (!running.empty() && !m.switch_controllers(running, {})) return 1;
      std::cout << "Controllers restored to original state\n";
    }
    return 0;
  }
  if (names.empty()) usage_error("controller_manager", command + " needs controller names");
  bool ok = false;
  if (command == "load") ok = all(names, [&](const std::string& n) { return m.load(n); });
  else if (command == "unload") ok = all(names, [&](const std::string& n) { return m.unload(n); });
  else if (command == "start") ok = m.switch_controllers(names, {});
  else if (command == "stop") ok = m.switch_controllers({}, names);
  else if (command == "spawn") ok = all(names, [&](const std::string& n) { return m.load(n); }) && m.switch_controllers(names, {});
  else if (command == "kill") ok = m.switch_controllers({}, names) && all(names, [&](const std::string& n) { return m.unload(n); });
  else usage_error("controller_manager", "unknown command '" + command + "'");
  return ok ? 0 : 1;
}

int run_unspawner(const Manager& m, const std::vector<std::string>& names, double shutdown_timeout) {
  if (!m.switch_controllers({}, names)) return 1;
  while (!g_signalled && ::ros::ok()) ::ros::WallDuration(0.1).sleep();
  // Back as they were; the services may be gone with the simulation.
  cmm::SwitchController srv;
  srv.request.start_controllers = names;
  srv.request.strictness = cmm::SwitchController::Request::STRICT;
  return m.call("switch_controller", srv, shutdown_timeout) && srv.response.ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::string program = argc > 0 ? argv[0] : "controller_manager";
  program = program.substr(program.find_last_of('/') + 1);
  const bool unspawner = program == "unspawner";
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  ::ros::init(argc, argv, unspawner ? "unspawner" : "controller_manager_tool",
              ::ros::init_options::AnonymousName | ::ros::init_options::NoSigintHandler);
  std::vector<std::string> args;
  ::ros::removeROSArgs(argc, argv, args);
  args.erase(args.begin());
  std::string ns = ::ros::this_node::getNamespace();
  double shutdown_timeout = 2.0;
  bool restore = false;
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const std::string& option) -> std::string {
      if (a.size() > option.size() && a[option.size()] == '=') return a.substr(option.size() + 1);
      if (i + 1 >= args.size()) usage_error(program, option + " needs a value");
      return args[++i];
    };
    if (a == "--namespace" || a.rfind("--namespace=", 0) == 0) ns = value("--namespace");
    else if (a == "--shutdown-timeout" || a.rfind("--shutdown-timeout=", 0) == 0) shutdown_timeout = std::stod(value("--shutdown-timeout"));
    else if (a == "--restore") restore = true;
    else if (a == "-h" || a == "--help") usage_error(program, "help requested");
    else if (a.rfind("--", 0) == 0) usage_error(program, "unknown option " + a);
    else rest.push_back(a);
  }
  const Manager manager(ns);
  if (unspawner) {
    if (rest.empty()) usage_error(program, "no controllers given");
    ::ros::AsyncSpinner spinner(1);
    spinner.start();
    return run_unspawner(manager, rest, shutdown_timeout);
  }
  if (rest.empty()) usage_error(program, "no command given");
  const std::string command = rest.front();
  rest.erase(rest.begin());
  return run_tool(manager, command, rest, restore);
}
