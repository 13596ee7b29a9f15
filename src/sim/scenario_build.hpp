#pragma once
// A scenario's simulation: its robot (xacro, the scenario's sensor blocks and camera overrides),
// world (with its boxes), controllers and other robots, built and their controllers started.

#include <memory>
#include <string>

#include "sim/scenario.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

// Throws ScenarioError naming the file and the part (robot, world, controllers, others: NAME).
// `urdf` receives the robot's expanded description.
std::unique_ptr<Simulation> build_simulation(const Scenario& s, std::string& urdf);

}  // namespace mechsim::sim
