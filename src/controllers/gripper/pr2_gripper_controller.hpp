#pragma once
// pr2_mechanism_controllers/Pr2GripperController with the action semantics of pr2_gripper_action
// (control_msgs/GripperCommand). It claims the gripper's gap joint (r_gripper_joint: the
// distance between the finger tips, m, driven through the PR2GripperTransmission) on the effort
// interface and closes a position PID on the gap; the PID's effort is clamped to +-max_effort
// of the current command (no clamp when max_effort < 0, as the PR2).
//
// Each tick:
//   1. the newest of the plain command ("command" port) and the newest goal ("gripper_action")
//      becomes the command; a plain command or a newer goal preempts the active goal;
//   2. effort = clamp(pid(position - gap, -gap velocity, period), max_effort);
//   3. the active goal succeeds once |gap - position| < goal_threshold (reached_goal = true);
//      it aborts with stalled = true, reached_goal = false when the gap moved slower than
//      stall_velocity_threshold for stall_timeout seconds before that (an object in the way).
//      Either way the controller keeps holding the command: a stalled gripper keeps squeezing
//      with max_effort. A cancelled goal is Preempted and the last command is held as well.
//
// Parameters (under the controller's namespace; units in brackets):
//   type                      pr2_mechanism_controllers/Pr2GripperController
//   joint                     the gap joint, e.g. r_gripper_joint
//   pid                       {p, i, d, i_clamp, ...}  [N/m, N/(m s), N s/m]
//   goal_threshold            [m]   default 0.01 (pr2_gripper_action's)
//   stall_velocity_threshold  [m/s] default 0.001 (pr2_gripper_action uses 1e-6 on the real
//                             robot; a simulated gripper pressing on an object never rests so
//                             exactly)
//   stall_timeout             [s]   default 0.1
//   max_effort                [N]   max_effort of the command held at start, default -1 (none)
//
// Ports:
//   "command"         GripperCommandPort (pr2_controllers_msgs/Pr2GripperCommand)
//   "gripper_action"  GripperGoalPort (control_msgs/GripperCommand action)
//   "state"           StatePort<JointControllerState>: set point (m), gap (m), its rate (m/s),
//                     error = gap - set point (the PR2's sign), effort command (N), gains
//   "gains"           PidGainsPort
//
// starting() holds the measured gap with the max_effort parameter and resets the PID.

#include "control/controller.hpp"
#include "control/pid.hpp"
#include "controllers/gripper/pr2_gripper_ports.hpp"

namespace mechsim::control {

inline constexpr const char* kPr2GripperControllerType = "pr2_mechanism_controllers/Pr2GripperController";

class Pr2GripperController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override { return {&command_, &goals_, &state_, &gains_}; }

  GripperCommandPort& command_port() { return command_; }
  GripperGoalPort& goal_port() { return goals_; }
  StatePort<JointControllerState>& state_port() { return state_; }
  Pid& pid() { return pid_; }

 private:
  void finish_goal(GoalStatus status) noexcept;

  JointHandle joint_;
  Pid pid_;
  double goal_threshold_ = 0.01;
  double stall_velocity_threshold_ = 0.001;
  double stall_timeout_ = 0.1;
  double initial_max_effort_ = -1.0;

  GripperCommand active_;          // the command being held
  std::uint64_t last_command_seq_ = 0;
  std::uint64_t goal_id_ = 0;      // the active goal, 0 when none
  std::uint64_t last_goal_id_ = 0; // for feedback
  double stall_time_ = 0.0;        // s the gap has been still
  GripperResult result_;           // this tick's position, effort, stalled, reached_goal

  GripperCommandPort command_{"command"};
  GripperGoalPort goals_{"gripper_action"};
  StatePort<JointControllerState> state_{"state"};
  PidGainsPort gains_{"gains", &pid_};
};

}  // namespace mechsim::control
