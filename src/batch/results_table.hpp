#pragma once
// The results of a sweep as one table: a row per point with its parameters, its status, how many
// of its checks passed, the chosen metrics and why it failed. Written as results.csv and
// results.json in the sweep folder (`mechsim sweep collect`, and at the end of a local sweep).
//
// results.csv columns: index, status, passed (1/0), one column per axis (its path, the value as
// given to the scenario), checks_passed, checks_total, the metrics (the sweep's `metrics`; empty
// where a point has none), error. Numbers are written in the shortest form that reads back
// exactly, so that two runs of the same sweep give the same bytes (but wall_time and
// real_time_factor, which are measured, not simulated).

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "batch/sweep_folder.hpp"

namespace mechsim::batch {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;  // one per point, in index order
  std::size_t missing = 0, passed = 0, not_passed = 0;
};

// Reads every point.json of the sweep in `dir` (a point without one: status "missing").
Table collect_table(const std::filesystem::path& dir, const Plan& plan);

// results.csv and results.json.
void write_table(const std::filesystem::path& dir, const Plan& plan, const Table& table);

// A number as results.csv writes it.
std::string table_number(double v);

}  // namespace mechsim::batch
