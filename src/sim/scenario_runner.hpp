#pragma once
// Runs a Scenario headless and writes its report: CSV files of joint states, controller states
// and the base pose, summary.json, and PNG plots drawn by gnuplot.
//
// Output folder:
//   joints.csv       time, then per mechanism joint: position, velocity, measured effort, commanded effort
//   controllers.csv  time, then per controller with a joint state port: set point, process value, error, command
//   base.csv         time, ground-truth base pose (x, y, z, roll, pitch, yaw) and odometry (x, y, yaw) if any
//   summary.json     distance, final pose, tracking error per controller, real-time factor, checks
//   path.png, tracking.png, errors.png   (gnuplot)

#include <functional>
#include <string>
#include <vector>

#include "sim/scenario.hpp"

namespace mechsim::sim {

struct RunProgress {
  double time = 0.0;      // s of simulation time done
  double duration = 0.0;  // s in all
  double real_time_factor = 0.0;
};

struct RunOptions {
  std::string output_dir;  // created if needed; empty: no files at all
  bool plots = true;       // draw PNGs with gnuplot (needs gnuplot on PATH)
  std::function<void(const RunProgress&)> progress;  // called about every 0.5 s of sim time
};

struct CheckOutcome {
  std::string name;
  bool passed = false;
  std::string detail;  // measured value against the bound
};

struct TrackingError {
  std::string controller;
  double rms = 0.0;  // of the state port's error over the recorded samples
  double max = 0.0;
  std::size_t samples = 0;
};

struct ScenarioResult {
  bool completed = false;  // ran its whole duration (no divergence)
  bool passed = false;     // completed and every check passed
  std::string error;       // why it did not complete
  double sim_time = 0.0;   // s
  double wall_time = 0.0;  // s
  double real_time_factor = 0.0;
  double distance = 0.0;   // m, length of the base's path in the horizontal plane
  double final_x = 0.0, final_y = 0.0, final_z = 0.0, final_yaw = 0.0;  // m, rad
  double max_tilt = 0.0;   // rad
  bool has_odometry = false;
  double odometry_error = 0.0;  // m, final |odom - truth| in the plane
  std::vector<TrackingError> tracking;
  std::vector<CheckOutcome> checks;
  std::vector<std::string> files;  // written, relative to output_dir
  std::vector<std::string> warnings;
};

// Throws ScenarioError for a scenario that cannot start (robot, world, controllers, unknown
// controller or port in the timeline); a divergence during the run is reported in the result.
ScenarioResult run_scenario(const Scenario& scenario, const RunOptions& options);

}  // namespace mechsim::sim
