#pragma once
// What became of one sweep point: point.json in its folder, written by the process that ran it
// (or, when that process crashed, timed out or was stopped, by the one that started it).

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::batch {

enum class PointStatus {
  Passed,       // ran its whole duration, every check passed
  Failed,       // ran its whole duration, a check failed
  Incomplete,   // the run stopped early: the physics diverged, or the robot left the ground
  Error,        // the scenario could not start (a refused value, say)
  Crashed,      // the process ended on a signal or without a result
  Timeout,      // killed at the sweep's time limit
  Interrupted,  // stopped by Ctrl-C (or SIGTERM)
};

// passed, failed, incomplete, error, crashed, timeout, interrupted.
const char* status_name(PointStatus s);
std::optional<PointStatus> parse_status(const std::string& name);
// Outcomes of the point itself, kept by --resume; crashes, timeouts and interruptions run again.
bool is_final(PointStatus s);

struct PointResult {
  std::size_t index = 0;
  PointStatus status = PointStatus::Crashed;
  std::string error;                      // why it did not pass cleanly ("" for passed/failed)
  std::map<std::string, double> metrics;  // batch::known_metrics() and tracking_rms.<controller>
  std::vector<std::pair<std::string, bool>> checks;  // the scenario's checks as written, passed
  int exit_code = 0;                      // of the point's process (0 while it writes its own)
  int signal = 0;                         // that ended it, or 0
};

// The metrics of a finished run. final_error (m): from the final position to the scenario's goal,
// which is the last waypoint of its last route, else its first final_pose check's point, else its
// last reach check's point (absent when it has none).
PointResult result_of_run(const sim::Scenario& scenario, const sim::ScenarioResult& run, double wall_time);

// point.json in `dir`, written aside and renamed (a reader never sees half of one).
void write_point_result(const std::filesystem::path& dir, const PointResult& result);
// nullopt when there is none (or it cannot be read: a half-written one does not exist).
std::optional<PointResult> read_point_result(const std::filesystem::path& dir);

}  // namespace mechsim::batch
