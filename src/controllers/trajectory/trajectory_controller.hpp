#pragma once
// Joint trajectory controllers: ros_controllers' joint_trajectory_controller in its effort,
// position and velocity variants, and the PR2's robot_mechanism_controllers/
// JointTrajectoryActionController (an effort controller).
//
// Parameters (ros_control types, e.g. effort_controllers/JointTrajectoryController):
//   joints                         list of joint names (required)
//   gains/<joint>/{p,i,d,i_clamp,...}  PID per joint (control/pid.hpp); effort and velocity only
//   velocity_ff/<joint>            feed-forward gain on the desired velocity (default 0);
//                                  effort and velocity only
//   constraints/goal_time, constraints/stopped_velocity_tolerance,
//   constraints/<joint>/trajectory, constraints/<joint>/goal   (trajectory_tolerances.hpp)
//   state_publish_rate             Hz, the "state" port (default 50; 0: every update)
//   action_monitor_rate            Hz, goal feedback (default 20; 0: every update)
//   stop_trajectory_duration       s, how long a stop (cancel, abort, start) takes to bring the
//                                  joints to rest (default 0: hold the measured position at once)
//   allow_partial_joints_goal      bool (default false, as ros_control)
//   max_trajectory_points          mechsim's own: the storage reserved at init (default 500);
//                                  a longer trajectory is rejected with INVALID_GOAL
// The PR2 type reads `joints`, `gains/<joint>` and its tolerances from
// `joint_trajectory_action_node/constraints` (falling back to `constraints`), and reports
// errors as actual - desired as pr2_controllers_msgs does; everything else is shared.
//
// Control law per joint, with e = desired - actual (continuous joints: the shortest angular
// distance) and the desired state sampled from the trajectory at the update's time:
//   effort:   effort   = pid(e_position, e_velocity, period) + velocity_ff * desired velocity
//   velocity: velocity = pid(e_position, e_velocity, period) + velocity_ff * desired velocity
//   position: position = desired position
//
// Ports: "command" (TrajectoryCommandPort), "follow_joint_trajectory" (TrajectoryGoalPort),
// "state" (StatePort<JointTrajectoryControllerState>), "query_state" (TrajectoryQueryPort),
// "gains/<joint>" (PidGainsPort, PID variants). starting() holds the current position; so does the end of a cancelled or aborted
// goal. A finished trajectory holds its last point. update() neither allocates nor throws.

#include <memory>
#include <vector>

#include "control/controller.hpp"
#include "control/pid.hpp"
#include "controllers/joint/pid_joint_controllers.hpp"
#include "controllers/trajectory/trajectory.hpp"
#include "controllers/trajectory/trajectory_goal.hpp"
#include "controllers/trajectory/trajectory_query.hpp"

namespace mechsim::control {

constexpr std::size_t kDefaultMaxTrajectoryPoints = 500;

class JointTrajectoryController : public Controller {
 public:
  explicit JointTrajectoryController(HardwareInterface iface,
                                     ControllerFlavour flavour = ControllerFlavour::RosControl)
      : iface_(iface), flavour_(flavour) {}
  // joint_trajectory_controller/JointTrajectoryController: the interface comes from the
  // parameters, `hardware_interface` ("EffortJointInterface", "hardware_interface/
  // PositionJointInterface", ...) or ROS 2's `command_interfaces: [effort|position|velocity]`;
  // effort when neither is given.
  JointTrajectoryController() : iface_(HardwareInterface::Effort), flavour_(ControllerFlavour::RosControl), generic_(true) {}
  // ros2_controllers' joint_trajectory_controller/JointTrajectoryController (Humble, Jazzy), with
  // its parameters (controllers/ros2_control/README: what applies):
  //   joints (required), command_joints (empty or equal to joints)
  //   command_interfaces (required): [position], [position, velocity], [position, velocity,
  //     acceleration] command positions (Gazebo's systems give position precedence; the joints
  //     must offer each interface listed); [velocity] and [effort] the PID law above
  //   state_interfaces (required): position, and velocity (required with [velocity] or [effort];
  //     acceleration is not simulated); the joints must offer them
  //   gains.<joint>.{p, i, d, i_clamp (Humble), i_clamp_max, i_clamp_min, ff_velocity_scale}:
  //     PID and velocity feed-forward (all default 0, as ros2_controllers), velocity and effort
  //   constraints.{goal_time, stopped_velocity_tolerance, <joint>.trajectory, <joint>.goal},
  //   allow_partial_joints_goal, state_publish_rate (Humble; Jazzy publishes every update: give
  //   0), action_monitor_rate: as above
  // Read and not simulated: open_loop_control, allow_integration_in_goal_trajectories,
  // interpolation_method, cmd_timeout, allow_nonzero_velocity_at_trajectory_end.
  static std::unique_ptr<JointTrajectoryController> ros2();
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override;

  TrajectoryCommandPort& command_port() { return *command_; }
  TrajectoryGoalPort& goal_port() { return *goal_; }
  StatePort<JointTrajectoryControllerState>& state_port() { return state_; }
  TrajectoryQueryPort& query_port() { return *query_; }
  const std::vector<std::string>& joint_names() const { return channel_->config().joints; }
  // The trajectory being run (read it only between ticks, e.g. in tests).
  const Trajectory& trajectory() const { return *active_; }
  std::uint64_t active_goal() const { return active_goal_; }

 private:
  void take(const TrajectoryRequest& request, double time) noexcept;
  void hold_current(double time) noexcept;
  void finish_goal(GoalStatus status, TrajectoryResultCode code, const char* reason, double time,
                   const ToleranceViolation* violation = nullptr) noexcept;
  void check_goal(double time) noexcept;
  void publish(double time) noexcept;
  void fill(JointTrajectoryControllerState& s, double time) const noexcept;
  bool canceled_before_start(std::uint64_t id) const noexcept;

  HardwareInterface iface_;
  ControllerFlavour flavour_;
  bool generic_ = false;
  bool ros2_ = false;
  std::vector<JointHandle> joints_;
  std::vector<std::uint8_t> continuous_;
  std::vector<std::unique_ptr<Pid>> pids_;
  std::vector<std::unique_ptr<PidGainsPort>> gains_;
  std::vector<double> velocity_ff_;
  double state_period_ = 0.02;    // s; 0: every update
  double monitor_period_ = 0.05;  // s
  double stop_duration_ = 0.0;    // s

  std::unique_ptr<TrajectoryChannel> channel_;
  std::unique_ptr<TrajectoryCommandPort> command_;
  std::unique_ptr<TrajectoryGoalPort> goal_;
  std::unique_ptr<TrajectoryQueryPort> query_;
  StatePort<JointTrajectoryControllerState> state_{"state"};

  // Real-time state, sized at init.
  Trajectory trajectories_[2];
  Trajectory* active_ = &trajectories_[0];
  Trajectory* spare_ = &trajectories_[1];
  bool query_stale_ = true;  // the active trajectory changed since query_ last took it
  std::vector<SplineState> desired_, actual_, error_;  // error = desired - actual
  std::vector<double> previous_velocity_;
  bool have_previous_velocity_ = false;
  std::uint64_t active_goal_ = 0;
  double goal_start_ = 0.0, goal_end_ = 0.0;
  std::vector<std::uint8_t> goal_joints_;
  TrajectoryTolerances goal_tolerances_;
  std::array<std::uint64_t, 16> canceled_{};  // recent cancels of goals not yet taken
  std::size_t canceled_next_ = 0;
  double last_state_publish_ = -1e300;
  double last_feedback_publish_ = -1e300;
};

}  // namespace mechsim::control
