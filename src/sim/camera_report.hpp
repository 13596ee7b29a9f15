#pragma once
// The cameras' part of a scenario's report: at each of `camera_picture_times` every camera of the
// robot renders once (cameras nobody asks for never render), its frames are saved as PNG
// (cameras/<sensor>[_<camera>]_<t>s.png, depth sensors also ..._depth.png, near white, log scale over the kept range), and
// camera_sheet.png puts them side by side (a row per time).

#include <cstdint>
#include <string>
#include <vector>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

class CameraReport {
 public:
  // `dir` empty: nothing is requested or written.
  CameraReport(const Simulation& sim, const Scenario& scenario, const std::string& dir);

  // A control observer (before the physics step): when the coming step reaches a picture time,
  // asks every camera for one sample.
  void before_step(Simulation& sim);
  // An observer (after the sensors sampled): saves the new frames.
  void observe(const Simulation& sim);
  // Writes camera_sheet.png; adds the files to result.files, failures to result.warnings.
  void write(ScenarioResult& result);

 private:
  struct Tile {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
  };
  void save(const Simulation& sim, std::size_t camera, double picture_time);

  std::string dir_;
  std::vector<std::size_t> cameras_;  // sensor indices
  std::vector<double> times_;
  std::size_t next_request_ = 0;
  std::vector<std::uint64_t> seen_;  // reading counts already handled
  std::vector<double> requested_at_;  // picture time each camera owes (-1: none)
  std::vector<std::vector<Tile>> rows_;  // contact sheet: per picture time, the tiles
  std::vector<std::string> files_, warnings_;
};

}  // namespace mechsim::sim
