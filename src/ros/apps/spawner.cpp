// mechsim_spawner (also `mechsim spawner`): ros_control's controller spawner in C++.
//
//   mechsim_spawner [--stopped] [--namespace NS] [--timeout S] [--wait-for TOPIC]
//                   [--shutdown-timeout S] CONTROLLER|FILE.yaml ...
// (each option also as --option=VALUE). It is also controller_manager's `spawner` and
// pr2_controller_manager's `spawner` in the compatibility packages (src/ros/packages).
//
// A YAML file is loaded to the parameter server under the namespace (as `rosparam load`) and
// each of its top-level keys becomes a controller to spawn. The spawner waits for
// <ns>/controller_manager/load_controller (at most --timeout s, default 30), loads every
// controller in order, then starts them all with one STRICT switch (unless --stopped), and
// waits. On SIGINT/SIGTERM it stops them (one STRICT switch) and unloads them in reverse order
// (each service waited for at most --shutdown-timeout s, default 2). Exit status 1 when a load
// or the switch fails (what it loaded is unloaded again), 2 when the ROS master restarted.
//
// The namespace: --namespace if given, else the node's own (launch `ns=`); service names are
// resolved relative to it, as the Python spawner does. Times are wall-clock (with use_sim_time
// a paused simulation would stop ros::Time).
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>
#include <yaml-cpp/yaml.h>

#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>

#include "ros/master_watch.hpp"

namespace {

namespace cmm = controller_manager_msgs;

// Set by SIGINT/SIGTERM: the one piece of process state a signal handler may touch. The first
// signal starts the teardown (which still needs ROS); a second one shuts ROS down, ending any
// wait, e.g. for an unreachable master (roslaunch follows SIGINT with SIGTERM).
volatile std::sig_atomic_t g_signalled = 0;
extern "C" void on_signal(int) {
  if (g_signalled) ::ros::requestShutdown();
  g_signalled = 1;
}

struct Args {
  bool stopped = false;
  std::string ns;
  double timeout = 30.0;
  double shutdown_timeout = 2.0;
  std::string wait_for;
  std::vector<std::string> items;
};

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "mechsim spawner: error: " << what << "\n"
            << "usage: mechsim spawner [--stopped] [--namespace NS] [--timeout S] [--wait-for TOPIC] "
               "[--shutdown-timeout S] CONTROLLER|FILE.yaml ...\n";
  std::exit(2);
}

double parse_seconds(const std::string& option, const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && v >= 0.0) return v;
  } catch (const std::exception&) {
  }
  usage_error(option + ": '" + text + "' is not a non-negative number of seconds");
}

Args parse(const std::vector<std::string>& argv) {
  Args a;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    // --option=value as well as --option value (ros_control's spawner parses with argparse).
    const std::string arg = argv[i];
    const auto eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
    const std::string s = arg.substr(0, eq);
    auto value = [&](const std::string& option) -> std::string {
      if (eq != std::string::npos) return arg.substr(eq + 1);
      if (i + 1 >= argv.size()) usage_error(option + " needs a value");
      return argv[++i];
    };
    if (s == "--stopped") a.stopped = true;
    else if (s == "--namespace") a.ns = value(s);
    else if (s == "--timeout") a.timeout = parse_seconds(s, value(s));
    else if (s == "--shutdown-timeout") a.shutdown_timeout = parse_seconds(s, value(s));
    else if (s == "--wait-for") a.wait_for = value(s);
    else if (s == "-h" || s == "--help") usage_error("help requested");
    else if (s.rfind("--", 0) == 0) usage_error("unknown option " + s);
    else a.items.push_back(s);
  }
  if (a.items.empty()) usage_error("no controllers given");
  return a;
}

XmlRpc::XmlRpcValue to_xmlrpc(const YAML::Node& node, const std::string& where) {
  if (node.IsMap()) {
    XmlRpc::XmlRpcValue v;
    v.begin();  // makes it a struct even when empty
    for (const auto& kv : node) v[kv.first.as<std::string>()] = to_xmlrpc(kv.second, where);
    return v;
  }
  if (node.IsSequence()) {
    XmlRpc::XmlRpcValue v;
    v.setSize(static_cast<int>(node.size()));
    for (std::size_t i = 0; i < node.size(); ++i) v[static_cast<int>(i)] = to_xmlrpc(node[i], where);
    return v;
  }
  if (!node.IsScalar()) throw std::runtime_error(where + ": line " + std::to_string(node.Mark().line + 1) + ": null value");
  const std::string text = node.Scalar();
  if (node.Tag() != "!") {  // unquoted: type by content, as rosparam does
    int i = 0;
    double d = 0.0;
    bool b = false;
    if (YAML::convert<int>::decode(node, i) && text.find_first_of(".eE") == std::string::npos) return XmlRpc::XmlRpcValue(i);
    if (YAML::convert<double>::decode(node, d)) return XmlRpc::XmlRpcValue(d);
    if (YAML::convert<bool>::decode(node, b)) return XmlRpc::XmlRpcValue(b);
  }
  return XmlRpc::XmlRpcValue(text);
}

