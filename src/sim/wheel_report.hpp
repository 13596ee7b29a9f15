#pragma once
// The wheels' part of a scenario's report when the world has a soil (world.soil): wheels.csv, a
// row per record period with each soil wheel's slip, slip angle, sinkage, normal load, traction
// (drawbar pull), lateral force and soil torque (physics::WheelSoilReading; slip and slip angle
// blank while undefined, at rest); wheels.png, their slip, sinkage and traction over time;
// per-wheel figures and what is not a wheel in summary.json ("wheels", "not_wheels"); the slip
// checks; and a test rig's steady states (Scenario::steady_states: steady_states.csv and .png).
// Without a soil it does nothing (slip checks fail, saying so).

#include <fstream>
#include <string>
#include <vector>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

class WheelReport {
 public:
  // `dir` empty: no files, checks and figures only. Throws ScenarioError when a slip check or the
  // steady states name a wheel the soil does not act on.
  WheelReport(const Simulation& sim, const Scenario& scenario, const std::string& dir);

  // A Simulation observer: every tick, after the step.
  void observe(const Simulation& sim);

  CheckOutcome judge(const Check& check) const;  // a slip check

  // Closes wheels.csv; with `plots`, draws wheels.png and steady_states.png; fills result.wheels,
  // result.not_wheels, result.steady_states and result.files.
  void write(ScenarioResult& result, bool plots);

 private:
  struct Window {  // a slip check's sums
    double sum = 0.0;
    long samples = 0;
  };
  struct Figures {  // per wheel, over the run while in the soil
    double slip_sum = 0.0, traction_sum = 0.0, max_sinkage = 0.0, sinkage_sum = 0.0, rut_sum = 0.0;
    long samples = 0, moving = 0;
  };
  struct Steady {  // a steady-state window's sums
    double slip = 0.0, drawbar = 0.0, load = 0.0, torque = 0.0, sinkage = 0.0;
    long samples = 0, moving = 0;
  };
  void write_steady_states(ScenarioResult& result, bool plots);

  const Scenario& scenario_;
  std::string dir_;
  bool active_ = false;
  std::vector<physics::SoilWheelInfo> wheels_;
  std::vector<std::string> not_wheels_;
  std::vector<int> check_wheel_;  // per check: -1 every wheel, else the wheel's index
  std::vector<Window> windows_;
  std::vector<Figures> figures_;
  int steady_wheel_ = -1;
  std::vector<Steady> steady_;
  std::uint64_t record_every_ = 1;
  std::ofstream csv_;
};

}  // namespace mechsim::sim
