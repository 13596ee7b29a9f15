#pragma once
// A sweep's folder, the one place every process of a sweep (local or on a cluster) reads from and
// writes to:
//   DIR/sweep.yaml        the sweep file as it was started
//   DIR/plan.json         every point's values: what each worker reads (never the sweep file)
//   DIR/points/NNNNN/     a point's scenario report (summary.json, CSVs), point.json, log.txt
//   DIR/results.csv, DIR/results.json, DIR/plots/   the table and the plots (sweep collect)
//   DIR/slurm/            job scripts, their logs and the submitted job ids (--slurm)

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "batch/sampling.hpp"
#include "batch/scenario_override.hpp"
#include "batch/sweep_spec.hpp"

namespace mechsim::batch {

struct PlanAxis {
  std::string path;
  std::string kind;      // list, grid, uniform, normal, log_uniform, lhs
  std::string location;  // file:line in the sweep file
};

struct Plan {
  std::string name;
  std::string sweep_file;  // absolute
  std::string scenario;    // absolute
  std::vector<FixedValue> set;
  std::vector<PlanAxis> axes;
  std::vector<Point> points;
  double time_limit = 3600.0;  // s per point
  bool plots_per_point = false;
  std::vector<std::string> metrics;
  std::vector<std::string> maps;
};

Plan make_plan(const SweepSpec& spec, std::size_t limit = static_cast<std::size_t>(-1));

// The overrides of point `index`: the sweep's `set` values, then its axes' values.
std::vector<Override> point_overrides(const Plan& plan, std::size_t index);

// Checks every distinct value of every axis (and the `set` values) against the base scenario:
// paths that lead nowhere, keys the scenario reader does not read, values it refuses. Throws
// SweepError naming the sweep file's line and the key.
void check_plan(const Plan& plan);

// plan.json's text (the same plan, the same text).
std::string plan_json(const Plan& plan);
// Whether two plans run the same points (scenario, set values, axes, values): --resume continues
// a sweep whose metrics, maps or time limit changed, not one whose points did.
bool same_points(const Plan& a, const Plan& b);
void write_plan(const std::filesystem::path& dir, const Plan& plan);
// Throws SweepError when DIR holds no sweep.
Plan read_plan(const std::filesystem::path& dir);

std::filesystem::path point_dir(const std::filesystem::path& dir, std::size_t index);

}  // namespace mechsim::batch
