#pragma once
// Internal to the C++20 side of the bridge (bridge/*.cpp; not C++17-clean, not for the ROS code):
// the typed port behind an opaque PortRef, and the tests the readers and goal functions share.

#include <cstdint>
#include <optional>
#include <string>

#include "control/ports.hpp"
#include "controllers/trajectory/trajectory_msgs.hpp"  // GoalStatus
#include "bridge/sim_bridge.hpp"

namespace mechsim::bridge::detail {

// The port as P, or null; then *error (when given) says the port has another type.
template <class P>
P* port_as(const PortRef& ref, std::string* error = nullptr) {
  auto* p = dynamic_cast<P*>(static_cast<control::Port*>(ref.port));
  if (!p && error) *error = "port '" + ref.name + "' of controller '" + ref.controller + "' has another type";
  return p;
}

// True when `seq` (a port's snapshot counter; 0: nothing written yet) is newer than *sequence,
// which it then updates. A null `sequence` takes any written snapshot.
inline bool take_newer(std::uint64_t seq, std::uint64_t* sequence) {
  if (seq == 0 || (sequence && seq == *sequence)) return false;
  if (sequence) *sequence = seq;
  return true;
}

// The state port when it has a snapshot newer than *sequence (take_newer), else null.
template <class T>
const control::StatePort<T>* fresh_state(const PortRef& ref, std::uint64_t* sequence) {
  const auto* p = port_as<const control::StatePort<T>>(ref);
  if (!p || !take_newer(p->sequence(), sequence)) return nullptr;
  return p;
}

// Goal ports (control::TrajectoryGoalPort, control::GripperGoalPort) share the goal life:
// cancel(id) and status(id). False / nullopt when the port is not a P.
template <class P>
bool cancel_goal_on(const PortRef& ref, std::uint64_t id) {
  auto* p = port_as<P>(ref);
  return p && p->cancel(id);
}

template <class P>
std::optional<control::GoalStatus> goal_status_on(const PortRef& ref, std::uint64_t id) {
  auto* p = port_as<P>(ref);
  if (!p) return std::nullopt;
  return p->status(id);
}

}  // namespace mechsim::bridge::detail
