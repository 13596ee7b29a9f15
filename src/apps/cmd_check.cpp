// `mechsim check FILE [name:=value ...] [--package NAME=DIR ...] [--lenient] [--controllers YAML]`: expands (when the
// file is xacro), parses and validates a robot description and prints a summary, like ROS's
// check_urdf. Problems go to stderr through main's error path (exit status 1); warnings go to
// stderr with exit status 0.
//
// The command is a list of steps over one CheckContext: options are gathered in CheckOptions,
// the robot is loaded once, then each check of the loaded robot runs in turn (the summary, the
// meshes the physics would leave out, the controllers). A further check
// (`--controllers FILE.yaml` is one) adds its option in add_check_command and a step in run_check.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "apps/cmd_common.hpp"
#include "apps/commands.hpp"
#include "control/controller_check.hpp"
#include "control/ros2_params.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/ros2_control/ros2_controllers.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/direct_joints.hpp"
#include "physics/physics_model.hpp"
#include "physics/wheel_identify.hpp"
#include "sim/ros2_control_config.hpp"
#include "sim/simulation.hpp"
#include "description/robot_loader.hpp"
#include "description/robot_summary.hpp"
#include "description/ros2_control_plugin.hpp"

namespace mechsim::apps {

namespace {

struct CheckOptions {
  RobotArgs robot;
  std::string controllers;  // --controllers FILE.yaml, "" when not given
};

struct CheckContext {
  description::LoadedRobot robot;
  std::vector<std::string> warnings;  // from every step, printed at the end
  bool failed = false;                // a step found errors (exit status 1)
};

void load_step(const CheckOptions& options, CheckContext& context) {
  context.robot = description::load_robot(options.robot.file, load_options(options.robot));
  context.warnings.insert(context.warnings.end(), context.robot.warnings.begin(),
                          context.robot.warnings.end());
}

// A ros2_control robot's controllers: the ROS 2 parameter files (`--controllers`, or the
// description's gazebo_ros2_control <parameters>), the controller manager they configure (its
// node, update_rate) and every controller it declares, loaded against the mechanism with the
// ros2_controllers types.
void ros2_controllers_step(const CheckOptions& options, CheckContext& context, std::ostream& out) {
  const description::RobotModel& robot = context.robot.model;
  std::vector<std::string> files;
  if (!options.controllers.empty()) files.push_back(options.controllers);
  const sim::Ros2ControlConfig config = sim::load_ros2_control_config(robot, files);
  context.warnings.insert(context.warnings.end(), config.notes.begin(), config.notes.end());
  const mechanism::MechanismModel mechanism = mechanism::build_mechanism(robot);
  sim::fill_description_params(config.setup.controllers, robot, true);
  const control::ControllerPluginSet plugins = control::find_controller_plugins();
  const control::ControllerRegistry registry = control::ros2_controller_registry(plugins);
  for (const std::string& note : registry.notes()) context.warnings.push_back(note);
  const std::unique_ptr<control::SensorHardware> sensors = control::make_sensor_hardware(robot.sensors);
  const std::vector<control::ControllerCheck> checks =
      control::check_controllers(mechanism, config.setup.controllers, registry, sensors.get());
  std::string sources;
  for (const std::string& f : config.files) sources += (sources.empty() ? "" : ", ") + f;
  out << "ros2_control controller manager " << config.setup.controller_manager << " (" << sources << "):\n";
  out << "  update_rate " << config.setup.update_rate << " Hz" << (config.setup.update_rate_given ? "" : " (ros2_control's default)")
      << ", " << config.setup.controller_names.size() << " controllers declared\n";
  std::size_t loaded = 0;
  for (const control::ControllerCheck& c : checks) {
    out << "  " << control::describe(c) << "\n";
    if (c.ok()) ++loaded;
  }
  out << "  " << loaded << " of " << checks.size() << " controllers load\n";
  if (loaded != checks.size()) context.failed = true;
}

// Loads every controller of the YAML against the robot's mechanism (geometry the rover drive and
// the PR2 base take from the description filled in first) and prints what each claims.
void controllers_step(const CheckOptions& options, CheckContext& context, std::ostream& out) {
  const mechanism::MechanismModel mechanism = mechanism::build_mechanism(context.robot.model);
  const control::Params root = control::Params::from_yaml_file(options.controllers);
  sim::fill_description_params(root, context.robot.model);
  for (const std::string& key : root.keys()) {
    if (root.child(key).is_map() && !root.child(key).has("type")) sim::fill_description_params(root.child(key), context.robot.model);
  }
  const control::ControllerPluginSet plugins = control::find_controller_plugins();
  const control::ControllerRegistry registry = control::controller_registry_with_plugins(plugins);
  if (!plugins.files.empty()) {
    out << "controller plugins (" << plugins.classes.size() << " types from " << plugins.files.size() << " descriptions):\n";
    for (const control::ControllerPluginClass& p : plugins.classes) {
      out << "  " << p.name << " (" << p.type << " in " << p.library << "), " << p.origin << "\n";
    }
  }
  for (const std::string& note : registry.notes()) context.warnings.push_back(note);
  const std::unique_ptr<control::SensorHardware> sensors = control::make_sensor_hardware(context.robot.model.sensors);
  const std::vector<control::ControllerCheck> checks =
      control::check_controllers(mechanism, root, registry, sensors.get());
  std::size_t loaded = 0;
  std::vector<std::string> unsupported;  // each unknown type once, in document order
  out << "controllers (" << options.controllers << "):\n";
  for (const control::ControllerCheck& c : checks) {
    out << "  " << control::describe(c) << "\n";
    if (c.ok()) ++loaded;
    if (!c.type.empty() && !registry.has(c.type) &&
        std::find(unsupported.begin(), unsupported.end(), c.type) == unsupported.end()) {
      unsupported.push_back(c.type);
    }
  }
  out << "  " << loaded << " of " << checks.size() << " controllers load\n";
  if (!unsupported.empty()) {
    out << "  unsupported types (" << unsupported.size() << "):";
    for (const std::string& t : unsupported) out << " " << t;
    out << "\n";
  }
  if (checks.empty()) {
    std::cerr << "mechsim check: error: " << options.controllers << ": no controllers found (a controller is a map with a 'type')\n";
    context.failed = true;
  }
  if (loaded != checks.size()) context.failed = true;
}

// The mesh geoms the simulation's physics would leave out (a file it cannot find or read), once
// each with the link and the path tried, among the warnings.
void meshes_step(CheckContext& context) {
  try {
    const std::vector<std::string> w = physics::mesh_warnings(context.robot.model);
    context.warnings.insert(context.warnings.end(), w.begin(), w.end());
  } catch (const std::exception& e) {
    context.warnings.push_back(std::string("meshes not checked: ") + e.what());
  }
}

void summary_step(const CheckContext& context, std::ostream& out) {
  out << description::summarize_robot(context.robot.model);
}

// The wheels the wheel-soil model would act on (physics/wheel_identify.hpp), narrow or wide, and
// each link that looks like a wheel but is not one, with the reason: said once, here.
void wheels_step(const CheckContext& context, std::ostream& out) {
  const std::vector<physics::WheelCandidate> candidates = physics::identify_wheels(context.robot.model);
  if (candidates.empty()) return;
  out << "wheels (on a soil, world.soil; world.wheels overrides):\n";
  for (const physics::WheelCandidate& c : candidates) out << "  " << physics::describe(c) << "\n";
}

// Every model plugin, simulated or not (an unknown one is named here once and is not an error),
// then each simulated one configured as the simulation would: bad elements are errors naming the
// file, the line and the plugin.
void plugins_step(const CheckOptions& options, CheckContext& context, std::ostream& out) {
  const description::RobotModel& robot = context.robot.model;
  const std::vector<control::ModelPluginStatus> statuses = control::model_plugin_status(robot);
  if (statuses.empty()) return;
  // The description's file is the check's own; each plugin by its line.
  out << "model plugins:\n";
  for (const control::ModelPluginStatus& s : statuses) {
    const std::string line = s.origin.substr(s.origin.rfind(':') + 1);
    out << "  " << s.name << " (" << s.filename << "), line " << line << ": " << s.detail << "\n";
  }
  control::Params server;
  if (!options.controllers.empty()) server = control::Params::from_yaml_file(options.controllers);
  // The robot namespace, as the node reads it: the file's top when controllers are there, else the
  // first map below it (not gazebo_ros_control's pid_gains block, which sits beside controllers).
  const control::Params top = server;
  bool top_has_controllers = false;
  for (const std::string& key : top.keys()) top_has_controllers = top_has_controllers || (top.child(key).is_map() && top.child(key).has("type"));
  for (const std::string& key : top.keys()) {
    if (top_has_controllers) break;
    if (key != "gazebo_ros_control" && top.child(key).is_map() && !top.child(key).has("type")) {
      server = top.child(key);
      break;
    }
  }
  // Without the run's YAML the parameter server is not the run's: what plugins read from it at
  // run time (a mimic joint's PID gains) is named, not checked.
  control::PluginContext plugin_context{robot.name, server};
  plugin_context.runtime_params = !options.controllers.empty();
  try {
    std::vector<control::ModelPluginBuild> plugins = control::build_model_plugins(robot, plugin_context);
    mechanism::MechanismModel mechanism = mechanism::build_mechanism(robot);
    for (const control::ModelPluginBuild& b : plugins) mechanism::add_direct_joints(mechanism, robot, b.joints);
    mechanism::MechanismState state = mechanism::make_state(mechanism);
    state.base.floating = robot.root_link != "world";
    control::ControllerManager manager(mechanism, state, server, control::controller_registry_with_plugins());
    for (control::ModelPluginBuild& b : plugins) {
      const control::ControlResult r = manager.add_model_plugin(b.name, b.filename, std::move(b.controller), b.params, b.origin, 0.0);
      if (!r) {
        std::cerr << "mechsim check: error: " << r.error << "\n";
        context.failed = true;
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "mechsim check: error: " << e.what() << "\n";
    context.failed = true;
  }
  context.warnings.insert(context.warnings.end(), plugin_context.deferred->begin(), plugin_context.deferred->end());
}

void run_check(const CheckOptions& options, std::ostream& out, std::ostream& err, CommandResult& result) {
  CheckContext context;
  load_step(options, context);
  summary_step(context, out);
  wheels_step(context, out);
  plugins_step(options, context, out);
  meshes_step(context);
  // A ros2_control robot's controllers: from the ROS 2 file given, or from its plugin's files.
  const bool ros2_file = !options.controllers.empty() && control::is_ros2_parameter_file(options.controllers);
  const std::optional<description::Ros2ControlPlugin> ros2_plugin =
      description::find_ros2_control_plugin(context.robot.model);
  const bool plugin_files = ros2_plugin && !ros2_plugin->parameters.empty();
  if (ros2_file || (options.controllers.empty() && !context.robot.model.ros2_control.empty() && plugin_files)) {
    ros2_controllers_step(options, context, out);
  } else if (!options.controllers.empty()) {
    controllers_step(options, context, out);
  }
  for (const std::string& w : context.warnings) err << "warning: " << w << "\n";
  if (context.failed) {
    result.exit_code = 1;
    return;
  }
  out << "OK: " << options.robot.file << " is a valid robot description";
  if (!context.warnings.empty()) out << " (" << context.warnings.size() << " warnings)";
  if (!options.controllers.empty() || (plugin_files && !context.robot.model.ros2_control.empty())) {
    out << " and its controllers load";
  }
  out << "\n";
}

}  // namespace

void add_check_command(CLI::App& app, CommandResult& result) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check", "Expand (if xacro), parse and validate a robot description; print a summary");
  add_robot_options(cmd, options->robot);
  cmd->add_option("--controllers", options->controllers,
                  "a controller YAML (ROS 1, or a ROS 2 parameter file for a ros2_control robot): load each controller "
                  "against the robot and print what it claims");
  cmd->callback([options, &result] { run_check(*options, std::cout, std::cerr, result); });
}

}  // namespace mechsim::apps
