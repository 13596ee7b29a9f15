#include "sim/ros2_control_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mechsim::sim {

namespace {

std::string manager_node(const std::optional<description::Ros2ControlPlugin>& plugin, const std::string& node_namespace) {
  const std::string ns = description::normalize_ros2_namespace(
      !node_namespace.empty() ? node_namespace : (plugin ? plugin->ros_namespace : std::string()));
  const std::string name = plugin ? plugin->controller_manager_name : std::string("controller_manager");
  return (ns == "/" ? std::string() : ns) + "/" + name;
}

}  // namespace

Ros2ControlConfig ros2_control_config(const description::RobotModel& robot, control::Ros2ParameterSet parameters,
                                      const std::string& node_namespace) {
  Ros2ControlConfig out;
  out.plugin = description::find_ros2_control_plugin(robot);
  out.files = parameters.sources();
  out.parameters = std::move(parameters);
  out.setup = control::ros2_control_setup(out.parameters, manager_node(out.plugin, node_namespace));
  out.notes.insert(out.notes.end(), out.setup.notes.begin(), out.setup.notes.end());
  return out;
}

Ros2ControlConfig load_ros2_control_config(const description::RobotModel& robot, const std::vector<std::string>& files,
                                           const std::string& node_namespace) {
  std::vector<std::string> to_read = files;
  std::vector<std::string> notes;
  const std::optional<description::Ros2ControlPlugin> plugin = description::find_ros2_control_plugin(robot);
  if (to_read.empty()) {
    if (!plugin || plugin->parameters.empty()) {
      throw std::runtime_error(robot.source + ": no controller parameter file: give one, or name it in the description's " +
                               "gazebo_ros2_control plugin (<parameters>FILE.yaml</parameters>)");
    }
    for (std::size_t i = 0; i < plugin->parameters.size(); ++i) {
      if (!plugin->parameter_paths[i].empty()) {
        to_read.push_back(plugin->parameter_paths[i]);
      } else {
        notes.push_back(plugin->origin + ": " + plugin->filename + " <parameters>" + plugin->parameters[i] +
                        "</parameters>: no such file (from the working directory or beside the description)");
      }
    }
    if (to_read.empty()) {
      throw std::runtime_error(plugin->origin + ": none of the plugin's parameter files exists: " + notes.front());
    }
  }
  Ros2ControlConfig out = ros2_control_config(robot, control::Ros2ParameterSet::from_files(to_read), node_namespace);
  out.notes.insert(out.notes.begin(), notes.begin(), notes.end());
  return out;
}

std::uint64_t ros2_control_ticks(double update_rate, double period, std::string* note) {
  const long long n = std::llround(1.0 / (update_rate * period));
  const auto every = static_cast<std::uint64_t>(std::max(1LL, n));
  const double control_period = static_cast<double>(every) * period;
  char text[512] = {};
  if (1.0 / update_rate < period * (1.0 - 1e-9)) {
    std::snprintf(text, sizeof text, "controller manager update_rate %g Hz is faster than the simulation (period %g s): "
                  "the controllers update every tick", update_rate, period);
  } else if (std::abs(control_period - 1.0 / update_rate) > 1e-9 / update_rate) {
    std::snprintf(text, sizeof text, "controller manager update_rate %g Hz is not a whole number of periods (%g s): "
                  "the controllers update every %g s", update_rate, period, control_period);
  }
  if (note != nullptr) *note = text;
  return every;
}

void apply_ros2_control(SimulationOptions& options, const Ros2ControlConfig& config) {
  options.ros2_control = true;
  options.controller_update_rate = config.setup.update_rate;
}

}  // namespace mechsim::sim
