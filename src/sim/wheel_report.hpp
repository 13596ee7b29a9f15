#pragma once
// The wheels' part of a scenario's report when the world has a soil (world.soil): wheels.csv, a
// row per record period with each wheel's slip, slip angle, sinkage, normal load, traction
// (drawbar pull), lateral force and soil torque (physics::WheelSoilReading); wheels.png, their
// slip, sinkage and traction over time; per-wheel figures in summary.json ("wheels"); and the
// slip checks. Without a soil it does nothing (slip checks fail, saying so).

#include <fstream>
#include <string>
#include <vector>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

class WheelReport {
 public:
  // `dir` empty: no files, checks and figures only. Throws ScenarioError when a slip check names
  // a wheel the robot does not have.
  WheelReport(const Simulation& sim, const Scenario& scenario, const std::string& dir);

  // A Simulation observer: every tick, after the step.
  void observe(const Simulation& sim);

  CheckOutcome judge(const Check& check) const;  // a slip check

  // Closes wheels.csv; with `plots`, draws wheels.png; fills result.wheels and result.files.
  void write(ScenarioResult& result, bool plots);

 private:
  struct Window {  // a slip check's sums
    double sum = 0.0;
    long samples = 0;
  };
  struct Figures {  // per wheel, over the run while in the soil
    double slip_sum = 0.0, traction_sum = 0.0, max_sinkage = 0.0, sinkage_sum = 0.0, rut_sum = 0.0;
    long samples = 0;
  };
  const Scenario& scenario_;
  std::string dir_;
  bool active_ = false;
  std::vector<std::string> links_;
  std::vector<int> check_wheel_;  // per check: -1 every wheel, else the wheel's index
  std::vector<Window> windows_;
  std::vector<Figures> figures_;
  std::uint64_t record_every_ = 1;
  std::ofstream csv_;
};

}  // namespace mechsim::sim
