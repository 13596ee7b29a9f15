#pragma once
// A ros2_control robot's controller configuration, as gazebo_ros2_control (or gz_ros2_control)
// gathers it: the ROS 2 parameter files (given, or else the plugin's <parameters>), the
// controller manager's node (the plugin's <ros><namespace> and <controller_manager_name>, or a
// namespace given), its update_rate and the controllers it declares
// (control::ros2_control_setup). Whoever builds a simulation from ROS 2 inputs (a scenario,
// mechsim check, the bridge) uses this, then apply_ros2_control on the simulation's options.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "control/ros2_params.hpp"
#include "description/robot_model.hpp"
#include "description/ros2_control_plugin.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

struct Ros2ControlConfig {
  std::optional<description::Ros2ControlPlugin> plugin;  // the description's, when it has one
  std::vector<std::string> files;                        // the parameter files read, in order
  control::Ros2ParameterSet parameters;                  // all of them
  control::Ros2ControlSetup setup;                       // the controller manager's part
  std::vector<std::string> notes;                        // warnings (setup's, plugin files not found)
};

// `files`: the parameter files to read; empty: the plugin's (each that resolves; one that does
// not is a note; none at all is an error). `node_namespace`: the manager's namespace ("" : the
// plugin's). Throws std::runtime_error naming the file and line (control::ParamsError), or what
// is missing.
Ros2ControlConfig load_ros2_control_config(const description::RobotModel& robot, const std::vector<std::string>& files,
                                           const std::string& node_namespace = "");
// The same, over parameters already loaded (the wire layer's, or a test's).
Ros2ControlConfig ros2_control_config(const description::RobotModel& robot, control::Ros2ParameterSet parameters,
                                      const std::string& node_namespace = "");

// The controller manager updates every N ticks for ros2_control's `update_rate` (Hz) at `period`
// (s): N = round(1 / (rate * period)), at least 1, as gazebo_ros2_control updates once the control
// period has passed. `note`: why the period differs from 1/rate (faster than the simulation, or
// not a whole number of periods), "" when it does not.
std::uint64_t ros2_control_ticks(double update_rate, double period, std::string* note);

// Sets options.ros2_control and controller_update_rate from `config`.
void apply_ros2_control(SimulationOptions& options, const Ros2ControlConfig& config);

}  // namespace mechsim::sim
