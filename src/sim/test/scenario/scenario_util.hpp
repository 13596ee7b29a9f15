#pragma once
// Helpers shared by the sim scenario tests.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "description/robot_model.hpp"
#include "physics/heightmap.hpp"
#include "sim/pose_math.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

// The real CC8 (reference expansion of cc8_description) and its controllers.
description::RobotModel load_shared_cc8(const std::filesystem::path& shared);
control::Params cc8_controller_params(const std::filesystem::path& shared);  // the `cc8` namespace
std::vector<std::string> cc8_controller_names();                            // all 11
// Implicit, or the environment variable MECHSIM_CC8_INTEGRATOR (implicit | euler | rk4) to run the
// CC8 stand and differential figures under another integrator; throws naming a bad value.
physics::Integrator cc8_test_integrator();

description::Pose link_pose(const Simulation& sim, const std::string& link);
// Wheel links (name starting with "wheel_") touching the ground or terrain.
int count_wheel_contacts(const Simulation& sim);
// A square heightmap of side `size` (m) and spacing `cell` (m) with heights f(x, y).
physics::Heightmap step_terrain(double size, double cell, const std::function<double(double, double)>& f);

}  // namespace mechsim::sim
