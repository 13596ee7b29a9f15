// Trajectory ports through the opaque PortRef (C++20 side of the bridge).
#include "controllers/trajectory/trajectory_goal.hpp"
#include "controllers/trajectory/trajectory_query.hpp"
#include "bridge/port_cast.hpp"
#include "bridge/sim_bridge.hpp"

namespace mechsim::bridge {

using detail::port_as;

bool write_trajectory(const PortRef& port, const control::JointTrajectory& trajectory, std::string* error) {
  auto* p = port_as<control::TrajectoryCommandPort>(port);
  if (!p) {
    if (error) *error = "port '" + port.name + "' of '" + port.controller + "' takes no trajectories";
    return false;
  }
  return p->write(trajectory, error);
}

bool read_trajectory_state(const PortRef& port, control::JointTrajectoryControllerState& out,
                           std::uint64_t* sequence) {
  const auto* p = detail::fresh_state<control::JointTrajectoryControllerState>(port, sequence);
  if (!p) return false;
  out = p->read();
  return true;
}

bool submit_goal(const PortRef& port, const control::FollowJointTrajectoryGoal& goal, GoalTicket& ticket) {
  auto* p = port_as<control::TrajectoryGoalPort>(port);
  if (!p) return false;
  const control::GoalSubmission s = p->submit(goal);
  ticket.id = s.id;
  ticket.accepted = s.accepted;
  ticket.result = s.result;
  return true;
}

bool query_trajectory(const PortRef& port, double time, TrajectorySample& out, std::string* error) {
  auto* p = port_as<control::TrajectoryQueryPort>(port);
  if (!p) {
    if (error) *error = "port '" + port.name + "' of '" + port.controller + "' samples no trajectory";
    return false;
  }
  std::vector<control::SplineState> states;
  if (!p->sample(time, states, error)) return false;
  out.names = p->joint_names();
  out.position.clear();
  out.velocity.clear();
  out.acceleration.clear();
  for (const control::SplineState& s : states) {
    out.position.push_back(s.position);
    out.velocity.push_back(s.velocity);
    out.acceleration.push_back(s.acceleration);
  }
  return true;
}

bool cancel_goal(const PortRef& port, std::uint64_t id) {
  return detail::cancel_goal_on<control::TrajectoryGoalPort>(port, id);
}

std::optional<control::GoalStatus> goal_status(const PortRef& port, std::uint64_t id) {
  return detail::goal_status_on<control::TrajectoryGoalPort>(port, id);
}

std::optional<control::TrajectoryResult> goal_result(const PortRef& port, std::uint64_t id) {
  auto* p = port_as<control::TrajectoryGoalPort>(port);
  if (!p) return std::nullopt;
  return p->result(id);
}

bool read_goal_feedback(const PortRef& port, control::FollowJointTrajectoryFeedback& out, std::uint64_t* sequence) {
  const auto* p = port_as<control::TrajectoryGoalPort>(port);
  if (!p || !detail::take_newer(p->feedback_sequence(), sequence)) return false;
  out = p->feedback();
  return true;
}

}  // namespace mechsim::bridge
