#pragma once
// Whether the robot is on the world's usable ground: its footprint (the x-y extent of its
// collision geometry) inside World::usable. Past a height field's edge there is no ground (the
// robot would fall for ever); the Mars Yard's flat border is outside the yard.

#include <optional>
#include <string>

#include "physics/physics.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {

class TerrainWatch {
 public:
  explicit TerrainWatch(const World& world);

  // Whether the world has an edge to watch (`empty` has none).
  bool active() const { return usable_.has_value(); }
  // Empty when `robot` (Physics::robot_bounds) lies inside the usable ground, or the world has
  // no edge; else a sentence saying where the footprint is against which ground.
  std::optional<std::string> outside(const physics::Bounds& robot) const;
  // The robot's top is this far (m) below the lowest ground: it has fallen off the world.
  bool fallen(const physics::Bounds& robot) const { return usable_ && !robot.empty() && robot.max.z < lowest_ - kFallDepth; }

  static constexpr double kFallDepth = 10.0;  // m (the event's text says 10 m)

 private:
  std::optional<physics::Region> usable_;
  std::string what_;
  double lowest_ = 0.0;  // m, the lowest ground height
};

}  // namespace mechsim::sim
