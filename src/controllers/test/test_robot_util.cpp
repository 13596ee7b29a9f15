#include "controllers/test/test_robot.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "mechanism/propagation.hpp"
#include "mechanism/simple_transmission.hpp"

namespace mechsim::control::testing {

std::unique_ptr<TestRobot> make_robot(const std::vector<JointSpec>& joints) {
  auto robot = std::make_unique<TestRobot>();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const JointSpec& spec = joints[i];
    mechanism::JointInfo info;
    info.name = spec.name;
    info.type = spec.type;
    info.continuous = spec.type == description::JointType::Continuous;
    if (!info.continuous) info.limits = spec.limits;
    if (info.continuous && spec.limits) info.limits = description::JointLimits{0.0, 0.0, spec.limits->effort, spec.limits->velocity};
    info.interfaces = spec.interfaces;
    info.transmission = static_cast<int>(i);
    robot->model.joints.push_back(info);
    robot->model.actuators.push_back(mechanism::ActuatorInfo{spec.name + "_motor", static_cast<int>(i)});
    robot->model.transmissions.push_back(std::make_unique<mechanism::SimpleTransmission>(
        spec.name + "_trans", "transmission_interface/SimpleTransmission", static_cast<int>(i), static_cast<int>(i),
        spec.reduction));
  }
  robot->state = mechanism::make_state(robot->model);
  return robot;
}

std::unique_ptr<TestRobot> make_robot(std::size_t n) {
  std::vector<JointSpec> specs;
  for (std::size_t i = 0; i < n; ++i) specs.push_back(JointSpec{std::string("j").append(std::to_string(i))});
  return make_robot(specs);
}

mechanism::JointState& TestRobot::joint(const std::string& name) {
  const int i = model.joint_index(name);
  if (i < 0) throw std::invalid_argument("no joint " + name);
  return state.joints[static_cast<std::size_t>(i)];
}

void TestRobot::step(double dt) {
  mechanism::propagate_actuator_to_joint_effort(model, state);
  for (mechanism::JointState& j : state.joints) {
    switch (j.command_mode) {
      case HardwareInterface::Effort:
        j.velocity += j.commanded_effort / mass * dt;
        j.position += j.velocity * dt;
        j.measured_effort = j.commanded_effort;
        break;
      case HardwareInterface::Velocity:  // an ideal velocity servo
        j.velocity = j.commanded_velocity;
        j.position += j.velocity * dt;
        break;
      case HardwareInterface::Position: {  // an ideal position servo
        const double before = j.position;
        j.position = j.commanded_position;
        j.velocity = (j.position - before) / dt;
        break;
      }
    }
  }
  mechanism::propagate_joint_to_actuator_position(model, state);
}

double run(ControllerManager& manager, TestRobot& robot, double time, int ticks, double dt) {
  for (int k = 0; k < ticks; ++k) {
    manager.update(time, dt);
    robot.step(dt);
    time += dt;
  }
  return time;
}

Controller* load_and_start(ControllerManager& manager, const std::string& name) {
  const ControlResult r = manager.load_controller(name);
  EXPECT_TRUE(r.ok) << r.error;
  const SwitchResult s = manager.switch_controllers({name}, {}, SwitchStrictness::Strict);
  EXPECT_TRUE(s.ok) << s.error;
  return manager.controller(name);
}

}  // namespace mechsim::control::testing
