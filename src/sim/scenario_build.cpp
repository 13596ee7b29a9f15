// build_simulation: a scenario's simulation (scenario_build.hpp).
#include "sim/scenario_build.hpp"

#include <vector>

#include "control/params.hpp"
#include "control/params_edit.hpp"
#include "description/camera_override.hpp"
#include "description/robot_loader.hpp"
#include "description/sensor_spec.hpp"
#include "description/urdf/sensor_reader.hpp"
#include "sim/ros2_control_config.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {

std::unique_ptr<Simulation> build_simulation(const Scenario& s, std::string& urdf) {
  description::LoadOptions load;
  load.xacro_args = s.xacro_args;
  load.packages = s.packages;
  load.lenient = s.lenient;
  description::LoadedRobot robot;
  try {
    robot = description::load_robot(s.description, load);
  } catch (const std::exception& e) {
    throw ScenarioError(s.file + ": robot: " + e.what());
  }
  urdf = robot.urdf;
  // Sensors the scenario adds (its `sensors:` blocks), read as the URDF's own.
  for (const SensorBlock& block : s.sensor_blocks) {
    try {
      std::vector<description::SensorSpec> specs = description::read_sensor_blocks(block.xml, robot.model, block.file, block.line);
      robot.model.sensors.insert(robot.model.sensors.end(), specs.begin(), specs.end());
    } catch (const std::exception& e) {
      throw ScenarioError(std::string("sensors: ") + e.what());
    }
  }
  if (!s.camera_overrides.empty()) {
    try {
      description::apply_camera_overrides(robot.model, s.camera_overrides);
    } catch (const std::exception& e) {
      throw ScenarioError(std::string("camera_overrides: ") + e.what());
    }
  }
  World world;
  try {
    WorldConfig config = s.world;
    world = make_world(config);
    for (const physics::WorldBox& b : s.boxes) {
      for (const physics::WorldBox& other : world.spec.boxes) {
        if (other.name == b.name) throw ScenarioError("box '" + b.name + "' is already in world '" + world.name + "'");
      }
      world.spec.boxes.push_back(b);
    }
  } catch (const std::exception& e) {
    throw ScenarioError(s.file + ": world: " + e.what());
  }
  control::Params params;
  control::Params root;  // the whole file: gazebo_ros_control's legacy pid_gains are at its top
  std::optional<Ros2ControlConfig> ros2;
  try {
    if (s.ros2_control) {
      std::vector<std::string> files = s.controllers_files;
      if (!s.controllers_file.empty()) files.insert(files.begin(), s.controllers_file);
      ros2 = load_ros2_control_config(robot.model, files, s.controllers_namespace);
      params = ros2->setup.controllers;
    } else if (!s.controllers_file.empty()) {
      params = control::Params::from_yaml_file(s.controllers_file);
    }
    root = params;
    if (!s.ros2_control && !s.controllers_namespace.empty()) params = params.child(s.controllers_namespace);
    for (const ControllerParam& p : s.controller_params) control::replace(params, p.key, p.value);
  } catch (const std::exception& e) {
    throw ScenarioError(s.file + ": controllers: " + e.what());
  }
  SimulationOptions options;
  if (ros2) apply_ros2_control(options, *ros2);
  options.period = s.period;
  options.integrator = s.integrator;
  options.spawn = s.spawn;
  options.settle_on_ground = s.settle_on_ground;
  options.differential = s.differential;
  // Initial joint positions (Gazebo's spawn_model -J): set before the first tick, so the
  // controllers starting in it hold them.
  options.initial_joints = s.initial_joints;
  options.sensor_seed = s.seed;
  options.parameter_root = root;
  std::vector<OtherRobot> others;
  for (const OtherRobotConfig& c : s.others) {
    const std::string where = s.file + ": others: " + c.name + ": ";
    OtherRobot o;
    o.name = c.name;
    o.spawn = c.spawn;
    o.initial_joints = c.initial_joints;
    try {
      description::LoadOptions other_load;
      other_load.xacro_args = c.xacro_args;
      other_load.packages = c.packages;
      other_load.lenient = c.lenient;
      o.robot = description::load_robot(c.description, other_load).model;
    } catch (const std::exception& e) {
      throw ScenarioError(where + "robot: " + e.what());
    }
    try {
      if (c.ros2_control) {
        std::vector<std::string> files = c.controllers_files;
        if (!c.controllers_file.empty()) files.insert(files.begin(), c.controllers_file);
        // Its own manager: in its own namespace unless the scenario names one (as spawn_entity's
        // -robot_namespace puts each spawned robot's plugins in its namespace).
        const Ros2ControlConfig config =
            load_ros2_control_config(o.robot, files, c.controllers_namespace.empty() ? "/" + c.name : c.controllers_namespace);
        o.controllers = config.setup.controllers;
        o.ros2_control = true;
        o.controller_update_rate = config.setup.update_rate;
      } else if (!c.controllers_file.empty()) {
        o.controllers = control::Params::from_yaml_file(c.controllers_file);
      }
      o.parameter_root = o.controllers;
      if (!c.ros2_control && !c.controllers_namespace.empty()) o.controllers = o.controllers.child(c.controllers_namespace);
    } catch (const std::exception& e) {
      throw ScenarioError(where + "controllers: " + e.what());
    }
    others.push_back(std::move(o));
  }
  try {
    auto sim = std::make_unique<Simulation>(std::move(robot.model), world, params, options, std::move(others));
    if (ros2) {
      for (const std::string& note : ros2->notes) sim->add_note(note);
    }
    sim->load_and_start(s.start);
    for (std::size_t i = 0; i < s.others.size(); ++i) {
      try {
        sim->other(i).load_and_start(s.others[i].start);
      } catch (const std::exception& e) {
        throw ScenarioError("others: " + s.others[i].name + ": " + e.what());
      }
    }
    return sim;
  } catch (const std::exception& e) {
    throw ScenarioError(s.file + ": " + e.what());
  }
}

}  // namespace mechsim::sim
