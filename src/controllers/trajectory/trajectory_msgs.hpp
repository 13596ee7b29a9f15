#pragma once
// Plain data types of the trajectory controllers, field for field what trajectory_msgs and
// control_msgs carry (JointTrajectory, JointTrajectoryPoint, JointTolerance,
// FollowJointTrajectory goal/result/feedback, JointTrajectoryControllerState), with times as
// simulation seconds. The ROS layer converts the messages; scenarios build them in code.

#include <cstdint>
#include <string>
#include <vector>

namespace mechsim::control {

// trajectory_msgs/JointTrajectoryPoint. Every non-empty vector has one value per joint of the
// trajectory. Which vectors are given chooses the spline: positions only -> linear,
// + velocities -> cubic, + accelerations -> quintic.
struct TrajectoryPoint {
  std::vector<double> positions;      // rad or m
  std::vector<double> velocities;     // rad/s or m/s (empty: not given)
  std::vector<double> accelerations;  // rad/s^2 or m/s^2 (empty: not given; needs velocities)
  std::vector<double> effort;         // N m or N; accepted and ignored, as ros_control does
  double time_from_start = 0.0;       // s after the trajectory's start time
};

// trajectory_msgs/JointTrajectory. `start_time` is header.stamp: 0 means "now", which for
// mechsim is the first controller update that sees the trajectory.
struct JointTrajectory {
  double start_time = 0.0;  // s, simulation time
  std::vector<std::string> joint_names;
  std::vector<TrajectoryPoint> points;
};

// control_msgs/JointTolerance. Per quantity: > 0 a tolerance, 0 "use the controller's default",
// < 0 "no tolerance" (control_msgs' convention).
struct JointTolerance {
  std::string name;
  double position = 0.0;      // rad or m
  double velocity = 0.0;      // rad/s or m/s
  double acceleration = 0.0;  // rad/s^2 or m/s^2
};

// control_msgs/FollowJointTrajectoryGoal.
struct FollowJointTrajectoryGoal {
  JointTrajectory trajectory;
  std::vector<JointTolerance> path_tolerance;
  std::vector<JointTolerance> goal_tolerance;
  double goal_time_tolerance = 0.0;  // s; 0: the controller's default (constraints/goal_time)
};

// control_msgs/FollowJointTrajectoryResult error codes.
enum class TrajectoryResultCode : std::int8_t {
  Successful = 0,
  InvalidGoal = -1,
  InvalidJoints = -2,
  OldHeaderTimestamp = -3,
  PathToleranceViolated = -4,
  GoalToleranceViolated = -5,
};
// "SUCCESSFUL", "INVALID_GOAL", ... as the message constants are named.
const char* result_code_name(TrajectoryResultCode code) noexcept;

struct TrajectoryResult {
  TrajectoryResultCode error_code = TrajectoryResultCode::Successful;
  std::string error_string;  // empty on success
};

// actionlib's goal states as a client sees them (RECALLED folds into Preempted, LOST into
// Rejected).
enum class GoalStatus : std::uint8_t { Pending, Active, Succeeded, Aborted, Preempted, Rejected };
const char* goal_status_name(GoalStatus status) noexcept;
inline bool goal_finished(GoalStatus s) noexcept { return s != GoalStatus::Pending && s != GoalStatus::Active; }

// One joint state per joint of the controller, in the controller's joint order.
struct TrajectoryPointState {
  std::vector<double> positions;      // rad or m
  std::vector<double> velocities;     // rad/s or m/s
  std::vector<double> accelerations;  // rad/s^2 or m/s^2
  double time_from_start = 0.0;       // s
};

// control_msgs/JointTrajectoryControllerState (and pr2_controllers_msgs', same fields).
// error = desired - actual for the ros_control types; the PR2 type reports actual - desired.
// Continuous joints report the shortest angular distance. The actual acceleration is estimated
// by differencing the measured velocity (the hardware measures none).
struct JointTrajectoryControllerState {
  double stamp = 0.0;  // s
  std::vector<std::string> joint_names;
  TrajectoryPointState desired;
  TrajectoryPointState actual;
  TrajectoryPointState error;
};

// control_msgs/FollowJointTrajectoryFeedback: the same snapshot for the goal being executed.
struct FollowJointTrajectoryFeedback {
  std::uint64_t goal_id = 0;  // 0 when no goal has run yet
  JointTrajectoryControllerState state;
};

}  // namespace mechsim::control
