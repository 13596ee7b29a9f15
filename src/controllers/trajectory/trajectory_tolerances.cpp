#include "controllers/trajectory/trajectory_tolerances.hpp"

#include <cmath>

#include "control/hardware.hpp"
#include "controllers/param_checks.hpp"

namespace mechsim::control {
namespace {

// control_msgs/JointTolerance: > 0 sets, 0 keeps the default, < 0 removes.
void apply(double requested, double& value) noexcept {
  if (requested > 0.0) value = requested;
  if (requested < 0.0) value = 0.0;
}

}  // namespace

TrajectoryTolerances read_default_tolerances(const std::optional<Params>& constraints,
                                             const std::vector<std::string>& joints) {
  TrajectoryTolerances t;
  t.path.assign(joints.size(), StateTolerance{});
  t.goal.assign(joints.size(), StateTolerance{});
  double stopped = kDefaultStoppedVelocityTolerance;
  if (constraints) {
    t.goal_time = non_negative_param(*constraints, "goal_time", 0.0);
    stopped = non_negative_param(*constraints, "stopped_velocity_tolerance", kDefaultStoppedVelocityTolerance);
  }
  for (std::size_t i = 0; i < joints.size(); ++i) {
    t.goal[i].velocity = stopped;
    if (!constraints) continue;
    if (auto joint = constraints->find(joints[i])) {
      t.path[i].position = non_negative_param(*joint, "trajectory", 0.0);
      t.goal[i].position = non_negative_param(*joint, "goal", 0.0);
    }
  }
  return t;
}

bool apply_goal_tolerances(const FollowJointTrajectoryGoal& goal, const std::vector<std::string>& joints,
                           TrajectoryTolerances& tolerances, std::string& error) {
  const auto apply_list = [&](const std::vector<JointTolerance>& list, std::vector<StateTolerance>& out,
                              const char* what) {
    for (std::size_t k = 0; k < list.size(); ++k) {
      const JointTolerance& jt = list[k];
      std::size_t i = 0;
      while (i < joints.size() && joints[i] != jt.name) ++i;
      if (i == joints.size()) {
        error = std::string(what) + "[" + std::to_string(k) + "] names joint '" + jt.name +
                "', which this controller does not control";
        return false;
      }
      if (!std::isfinite(jt.position) || !std::isfinite(jt.velocity) || !std::isfinite(jt.acceleration)) {
        error = std::string(what) + "[" + std::to_string(k) + "] (joint '" + jt.name + "') is not finite";
        return false;
      }
      apply(jt.position, out[i].position);
      apply(jt.velocity, out[i].velocity);
      apply(jt.acceleration, out[i].acceleration);
    }
    return true;
  };
  if (!apply_list(goal.path_tolerance, tolerances.path, "path_tolerance")) return false;
  if (!apply_list(goal.goal_tolerance, tolerances.goal, "goal_tolerance")) return false;
  if (!std::isfinite(goal.goal_time_tolerance)) {
    error = "goal_time_tolerance is not finite";
    return false;
  }
  apply(goal.goal_time_tolerance, tolerances.goal_time);
  return true;
}

const char* tolerance_quantity_name(ToleranceQuantity q) noexcept {
  switch (q) {
    case ToleranceQuantity::Position: return "position";
    case ToleranceQuantity::Velocity: return "velocity";
    case ToleranceQuantity::Acceleration: return "acceleration";
  }
  return "?";
}

bool within_tolerance(const StateTolerance& tol, double position_error, double velocity_error,
                      double acceleration_error, ToleranceViolation* violation) noexcept {
  const auto check = [&](double tolerance, double err, ToleranceQuantity q) {
    if (tolerance > 0.0 && !(std::fabs(err) <= tolerance)) {
      if (violation != nullptr) {
        violation->quantity = q;
        violation->error = err;
        violation->tolerance = tolerance;
      }
      return false;
    }
    return true;
  };
  return check(tol.position, position_error, ToleranceQuantity::Position) &&
         check(tol.velocity, velocity_error, ToleranceQuantity::Velocity) &&
         check(tol.acceleration, acceleration_error, ToleranceQuantity::Acceleration);
}

}  // namespace mechsim::control
