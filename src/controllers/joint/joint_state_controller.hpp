#pragma once
// joint_state_controller/JointStateController: reads every joint of the mechanism (claims
// nothing) and, at `publish_rate` (Hz, required, > 0), fills the "joint_states" port with a
// snapshot of names, positions, velocities and measured efforts, as sensor_msgs/JointState.
// A snapshot is due when more than 1/publish_rate has passed since the last one (the first
// one 1/publish_rate after starting), exactly ros_control's timing; the port's sequence()
// counts snapshots.

#include "control/controller.hpp"

namespace mechsim::control {

class JointStateController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&joint_states_}; }

  StatePort<JointStateSnapshot>& joint_states_port() { return joint_states_; }
  double publish_rate() const { return publish_rate_; }

 private:
  std::vector<JointStateHandle> joints_;
  double publish_rate_ = 0.0;       // Hz
  double last_publish_time_ = 0.0;  // s
  StatePort<JointStateSnapshot> joint_states_{"joint_states"};
};

}  // namespace mechsim::control
