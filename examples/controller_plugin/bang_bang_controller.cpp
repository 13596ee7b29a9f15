// An example controller plugin: a bang-bang position controller for one effort joint. It applies
// +effort or -effort (N m or N), switching where a full brake at `braking_acceleration` would stop
// the joint on its target (the time-optimal switching curve of a double integrator), and nothing
// within `deadband` of it. Built against mechsim/controller_api.hpp only; see README.md.
//
//   finger_bang_bang:
//     type: mechsim_example_controllers/BangBangController
//     joint: left_finger_joint
//     effort: 0.05                # N m, > 0
//     braking_acceleration: 50    # rad/s^2 (or m/s^2), > 0; absent: switch on the position error alone
//     deadband: 0.01              # rad (or m), >= 0
//     setpoint: 0.3               # rad (or m); absent: hold where the joint is when started
//
// The target can be changed through the "command" input (a scenario's `command:`, the ROS topic
// <controller>/command); its state ("state": set point, position, error, effort) is published
// every update.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <mechsim/controller_api.hpp>

namespace mechsim_example {

namespace api = mechsim::controller_api;

class BangBangController final : public api::Controller {
 public:
  void init(api::Setup& setup) override {
    const api::Parameters& p = setup.params();
    effort_ = p.get_double("effort");
    if (!(effort_ > 0.0) || !std::isfinite(effort_)) {
      throw std::runtime_error(p.path() + "/effort must be finite and > 0, got " + std::to_string(effort_));
    }
    braking_ = p.get_double_or("braking_acceleration", std::numeric_limits<double>::infinity());
    if (!(braking_ > 0.0)) throw std::runtime_error(p.path() + "/braking_acceleration must be > 0");
    deadband_ = p.get_double_or("deadband", 0.01);
    if (!(deadband_ >= 0.0) || !std::isfinite(deadband_)) throw std::runtime_error(p.path() + "/deadband must be finite and >= 0");
    has_setpoint_ = p.has("setpoint");
    setpoint_ = p.get_double_or("setpoint", 0.0);
    joint_ = &setup.claim_joint(p.get_string("joint"), api::Interface::Effort, "joint");
    target_ = &setup.add_command_input(setpoint_);
    state_ = &setup.add_state_output();
  }

  void starting(double /*time*/) noexcept override { target_->reset(has_setpoint_ ? setpoint_ : joint_->position()); }

  api::Status update(double time, double period) noexcept override {
    const double target = target_->read();
    const double position = joint_->position();
    const double velocity = joint_->velocity();
    const double error = target - position;
    // Where the joint would stop if braked now, measured from the target.
    const double stopping = std::isinf(braking_) ? 0.0 : velocity * std::fabs(velocity) / (2.0 * braking_);
    const double s = error - stopping;
    const double command = s > deadband_ ? effort_ : (s < -deadband_ ? -effort_ : 0.0);
    joint_->set_command(command);
    state_->publish(time, period, api::ControllerState{target, position, velocity, error, command});
    return {};
  }

  void stopping(double /*time*/) noexcept override { joint_->set_command(0.0); }

 private:
  api::Joint* joint_ = nullptr;
  api::CommandInput* target_ = nullptr;
  api::StateOutput* state_ = nullptr;
  double effort_ = 0.0;
  double braking_ = 0.0;
  double deadband_ = 0.0;
  double setpoint_ = 0.0;
  bool has_setpoint_ = false;
};

}  // namespace mechsim_example

MECHSIM_CONTROLLER_LIBRARY({"mechsim_example::BangBangController",
                            mechsim::controller_api::create_controller<mechsim_example::BangBangController>})
