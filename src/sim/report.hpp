#pragma once
// What a scenario run leaves behind: the CSV recorder (sampled during the run) and the final
// report (summary.json and gnuplot PNGs).

#include <fstream>
#include <string>
#include <vector>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/trajectory/trajectory_goal.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

// Samples joint states, controller states and the base pose into CSV files (when `dir` is not
// empty) and accumulates each controller's tracking error (always). The trajectory controllers
// named in `trajectory_controllers` also get their desired and actual positions per joint
// recorded into trajectory.csv. sample() belongs in a control observer of the simulation
// (Simulation::add_control_observer), where every file's row stamped t holds the state at t.
class Recorder {
 public:
  Recorder(const Simulation& sim, const std::string& dir, const std::vector<std::string>& trajectory_controllers = {});
  void sample(const control::StatePort<control::OdometrySnapshot>* odometry);
  std::vector<TrackingError> tracking() const;
  void close();

  struct Channel {
    std::string controller, joint;  // the joint is empty for single-joint controllers
    const control::StatePort<control::JointControllerState>* single = nullptr;
    const control::StatePort<control::JointGroupControllerState>* group = nullptr;
    std::size_t index = 0;  // in the group
    double sum_sq = 0.0, max_abs = 0.0;
    std::size_t samples = 0;
  };
  // Joint names ("controller/joint") of trajectory.csv, in column order (desired, actual each).
  const std::vector<std::string>& trajectory_columns() const { return trajectory_columns_; }

 private:
  const Simulation& sim_;
  std::vector<Channel> channels_;
  std::vector<std::size_t> passive_joints_;  // physics joints outside the mechanism
  std::vector<const control::StatePort<control::JointTrajectoryControllerState>*> trajectory_states_;
  std::vector<std::string> trajectory_columns_;
  std::ofstream joints_, controllers_, base_, trajectory_, others_;  // others.csv: the other robots' bases
};

// summary.json and, when options.plots, path.png, tracking.png, errors.png and (when the
// recorder has trajectory columns) trajectory.png. Adds the files written to result.files; a
// plotting failure becomes a warning.
// Before the run: the report folder exists and takes a file, the disk has room (a clear error
// now rather than a lost report after an hour of simulation), and summary.json says the run has
// not completed. Throws ScenarioError naming the folder. Empty `dir`: nothing (no report).
void prepare_report_folder(const Scenario& scenario, const std::string& dir);

void write_report(const Scenario& scenario, const Simulation& sim, const Recorder& recorder, ScenarioResult& result,
                  const RunOptions& options);

}  // namespace mechsim::sim
