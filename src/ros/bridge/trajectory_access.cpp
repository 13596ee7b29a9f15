// Trajectory ports through the opaque PortRef (C++20 side of the bridge).
#include "control/trajectory_goal.hpp"
#include "ros/bridge/sim_bridge.hpp"

namespace mechsim::ros {

namespace {

template <class P>
P* as(const PortRef& ref) {
  return dynamic_cast<P*>(static_cast<control::Port*>(ref.port));
}

}  // namespace

bool write_trajectory(const PortRef& port, const control::JointTrajectory& trajectory, std::string* error) {
  auto* p = as<control::TrajectoryCommandPort>(port);
  if (!p) {
    if (error) *error = "port '" + port.name + "' of '" + port.controller + "' takes no trajectories";
    return false;
  }
  return p->write(trajectory, error);
}

bool read_trajectory_state(const PortRef& port, control::JointTrajectoryControllerState& out,
                           std::uint64_t* sequence) {
  const auto* p = as<control::StatePort<control::JointTrajectoryControllerState>>(port);
  if (!p) return false;
  const std::uint64_t seq = p->sequence();
  if (seq == 0 || (sequence && seq == *sequence)) return false;
  if (sequence) *sequence = seq;
  out = p->read();
  return true;
}

bool submit_goal(const PortRef& port, const control::FollowJointTrajectoryGoal& goal, GoalTicket& ticket) {
  auto* p = as<control::TrajectoryGoalPort>(port);
  if (!p) return false;
  const control::GoalSubmission s = p->submit(goal);
  ticket.id = s.id;
  ticket.accepted = s.accepted;
  ticket.result = s.result;
  return true;
}

bool cancel_goal(const PortRef& port, std::uint64_t id) {
  auto* p = as<control::TrajectoryGoalPort>(port);
  return p && p->cancel(id);
}

std::optional<control::GoalStatus> goal_status(const PortRef& port, std::uint64_t id) {
  auto* p = as<control::TrajectoryGoalPort>(port);
  if (!p) return std::nullopt;
  return p->status(id);
}

std::optional<control::TrajectoryResult> goal_result(const PortRef& port, std::uint64_t id) {
  auto* p = as<control::TrajectoryGoalPort>(port);
  if (!p) return std::nullopt;
  return p->result(id);
}

bool read_goal_feedback(const PortRef& port, control::FollowJointTrajectoryFeedback& out, std::uint64_t* sequence) {
  const auto* p = as<control::TrajectoryGoalPort>(port);
  if (!p) return false;
  const std::uint64_t seq = p->feedback_sequence();
  if (seq == 0 || (sequence && seq == *sequence)) return false;
  if (sequence) *sequence = seq;
  out = p->feedback();
  return true;
}

}  // namespace mechsim::ros
