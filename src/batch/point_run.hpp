#pragma once
// Running one sweep point in this process: what `mechsim sweep run-point DIR INDEX` does in the
// child process that the local pool or a Slurm task starts for each point.

#include <atomic>
#include <cstddef>
#include <filesystem>

#include "batch/sweep_folder.hpp"

namespace mechsim::batch {

// Runs point `index` of the sweep in `dir` into its folder and writes its point.json (passed,
// failed, incomplete, or error when the scenario cannot start). Interrupted (`interrupt` set by a
// signal handler) it writes no point.json and returns 128 + the signal: the process that started
// it records why. Otherwise returns 0 (the point's outcome is in point.json, not the exit status).
int run_point(const std::filesystem::path& dir, const Plan& plan, std::size_t index, const std::atomic<int>* interrupt);

}  // namespace mechsim::batch
