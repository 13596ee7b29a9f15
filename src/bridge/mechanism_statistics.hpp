#pragma once
// The PR2 controller manager's joint and actuator bookkeeping for joint_states and
// mechanism_statistics (C++20 side of the bridge; sim_bridge.hpp has the data types).
//
// update() runs after every tick in the loop thread (a Simulation observer) and only folds the
// tick into the window: min/max position, max |velocity|, max |measured effort|, the odometer
// and whether a limit was violated. take() copies the window out and starts a new one. It
// allocates nothing after the first take (the output vectors keep their capacity).

#include <cstdint>
#include <vector>

#include "bridge/sim_bridge.hpp"

namespace mechsim::sim {
class Simulation;
}

namespace mechsim::bridge {

class MechanismStatistics {
 public:
  // The joints: every non-fixed joint of the simulation's robot, in description order.
  explicit MechanismStatistics(const sim::Simulation& simulation);

  void update(const sim::Simulation& simulation) noexcept;
  void joint_states(const sim::Simulation& simulation, JointStatesData& out) const;
  void take(const sim::Simulation& simulation, MechanismStatisticsData& out);

 private:
  struct Source {
    int mechanism = -1;  // mechanism joint index, -1: none
    int physics = -1;    // physics joint index, -1: none
    double lower = 0.0, upper = 0.0;  // rad or m; lower > upper: no position limits
    double effort_limit = 0.0;        // N m or N; 0: none
  };
  struct Window {
    bool initialized = false;
    bool violated = false;
    double min_position = 0.0, max_position = 0.0;
    double max_abs_velocity = 0.0, max_abs_effort = 0.0;
    double odometer = 0.0, last_position = 0.0;
  };
  struct Sample {
    double position = 0.0, velocity = 0.0, measured_effort = 0.0, commanded_effort = 0.0;
  };
  Sample sample(const sim::Simulation& simulation, const Source& source) const noexcept;

  std::vector<std::string> names_;
  std::vector<Source> sources_;
  std::vector<Window> windows_;
  std::uint64_t resets_seen_ = 0;
  std::uint64_t generation_ = 0;  // the physics' generation the physics indices are of
};

}  // namespace mechsim::bridge
