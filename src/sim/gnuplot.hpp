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

// gnuplot commands that, after a plot, append that plot's axes to `file` as one JSON line:
// {"px": [left, right, bottom, top] (pixels of the PNG; bottom and top counted from the image's
// lower edge), "x": [min, max], "y": [min, max]} (data units). `mechsim view` draws its time
// cursor (or the robot's position on path.png) from them. `first`: start the file afresh.
std::string axes_record(const std::filesystem::path& file, bool first);

// The terrain as "x,y,z" rows (blank line between grid rows: gnuplot's `with image`), at most
// ~400 samples a side; its height range in z_min, z_max.
void write_terrain(const physics::Heightmap& map, const std::filesystem::path& file, double& z_min, double& z_max);

}  // namespace mechsim::sim
