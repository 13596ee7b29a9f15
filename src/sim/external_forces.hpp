#pragma once
// Forces from outside the robot, as Gazebo's /gazebo/apply_body_wrench and apply_joint_effort
// apply them: each from a start time for a duration of simulation time, added to everything else
// acting on the body or joint. The Simulation applies the active ones before each physics step
// (sim/simulation.hpp); with none queued the tick does not look at them.

#include <cstddef>
#include <string>
#include <vector>

#include "description/pose.hpp"

namespace mechsim::physics {
class Physics;
}

namespace mechsim::sim {

// A wrench on a link, world frame: force_W (N) acting at the centre of mass of the link's body
// moved by offset_W (m), plus torque_W (N m) (physics::Physics::add_link_wrench).
struct LinkWrench {
  std::size_t link = 0;  // physics::PhysicsModel::link_index
  description::Vec3 force_W, torque_W, offset_W;
};

// Start and end in simulation time (s); end < 0: no end.
struct ForceWindow {
  double start = 0.0;
  double end = -1.0;
  bool active_at(double t) const { return t + 1e-12 >= start && (end < 0.0 || t + 1e-12 < end); }
  bool over_at(double t) const { return end >= 0.0 && t + 1e-12 >= end; }
};

// The window Gazebo gives a request at simulation time `now` with a step of `period`: a start in
// the past starts now; duration < 0 has no end; 0 does nothing (nullopt-like: end == start);
// shorter than a step lasts one step.
ForceWindow force_window(double now, double period, double start_time, double duration);

class ExternalForces {
 public:
  bool empty() const { return wrenches_.empty() && efforts_.empty(); }
  // Whether the next step must apply(): some are queued, or the physics still holds forces that
  // were cleared since (clear_* between ticks).
  bool active() const { return !empty() || in_physics_; }
  void add_wrench(const LinkWrench& wrench, ForceWindow window) { wrenches_.push_back({wrench, window}); }
  void add_effort(std::size_t joint, double effort, ForceWindow window) { efforts_.push_back({joint, effort, window}); }
  // Removes every wrench on `link` / effort on `joint`; returns how many.
  std::size_t clear_wrenches(std::size_t link);
  std::size_t clear_efforts(std::size_t joint);
  // After the physics was reset (which drops its external forces).
  void clear() {
    wrenches_.clear();
    efforts_.clear();
    in_physics_ = false;
  }
  // Loop thread, before the physics step at time `t`: writes the sum of the active ones into
  // `physics` (replacing what it held) and drops those that are over. No allocation.
  void apply(physics::Physics& physics, double t);

 private:
  struct TimedWrench {
    LinkWrench wrench;
    ForceWindow window;
  };
  struct TimedEffort {
    std::size_t joint;
    double effort;
    ForceWindow window;
  };
  std::vector<TimedWrench> wrenches_;
  std::vector<TimedEffort> efforts_;
  bool in_physics_ = false;  // the last apply() wrote forces that are still in the physics
};

}  // namespace mechsim::sim
