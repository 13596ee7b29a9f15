#pragma once
// Runs sweep points on this machine, each in its own process (`mechsim sweep run-point`), N at a
// time, with a progress line (done, failures so far, ETA). A point that crashes, hangs past the
// time limit or is interrupted gets a point.json saying so, pointing at its log; the others go on.

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "batch/sweep_folder.hpp"

namespace mechsim::batch {

struct LocalOptions {
  std::string exe;  // the mechsim binary that runs each point (this one)
  int jobs = 1;
  const std::atomic<int>* interrupt = nullptr;  // see PoolOptions
  std::ostream* progress = nullptr;             // progress and failures; none when null
  bool tty = false;                             // progress as one line redrawn in place
};

struct Tally {
  std::size_t ran = 0;     // points run now
  std::size_t passed = 0;  // of those
  std::size_t not_passed = 0;
  bool interrupted = false;
  double wall_time = 0.0;  // s for all of them
};

// The points among [first, last) without a final result (none yet, or crashed, timed out,
// interrupted): what --resume runs.
std::vector<std::size_t> unfinished_points(const std::filesystem::path& dir, const Plan& plan, std::size_t first = 0,
                                           std::size_t last = static_cast<std::size_t>(-1));

Tally run_points_locally(const std::filesystem::path& dir, const Plan& plan, const std::vector<std::size_t>& points,
                         const LocalOptions& options);

// "killed by signal 11 (Segmentation fault)".
std::string describe_signal(int signal);

}  // namespace mechsim::batch
