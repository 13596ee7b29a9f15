#pragma once
// A sweep's pictures, drawn by gnuplot into DIR/plots/:
//   <metric>.png     the metric against each axis, a panel per axis (passed points green, the
//                    others red)
//   heatmap_<metric>.png   the first metric over the two map axes (the sweep's `maps`), the mean
//                    of the points at each pair of values: cells where both axes are lists or
//                    grids, else a coloured square at each pair
//   pass_fail.png    every point over the two map axes: passed, failed a check, did not finish
//                    (diverged, left the ground, crashed, timed out); list and grid values are
//                    spread a little within their cell so that stacked points show
// Values that are not numbers (a list of world names) are placed at their position in the list.

#include <filesystem>
#include <string>
#include <vector>

#include "batch/results_table.hpp"
#include "batch/sweep_folder.hpp"

namespace mechsim::batch {

// Returns the PNGs written (relative to dir); gnuplot's complaints go to `errors`.
std::vector<std::string> write_plots(const std::filesystem::path& dir, const Plan& plan, std::vector<std::string>& errors);

}  // namespace mechsim::batch
