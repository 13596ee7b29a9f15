// The PR2 gripper's ports through the opaque PortRef (C++20 side of the bridge).
#include "controllers/gripper/pr2_gripper_ports.hpp"
#include "bridge/port_cast.hpp"
#include "bridge/sim_bridge.hpp"

namespace mechsim::bridge {

using detail::port_as;

namespace {

GripperStateData to_data(const control::GripperResult& r) { return {r.position, r.effort, r.stalled, r.reached_goal}; }

}  // namespace

bool write_gripper_command(const PortRef& port, double position, double max_effort, std::string* error) {
  auto* p = port_as<control::GripperCommandPort>(port);
  if (!p) {
    if (error) *error = "port '" + port.name + "' of '" + port.controller + "' takes no gripper commands";
    return false;
  }
  return p->write({position, max_effort}, error);
}

bool submit_gripper_goal(const PortRef& port, double position, double max_effort, GripperTicket& ticket) {
  auto* p = port_as<control::GripperGoalPort>(port);
  if (!p) return false;
  const control::GripperSubmission s = p->submit({position, max_effort});
  ticket.id = s.id;
  ticket.accepted = s.accepted;
  ticket.error = s.error;
  return true;
}

bool cancel_gripper_goal(const PortRef& port, std::uint64_t id) {
  return detail::cancel_goal_on<control::GripperGoalPort>(port, id);
}

std::optional<control::GoalStatus> gripper_goal_status(const PortRef& port, std::uint64_t id) {
  return detail::goal_status_on<control::GripperGoalPort>(port, id);
}

std::optional<GripperStateData> gripper_goal_result(const PortRef& port, std::uint64_t id) {
  auto* p = port_as<control::GripperGoalPort>(port);
  if (!p) return std::nullopt;
  const auto r = p->result(id);
  if (!r) return std::nullopt;
  return to_data(*r);
}

bool read_gripper_feedback(const PortRef& port, GripperStateData& out, std::uint64_t* goal_id,
                           std::uint64_t* sequence) {
  const auto* p = port_as<control::GripperGoalPort>(port);
  if (!p || !detail::take_newer(p->feedback_sequence(), sequence)) return false;
  const control::GripperFeedback f = p->feedback();
  out = to_data(f.state);
  if (goal_id) *goal_id = f.goal_id;
  return true;
}

}  // namespace mechsim::bridge
