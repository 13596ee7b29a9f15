#pragma once
// ros_controllers' forward_command_controller family: the command is written to the joint's
// hardware interface as it is.
//   effort_controllers/JointEffortController, position_controllers/JointPositionController,
//   velocity_controllers/JointVelocityController, robot_mechanism_controllers/JointEffortController
//     params: joint. Ports: "command" (ScalarCommandPort), "state" (JointControllerState).
//   effort_controllers/JointGroupEffortController, position_controllers/JointGroupPositionController,
//   velocity_controllers/JointGroupVelocityController
//     params: joints. Ports: "command" (ArrayCommandPort, one value per joint), "state".
//   forward_command_controller/ForwardCommandController (ros2_controllers)
//     params: joints, interface_name (position, velocity or effort). Ports as the group ones.
// starting(): position controllers hold the current position; effort and velocity controllers
// start from 0 (as ros_controllers does; ros2_controllers writes nothing until the first command,
// which leaves Gazebo's command at its last value).

#include <memory>
#include <vector>

#include "control/controller.hpp"

namespace mechsim::control {

class JointCommandController : public Controller {
 public:
  explicit JointCommandController(HardwareInterface iface) : iface_(iface) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&command_, &state_}; }

  ScalarCommandPort& command_port() { return command_; }
  StatePort<JointControllerState>& state_port() { return state_; }

 private:
  HardwareInterface iface_;
  JointHandle joint_;
  ScalarCommandPort command_{"command"};
  StatePort<JointControllerState> state_{"state"};
};

class JointGroupCommandController : public Controller {
 public:
  explicit JointGroupCommandController(HardwareInterface iface) : iface_(iface) {}
  // ros2_controllers' ForwardCommandController: the interface from `interface_name`.
  JointGroupCommandController() : interface_from_params_(true) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {command_.get(), &state_}; }

  ArrayCommandPort& command_port() { return *command_; }
  StatePort<JointGroupControllerState>& state_port() { return state_; }

 private:
  HardwareInterface iface_ = HardwareInterface::Effort;
  bool interface_from_params_ = false;
  std::vector<JointHandle> joints_;
  std::vector<double> start_values_;  // scratch for starting(), sized at init
  std::unique_ptr<ArrayCommandPort> command_;
  StatePort<JointGroupControllerState> state_{"state"};
};

// The measured quantity an interface commands: position, velocity or effort.
double process_value(const JointHandle& joint) noexcept;

}  // namespace mechsim::control
