#pragma once
// position_controllers/GripperActionController and effort_controllers/GripperActionController with
// ros_controllers' gripper_action_controller semantics: one joint, driven to the goal of a
// control_msgs/GripperCommand action (position, rad or m; max_effort, N m or N).
//
// Each tick (the order of ros_controllers' update):
//   1. goal monitoring, against the command in force: |position error| < goal_tolerance ->
//      Succeeded (reached_goal); else, while |velocity| stays at or below
//      stall_velocity_threshold for more than stall_timeout s -> Aborted (stalled). The result
//      carries the joint's position and the effort of the previous command;
//   2. the command: position interface: the goal position as the joint's position command (the
//      effort reported is max_effort: the physics' servo is bounded by the joint's effort limit,
//      not by max_effort, as gazebo_ros_control's position joints); effort interface: a PID on the
//      position error (gains/<joint>) with the velocity as its derivative, clamped to
//      +-|max_effort|.
// A new goal preempts the active one; a cancel preempts it and holds the current position with
// the default max_effort; an aborted (stalled) goal's command stays: the gripper keeps squeezing.
// starting(): hold the current position with the default max_effort; stopping(): the active goal
// is preempted.
//
// Parameters (ros_controllers' names and defaults):
//   joint                     the gripper's joint
//   goal_tolerance            0.01 (rad or m)
//   max_effort                0.0  the default max_effort (hold; N m or N)
//   stall_velocity_threshold  0.001 (rad/s or m/s)
//   stall_timeout             1.0 (s)
//   gains/<joint>             {p, i, d, i_clamp, ...}: effort_controllers only, required
//   action_monitor_rate       not read: the ROS binding relays feedback and results at 20 Hz (wall)
// Ports: "gripper_cmd" GripperGoalPort (control_msgs/GripperCommandAction), "state"
// StatePort<JointControllerState> (set point, position, error, command).

#include "control/controller.hpp"
#include "control/pid.hpp"
#include "controllers/gripper/pr2_gripper_ports.hpp"

namespace mechsim::control {

inline constexpr const char* kPositionGripperActionType = "position_controllers/GripperActionController";
inline constexpr const char* kEffortGripperActionType = "effort_controllers/GripperActionController";

class GripperActionController : public Controller {
 public:
  explicit GripperActionController(HardwareInterface iface) : iface_(iface) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override { return {&goals_, &state_}; }

  GripperGoalPort& goal_port() { return goals_; }

 private:
  void finish_goal(GoalStatus status) noexcept;
  void hold(double time) noexcept;

  HardwareInterface iface_;
  JointHandle joint_;
  Pid pid_;  // effort interface
  double goal_tolerance_ = 0.01, default_max_effort_ = 0.0;
  double stall_velocity_threshold_ = 0.001, stall_timeout_ = 1.0;
  GripperCommand command_;          // in force
  double computed_command_ = 0.0;   // N m or N: the last effort written (position: max_effort)
  double last_movement_ = 0.0;      // s
  std::uint64_t goal_id_ = 0, last_goal_id_ = 0;
  GripperResult result_;
  GripperGoalPort goals_{"gripper_cmd"};
  StatePort<JointControllerState> state_{"state"};
};

}  // namespace mechsim::control
