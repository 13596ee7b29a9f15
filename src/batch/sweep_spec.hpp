#pragma once
// A sweep file: a base scenario, the axes of scenario values to vary, and what to record.
//
//   name: cc8_route_mc                  # default: the file's stem
//   scenario: ../robots/cc8/scenarios/mars_yard_route.yaml   # relative to this file
//   set: {duration: 20}                 # values every point overrides (same paths as axes)
//   samples: 10                         # draws of the random and Latin hypercube axes
//   seed: 1                             # of those draws (the same seed, the same points)
//   time_limit: 600                     # s of wall-clock time per point (default 3600)
//   plots_per_point: false              # each point's report PNGs and 3D replay (default: CSVs and summary only)
//   metrics: [final_error, max_tilt_deg, odometry_error, wall_time]   # table columns
//   maps: [spawn.yaw, world.seed]       # the two axes of the heat map and pass/fail map
//   axes:
//     - {path: world.seed, list: [1, 2, 3]}                          # any YAML scalars
//     - {path: spawn.yaw, grid: {from: -0.3, to: 0.3, steps: 4}}     # evenly spaced, both ends
//     - {path: controllers.params.rover_drive_controller.wheel_pid.p, uniform: [2, 8]}
//     - {path: world.boxes.0.mass, normal: {mean: 1.0, stddev: 0.1}}
//     - {path: controllers.params.rover_drive_controller.wheel_pid.i, log_uniform: [5, 50]}
//     - {path: spawn.x, lhs: [-16.5, -16.0]}                        # Latin hypercube
//     - {path: seed, uniform: [1, 1000], integer: true}              # rounded to integers
//
// A path is dotted: map keys, and list indices as numbers (`timeline.0.route.speed`). It names
// any value of the scenario file, or one its reader knows (`world.seed` where the file has no
// seed); `controllers.params.<controller>.<parameter>` lays a value over the controllers file
// (sim/scenario.hpp). Points: the product of the list and grid axes (the first axis varies
// slowest), each with `samples` draws of the random (uniform, normal, log_uniform) and `lhs`
// axes; the draws are the same for every product point (common random numbers). Each random axis
// draws from its own stream (seed, axis number), so adding an axis leaves the others' values be.
// Latin hypercube: each lhs axis cuts its range into `samples` equal strata and takes one value
// in each, in an order shuffled per axis.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace mechsim::batch {

// A bad sweep file: what names the file, the line and the key.
struct SweepError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Axis {
  enum class Kind { List, Grid, Uniform, Normal, LogUniform, Lhs } kind = Kind::List;
  std::string path;                 // dotted scenario path
  std::string location;             // file:line of the axis, for errors
  std::vector<std::string> values;  // List: the values as written (YAML scalars)
  double a = 0.0, b = 0.0;          // Grid from/to; Uniform, LogUniform, Lhs bounds; Normal mean, stddev
  int steps = 0;                    // Grid
  bool integer = false;             // values rounded to integers
  bool discrete() const { return kind == Kind::List || kind == Kind::Grid; }
  // How many values a discrete axis has.
  std::size_t size() const { return kind == Kind::List ? values.size() : static_cast<std::size_t>(steps); }
};

struct FixedValue {
  std::string path;
  std::string value;  // YAML scalar text
  std::string location;
};

struct SweepSpec {
  std::string file;      // the sweep file (absolute)
  std::string name;
  std::string scenario;  // the base scenario (absolute)
  std::vector<FixedValue> set;
  std::vector<Axis> axes;
  std::size_t samples = 1;  // 1 when there is no random axis
  std::uint64_t seed = 1;
  double time_limit = 3600.0;  // s per point
  bool plots_per_point = false;
  std::vector<std::string> metrics;
  std::vector<std::string> maps;  // two axis paths (default: the first two)
  std::string axes_location;      // file:line of `axes`, for the point count
};

// The metrics a point records (batch/point_result.hpp), the default table columns.
const std::vector<std::string>& known_metrics();

// More points than this need `force` (a typo in a grid must not start 10^7 runs).
constexpr std::size_t kMaxPointsWithoutForce = 100000;

// Reads and checks a sweep file: every error names the file, the line and the key. The base
// scenario's own checks (and the paths against it) are batch/scenario_override.hpp's.
SweepSpec load_sweep(const std::string& path, bool force);

// The number of points (saturating at SIZE_MAX).
std::size_t point_count(const SweepSpec& spec);

}  // namespace mechsim::batch