// Loads a YAML file under `ns`; returns its top-level keys (the controllers).
std::vector<std::string> load_yaml(::ros::NodeHandle& nh, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read " + file + ": " + e.what());
  }
  if (!root.IsMap()) throw std::runtime_error(file + ": the top level must be a map of controllers");
  std::vector<std::string> names;
  for (const auto& kv : root) {
    const std::string key = kv.first.as<std::string>();
    nh.setParam(key, to_xmlrpc(kv.second, file));
    names.push_back(key);
  }
  return names;
}

// Waits for a service (timeout <= 0: forever); false on timeout, signal or ROS shutdown.
bool wait_for_service(const std::string& name, double timeout, bool interruptible = true) {
  const ::ros::WallTime deadline = ::ros::WallTime::now() + ::ros::WallDuration(timeout);
  while (::ros::ok() && !(interruptible && g_signalled)) {
    if (::ros::service::exists(name, false)) return true;
    if (timeout > 0.0 && ::ros::WallTime::now() > deadline) return false;
    ::ros::WallDuration(0.05).sleep();
  }
  return false;
}

class Spawner {
 public:
  Spawner(::ros::NodeHandle nh, std::string prefix) : nh_(std::move(nh)), prefix_(std::move(prefix)) {}
  std::string service(const std::string& name) const { return nh_.resolveName(prefix_ + "controller_manager/" + name); }

  bool load(const std::string& c) {
    cmm::LoadController srv;
    srv.request.name = c;
    if (!::ros::service::call(service("load_controller"), srv) || !srv.response.ok) {
      ROS_ERROR_STREAM("mechsim spawner: failed to load " << c);
      return false;
    }
    ROS_INFO_STREAM("mechsim spawner: loaded " << c);
    loaded_.push_back(c);
    return true;
  }
  bool switch_(const std::vector<std::string>& start, const std::vector<std::string>& stop) {
    cmm::SwitchController srv;
    srv.request.start_controllers = start;
    srv.request.stop_controllers = stop;
    srv.request.strictness = cmm::SwitchController::Request::STRICT;
    return ::ros::service::call(service("switch_controller"), srv) && srv.response.ok;
  }
  // Stops (when started) and unloads in reverse order what this spawner loaded.
  void teardown(bool started, double timeout) {
    if (loaded_.empty()) return;
    if (!wait_for_service(service("unload_controller"), timeout, /*interruptible=*/false)) {
      ROS_WARN_STREAM("mechsim spawner: controller manager gone; controllers left as they are");
      return;
    }
    if (started && !switch_({}, loaded_)) ROS_WARN_STREAM("mechsim spawner: could not stop the controllers");
    for (auto it = loaded_.rbegin(); it != loaded_.rend(); ++it) {
      cmm::UnloadController srv;
      srv.request.name = *it;
      if (!::ros::service::call(service("unload_controller"), srv) || !srv.response.ok) {
        ROS_WARN_STREAM("mechsim spawner: failed to unload " << *it);
      } else {
        ROS_INFO_STREAM("mechsim spawner: unloaded " << *it);
      }
    }
    loaded_.clear();
  }
  const std::vector<std::string>& loaded() const { return loaded_; }
  // Of `names`, those the controller manager lists as "waiting": their start is accepted but
  // not applied (mechsim applies a switch at the next tick, and a paused world does not tick).
  std::vector<std::string> waiting(const std::vector<std::string>& names) const {
    cmm::ListControllers srv;
    std::vector<std::string> out;
    if (!::ros::service::call(service("list_controllers"), srv)) return out;
    for (const auto& c : srv.response.controller) {
      if (c.state == "waiting" && std::find(names.begin(), names.end(), c.name) != names.end()) out.push_back(c.name);
    }
    return out;
  }

