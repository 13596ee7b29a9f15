#pragma once
// The sensors' part of a scenario's report: a CSV per sensor (sensors/<name>.csv, a row per
// sample), a plot per IMU (sensors/<name>.png), the laser scans seen from above over the world at
// chosen times (laser_scans.png), and the sensor checks (laser_range, imu_tilt).

#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sensors/sensor_output.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

class SensorReport {
 public:
  // `dir` empty: no files, checks only. Throws ScenarioError when a sensor check names a sensor
  // the robot does not have (or of the wrong kind).
  SensorReport(const Simulation& sim, const Scenario& scenario, const std::string& dir);
  ~SensorReport();

  // A Simulation observer: runs after the tick's sensors sampled (records new samples, captures
  // scans at the picture times and readings at the checks' times).
  void observe(const Simulation& sim);

  // A laser_range or imu_tilt check on the reading at its time (or the last one).
  CheckOutcome judge(const Check& check) const;

  // Closes the CSV files; with `plots`, draws the IMU plots and laser_scans.png. Adds what it
  // wrote to result.files, plotting failures to result.warnings.
  void write(ScenarioResult& result, bool plots);
  // The CSV file of sensor `i` of the simulation's SensorSet, relative to the report folder
  // ("sensors/<name>.csv"; written when the sensor gave a reading).
  std::string csv_file(std::size_t i) const;

 private:
  struct Capture {
    double time = 0.0;
    std::string sensor;
    double x = 0.0, y = 0.0;                    // sensor origin (m, world)
    std::vector<std::array<double, 2>> points;  // scan end points (m, world)
  };
  struct Channel;
  void capture_scan(const Simulation& sim, std::size_t sensor, double picture_time);
  void laser_picture(ScenarioResult& result);
  void imu_plots(ScenarioResult& result);

  const Simulation& sim_;
  const Scenario& scenario_;
  std::string dir_;
  std::vector<std::unique_ptr<Channel>> channels_;  // one per simulated sensor
  std::vector<double> picture_times_;
  std::vector<Capture> captures_;
  // Checks: the sensor index and the reading captured at `at` (the last one when absent).
  std::vector<int> check_sensor_;
  std::vector<std::optional<sensors::SensorReading>> check_reading_;
};

}  // namespace mechsim::sim
