#pragma once
// What a report keeps for `mechsim view` (a 3D replay in a browser): the world pose of every
// URDF link at the scenario's replay_rate, and beside it the robot's visuals, the world and a
// manifest with a format version, all under <report>/replay/:
//   manifest.json  format "mechsim-replay", version kReplayFormatVersion, link names, the world's
//                  free objects' and passive models' moving bodies (`objects`: world.json box and
//                  body names), frame count
//   poses.bin      float32 little-endian frames: t (s), then per link x y z (m) qw qx qy qz (W),
//                  then the same per object (a box: the pose of its shape, as world.json's box
//                  pose; a passive body: its frame, world.json's body shapes are in it)
//   robot.json     the links' visuals (box, cylinder, sphere, mesh), origins X_LV, colours
//   robot.urdf     the expanded description as the run loaded it
//   meshes/        each visual mesh as binary STL or OBJ (Collada converted by assimp)
//   world.json     ground plane, boxes, the passive models' bodies and their primitive shapes
//                  (meshes not drawn), the height field's grid and extent
//   terrain.bin    the height field's heights (float32, row-major, row 0 south), when there is one

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sim/scenario.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

inline constexpr int kReplayFormatVersion = 1;
inline constexpr const char* kReplayFormatName = "mechsim-replay";

class ReplayRecorder {
 public:
  // Records nothing when `dir` (the report folder) is empty or scenario.replay_rate is 0. Writes
  // the robot, world and mesh files now; throws ScenarioError naming a file it cannot write.
  ReplayRecorder(const Simulation& sim, const Scenario& scenario, const std::string& dir, const std::string& urdf);
  bool active() const { return active_; }
  // In a control observer, every tick: samples the links' poses when a replay frame is due (every
  // 1/replay_rate s, and at `last_tick`). Allocates nothing: one buffered write of a fixed frame.
  void observe(const Simulation& sim, std::uint64_t last_tick);
  // Closes poses.bin and writes manifest.json (last, so that a folder with a manifest is complete);
  // `report_files` are the report's files (its PNG plots are listed for the page, base.csv for
  // the odometry trace when `has_odometry`, and the lasers' CSV files: `sensor_files[i]` is
  // sensor i's of the simulation's SensorSet).
  void finish(const Simulation& sim, const std::vector<std::string>& report_files, bool has_odometry,
              const std::vector<std::string>& sensor_files);
  std::uint64_t frames() const { return frames_; }

 private:
  bool active_ = false;
  std::filesystem::path dir_;  // <report>/replay
  std::uint64_t every_ = 1;    // ticks per frame
  std::uint64_t frames_ = 0;
  double rate_ = 0.0;
  std::vector<float> frame_;   // 1 + 7 * (links + objects)
  std::vector<int> object_bodies_;  // the free world objects' physics bodies
  std::vector<std::string> object_names_;
  std::vector<char> buffer_;   // poses.bin's stream buffer, sized once
  std::ofstream poses_;
  std::string scenario_name_;
  std::vector<std::array<double, 2>> waypoints_;
};

}  // namespace mechsim::sim
