#pragma once
// The model plugin tests' rig: the test robot (controllers/test/test_robot.hpp: ideal servos) with
// two wheels, a caster, a pan joint and two fingers, its description with <gazebo> blocks, and a
// controller manager the plugins join through add_model_plugin.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "controllers/test/test_robot.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::control::plugin_test {

// A robot with two wheels, a caster, a pan joint and two fingers, and `plugins` (<gazebo> blocks).
inline std::string urdf(const std::string& plugins) {
  std::string joints;
  for (const char* j : {"left", "right", "pan", "finger_a", "finger_b", "rl", "rr"}) {
    joints += std::string("<joint name=\"") + j + "\" type=\"continuous\"><parent link=\"base\"/><child link=\"" + j +
              "_link\"/><axis xyz=\"0 1 0\"/></joint>\n<link name=\"" + j +
              "_link\"><inertial><mass value=\"0.1\"/><inertia ixx=\"1e-4\" ixy=\"0\" ixz=\"0\" iyy=\"1e-4\" iyz=\"0\" "
              "izz=\"1e-4\"/></inertial></link>\n";
  }
  return "<robot name=\"bot\">\n<link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" "
         "iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>\n" +
         joints + plugins + "</robot>\n";
}

inline description::RobotModel robot_with(const std::string& plugins) {
  return description::parse_urdf_string(urdf(plugins), "bot.urdf", {});
}

struct PluginRig {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  double time = 0.0;

  explicit PluginRig(const std::string& yaml = "bot: {}\n") {
    std::vector<testing::JointSpec> specs;
    for (const char* j : {"left", "right", "pan", "finger_a", "finger_b", "rl", "rr"}) {
      specs.push_back({j, description::JointType::Continuous});
    }
    robot = testing::make_robot(specs);
    robot->state.base.floating = true;
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml).child("bot"),
                                                  builtin_controller_registry());
  }
  // Adds every plugin of `plugins`; returns the first error, "" when all load.
  std::string add(const std::string& plugins, const Params& server = Params()) { return add(robot_with(plugins), server); }
  // The same from a description of the test robot's joints (with geometry of its own).
  std::string add(const description::RobotModel& description, const Params& server = Params()) {
    for (ModelPluginBuild& b : build_model_plugins(description, PluginContext{"bot", server})) {
      const ControlResult r = manager->add_model_plugin(b.name, b.filename, std::move(b.controller), b.params, b.origin, time);
      if (!r) return r.error;
    }
    return {};
  }
  template <class T>
  T* plugin(const std::string& name) {
    return dynamic_cast<T*>(manager->controller(name));
  }
  void run(int ticks) { time = testing::run(*manager, *robot, time, ticks); }
  // A joint's position as the encoders would report it.
  void set_position(const std::string& joint, double q) {
    robot->joint(joint).position = q;
    mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
  }
  // A joint's velocity as the encoders would report it (held by the test robot while no
  // controller commands the joint).
  void set_velocity(const std::string& joint, double v) {
    robot->joint(joint).velocity = v;
    mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
  }
  // The joint without a velocity limit (the test robot's limit rate-limits position commands, as
  // ros_control's does; a model plugin's joints in the simulation have none).
  void without_velocity_limit(const std::string& joint) {
    for (mechanism::JointInfo& j : robot->model.joints) {
      if (j.name == joint && j.limits) j.limits->velocity = 0.0;
    }
  }
  void send(const std::string& plugin, double vx, double vy, double wz) {
    auto* port = dynamic_cast<TwistCommandPort*>(manager->controller(plugin)->port("cmd_vel"));
    ASSERT_NE(port, nullptr);
    Twist t;
    t.linear.x = vx;
    t.linear.y = vy;
    t.angular.z = wz;
    ASSERT_TRUE(port->write(t));
  }
};

}  // namespace mechsim::control::plugin_test
