#pragma once
// Effort controllers closing a PID loop around one joint (ros_controllers' effort_controllers
// and the PR2's robot_mechanism_controllers). Params: `joint`, and the gains under `pid`
// (control/pid.hpp). Ports: "command" (ScalarCommandPort: position in rad or m, or velocity in
// rad/s or m/s), "state" (JointControllerState), "gains" (PidGainsPort).
//
// Position: starting() holds the current position; the command is clamped into the joint's
// position limits; error = shortest angular distance on continuous joints, the plain
// difference otherwise; effort = pid(error, period) (the derivative from the error).
// Velocity: starting() commands 0; effort = pid(command - velocity, period).
// The PR2 flavour reads the same parameters and reports error = process value - set point, as
// pr2_controllers_msgs/JointControllerState does; it does not clamp the command (the PR2
// relies on its safety limits).

#include "control/controller.hpp"
#include "control/pid.hpp"

namespace mechsim::control {

enum class ControllerFlavour : std::uint8_t { RosControl, Pr2 };

// Fills one joint's controller state: time and period in s, the rest in the joint's units (set point and
// process value: position or velocity; command: effort).
void fill_joint_controller_state(JointControllerState& s, double time, double period, double set_point, double value,
                                 double value_dot, double error, double command, const PidGains& gains) noexcept;

// What the position and velocity controllers share: the joint (`joint`, claimed on the effort
// interface), its PID (gains under `pid`) and the three ports.
class SingleJointPidController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  std::vector<Port*> ports() override { return {&command_, &state_, &gains_}; }

  ScalarCommandPort& command_port() { return command_; }
  StatePort<JointControllerState>& state_port() { return state_; }
  Pid& pid() { return pid_; }

 protected:
  explicit SingleJointPidController(ControllerFlavour flavour) : flavour_(flavour) {}
  // Real-time: effort = pid(error, period) to the joint, then the state (the error reported
  // with the flavour's sign).
  void drive(double time, double period, double set_point, double value, double value_dot, double error) noexcept;

  ControllerFlavour flavour_;
  JointHandle joint_;
  Pid pid_;
  ScalarCommandPort command_{"command"};
  StatePort<JointControllerState> state_{"state"};
  PidGainsPort gains_{"gains", &pid_};
};

class JointPositionPidController : public SingleJointPidController {
 public:
  explicit JointPositionPidController(ControllerFlavour flavour = ControllerFlavour::RosControl)
      : SingleJointPidController(flavour) {}
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;

 private:
  double limit(double command) const noexcept;
};

class JointVelocityPidController : public SingleJointPidController {
 public:
  explicit JointVelocityPidController(ControllerFlavour flavour = ControllerFlavour::RosControl)
      : SingleJointPidController(flavour) {}
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
};

// effort_controllers/JointGroupPositionController: params `joints`, one PID per joint under
// `<joint>/pid`. Ports: "command" (ArrayCommandPort of positions), "state"
// (JointGroupControllerState).
class JointGroupPositionPidController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override;

  ArrayCommandPort& command_port() { return *command_; }
  StatePort<JointGroupControllerState>& state_port() { return state_; }
  Pid& pid(std::size_t joint_index) { return *pids_[joint_index]; }

 private:
  std::vector<JointHandle> joints_;
  std::vector<std::unique_ptr<Pid>> pids_;
  std::vector<std::unique_ptr<PidGainsPort>> gains_;  // "gains/<joint>"
  std::vector<double> scratch_;                        // sized at init
  std::unique_ptr<ArrayCommandPort> command_;
  StatePort<JointGroupControllerState> state_{"state"};
};

}  // namespace mechsim::control
