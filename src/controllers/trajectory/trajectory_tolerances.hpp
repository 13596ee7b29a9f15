#pragma once
// Path and goal tolerances of a trajectory controller (ros_control's
// joint_trajectory_controller/tolerances.h semantics).
//
// Defaults from parameters (`constraints` for the ros_control types, the PR2 controller's
// `joint_trajectory_action_node/constraints`):
//   goal_time                     s, how long after the trajectory's end the goal may take to
//                                 settle within its goal tolerance; 0: no limit (it waits)
//   stopped_velocity_tolerance    rad/s or m/s, the default goal velocity tolerance (0.01)
//   <joint>/trajectory            rad or m, the default path position tolerance (0: none)
//   <joint>/goal                  rad or m, the default goal position tolerance (0: none)
// A tolerance <= 0 is not checked. A goal's own tolerances replace the defaults per joint and
// quantity: > 0 sets it, 0 keeps the default, < 0 removes it (control_msgs/JointTolerance).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "controllers/trajectory/trajectory_msgs.hpp"

namespace mechsim::control {

struct StateTolerance {
  double position = 0.0;      // rad or m; <= 0: not checked
  double velocity = 0.0;      // rad/s or m/s
  double acceleration = 0.0;  // rad/s^2 or m/s^2
};

// One entry per controller joint, in the controller's joint order.
struct TrajectoryTolerances {
  std::vector<StateTolerance> path;
  std::vector<StateTolerance> goal;
  double goal_time = 0.0;  // s; <= 0: no limit
};

constexpr double kDefaultStoppedVelocityTolerance = 0.01;  // rad/s, ros_control and the PR2

// Reads the defaults from `constraints` (a map; absent keys take the defaults above). Throws
// ParamsError/ControllerConfigError naming the parameter for a mistyped or negative value.
TrajectoryTolerances read_default_tolerances(const std::optional<Params>& constraints,
                                             const std::vector<std::string>& joints);

// Applies a goal's tolerances to `tolerances` (which holds the defaults). False, with `error`
// naming the entry, when an entry names a joint the controller does not have or is not finite.
bool apply_goal_tolerances(const FollowJointTrajectoryGoal& goal, const std::vector<std::string>& joints,
                           TrajectoryTolerances& tolerances, std::string& error);

enum class ToleranceQuantity : std::uint8_t { Position, Velocity, Acceleration };
const char* tolerance_quantity_name(ToleranceQuantity q) noexcept;

struct ToleranceViolation {
  int joint = -1;  // controller joint index
  ToleranceQuantity quantity = ToleranceQuantity::Position;
  double error = 0.0;      // the offending error (desired - actual)
  double tolerance = 0.0;  // the tolerance it exceeded
};

// Real-time. True when |error| is within every checked tolerance; otherwise false and, when
// `violation` is given, the first quantity exceeded (position, then velocity, acceleration).
bool within_tolerance(const StateTolerance& tolerance, double position_error, double velocity_error,
                      double acceleration_error, ToleranceViolation* violation = nullptr) noexcept;

}  // namespace mechsim::control
