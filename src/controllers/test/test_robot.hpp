#pragma once
// Test fixture: a hand-built mechanism (one SimpleTransmission per joint) and a tiny physics
// (each joint a unit mass or inertia, integrated with semi-implicit Euler) to close loops.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/controller_manager.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::control::testing {

struct JointSpec {
  std::string name;
  description::JointType type = description::JointType::Revolute;
  std::optional<description::JointLimits> limits = description::JointLimits{-3.0, 3.0, 100.0, 10.0};
  std::vector<HardwareInterface> interfaces = {HardwareInterface::Effort, HardwareInterface::Position,
                                               HardwareInterface::Velocity};
  double reduction = 1.0;
};

struct TestRobot {
  mechanism::MechanismModel model;
  mechanism::MechanismState state;
  double mass = 1.0;  // kg or kg m^2, every joint

  // One physics step of `dt` seconds after a manager tick: actuator commands back to the
  // joints, integrate, joint state forward to the actuators (what the encoders report).
  void step(double dt);
  mechanism::JointState& joint(const std::string& name);
};

std::unique_ptr<TestRobot> make_robot(const std::vector<JointSpec>& joints);
// `n` revolute joints named j0, j1, ...
std::unique_ptr<TestRobot> make_robot(std::size_t n);

// Runs `ticks` manager ticks at `dt`, each followed by a physics step, from `time`. Returns the
// time after the last tick.
double run(ControllerManager& manager, TestRobot& robot, double time, int ticks, double dt = 0.001);

// Loads `name` and starts it (a failed load or switch fails the test, naming the error); returns
// the controller, null when it did not load.
Controller* load_and_start(ControllerManager& manager, const std::string& name);

}  // namespace mechsim::control::testing