 private:
  ::ros::NodeHandle nh_;
  std::string prefix_;
  std::vector<std::string> loaded_;
};

bool wait_for_topic(const std::string& topic, double timeout) {
  ROS_INFO_STREAM("mechsim spawner: waiting for a message on " << topic);
  const ::ros::WallTime deadline = ::ros::WallTime::now() + ::ros::WallDuration(timeout);
  while (::ros::ok() && !g_signalled) {  // short waits, so that a signal is seen
    if (::ros::topic::waitForMessage<topic_tools::ShapeShifter>(topic, ::ros::Duration(0.2))) return true;
    if (timeout > 0.0 && ::ros::WallTime::now() > deadline) return false;
  }
  return false;
}

int run(int argc, char** argv) {
  ::ros::init(argc, argv, "mechsim_spawner", ::ros::init_options::AnonymousName | ::ros::init_options::NoSigintHandler);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  mechsim::ros::MasterWatch master;
  std::vector<std::string> rest;
  ::ros::removeROSArgs(argc, argv, rest);
  const Args args = parse(std::vector<std::string>(rest.begin() + 1, rest.end()));
  ::ros::NodeHandle nh;
  const std::string prefix = args.ns.empty() ? "" : (args.ns.back() == '/' ? args.ns : args.ns + "/");
  ::ros::NodeHandle param_nh(args.ns.empty() ? nh.getNamespace() : nh.resolveName(args.ns));

  std::vector<std::string> controllers;
  for (const std::string& item : args.items) {
    const bool yaml = item.size() > 5 && (item.compare(item.size() - 5, 5, ".yaml") == 0 ||
                                          item.compare(item.size() - 4, 4, ".yml") == 0);
    if (yaml) {
      for (const std::string& c : load_yaml(param_nh, item)) controllers.push_back(c);
    } else {
      controllers.push_back(item);
    }
  }

  Spawner spawner(nh, prefix);
  if (!args.wait_for.empty() && !wait_for_topic(args.wait_for, args.timeout)) {
    ROS_ERROR_STREAM("mechsim spawner: no message on " << args.wait_for << " within " << args.timeout << " s");
    return 1;
  }
  ROS_INFO_STREAM("mechsim spawner: waiting for " << spawner.service("load_controller"));
  if (!wait_for_service(spawner.service("load_controller"), args.timeout) ||
      !wait_for_service(spawner.service("switch_controller"), args.timeout)) {
    ROS_ERROR_STREAM("mechsim spawner: the controller manager did not come up within " << args.timeout
                                                                                       << " s (" << spawner.service("load_controller") << ")");
    return 1;
  }
  for (const std::string& c : controllers) {
    if (!spawner.load(c)) {
      spawner.teardown(false, args.shutdown_timeout);
      return 1;
    }
  }
  bool started = false;
  if (!args.stopped) {
    if (!spawner.switch_(controllers, {})) {
      ROS_ERROR_STREAM("mechsim spawner: the STRICT switch to start the controllers was refused");
      spawner.teardown(false, args.shutdown_timeout);
      return 1;
    }
    started = true;
    const std::vector<std::string> waiting = spawner.waiting(controllers);
    if (waiting.empty()) {
      ROS_INFO_STREAM("mechsim spawner: started " << controllers.size() << " controllers");
    } else {
      ROS_INFO_STREAM("mechsim spawner: loaded " << controllers.size() << " controllers; the simulation is paused: "
                                                 << waiting.size()
                                                 << " will start on unpause (/gazebo/unpause_physics; "
                                                    "list_controllers shows them 'waiting')");
    }
  }

  // Until a signal; a restarted master (master_watch.hpp) lost the controller manager's
  // registration with ours: nothing to tear down through it, exit status 2.
  for (int tick = 1; ::ros::ok() && !g_signalled; ++tick) {
    ::ros::WallDuration(0.1).sleep();
    if (tick % 10 == 0 && master.poll() == mechsim::ros::MasterWatch::State::Restarted) {
      ::ros::shutdown();
      return 2;
    }
  }
  const bool signalled = g_signalled != 0;
  if (signalled) spawner.teardown(started, args.shutdown_timeout);
  ::ros::shutdown();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Line by line into a log file too (roslaunch's output="log", a test's capture): INFO goes to
  // stdout, which is otherwise block-buffered when it is not a terminal.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "mechsim spawner: error: " << e.what() << "\n";
    return 1;
  }
}
