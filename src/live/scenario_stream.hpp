#pragma once
// What a scenario run adds to its live stream: the robot description as the run expands it, and
// the waypoints of the routes in its timeline (scenario markers).

#include <array>
#include <string>
#include <vector>

#include "sim/scenario.hpp"

namespace mechsim::live {

// The scenario's robot description expanded (xacro arguments and packages as the run uses them).
// Throws sim::ScenarioError naming the scenario when it cannot be expanded.
std::string scenario_urdf(const sim::Scenario& scenario);
// (x, y) in the world (m) of every route waypoint in the timeline, in order.
std::vector<std::array<double, 2>> scenario_waypoints(const sim::Scenario& scenario);

}  // namespace mechsim::live
