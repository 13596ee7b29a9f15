#pragma once
// What the report's pictures share: running gnuplot on a script, quoting, and the terrain as a
// gnuplot image file.

#include <filesystem>
#include <string>

#include "physics/heightmap.hpp"

namespace mechsim::sim {

// A gnuplot string literal.
std::string quoted(const std::string& s);

// Runs gnuplot on `script` (kept as <dir>/<name>.gp with gnuplot's log when it fails); empty on
// success, else gnuplot's complaint.
std::string run_gnuplot(const std::filesystem::path& dir, const std::string& name, const std::string& script);

// The terrain as "x,y,z" rows (blank line between grid rows: gnuplot's `with image`), at most
// ~400 samples a side; its height range in z_min, z_max.
void write_terrain(const physics::Heightmap& map, const std::filesystem::path& file, double& z_min, double& z_max);

}  // namespace mechsim::sim
