#pragma once
// The still parts of a replay (sim/replay_recorder.hpp lists the folder): robot.json with the
// links' visuals and their meshes, robot.urdf, world.json and terrain.bin.

#include <filesystem>
#include <string>

#include "sim/simulation.hpp"

namespace mechsim::sim {

// Writes into `replay_dir` (which exists). A mesh that cannot be read becomes a warning in
// robot.json ("warnings") and the visual is left out; a file that cannot be written throws
// ScenarioError naming it.
void write_replay_assets(const Simulation& sim, const std::filesystem::path& replay_dir, const std::string& urdf);

// The colour (r, g, b in 0..1) a Gazebo material name ("Gazebo/Grey") stands for; false when
// the name is not one of Gazebo's plain colours.
bool gazebo_material_rgb(const std::string& name, double rgb[3]);

}  // namespace mechsim::sim
