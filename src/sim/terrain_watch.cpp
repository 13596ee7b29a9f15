#include "sim/terrain_watch.hpp"

#include <algorithm>
#include <cstdio>

namespace mechsim::sim {

TerrainWatch::TerrainWatch(const World& world) : usable_(world.usable), what_(world.usable_what) {
  if (world.spec.terrain && !world.spec.terrain->heights.empty()) {
    lowest_ = *std::min_element(world.spec.terrain->heights.begin(), world.spec.terrain->heights.end());
  }
}

std::optional<std::string> TerrainWatch::outside(const physics::Bounds& robot) const {
  if (!usable_ || robot.empty()) return std::nullopt;
  const physics::Region& u = *usable_;
  if (robot.min.x >= u.x_min && robot.max.x <= u.x_max && robot.min.y >= u.y_min && robot.max.y <= u.y_max) return std::nullopt;
  char text[640];
  std::snprintf(text, sizeof text,
                "the robot's footprint x [%.2f, %.2f] m, y [%.2f, %.2f] m is not inside %s: x [%.2f, %.2f] m, y [%.2f, %.2f] m",
                robot.min.x, robot.max.x, robot.min.y, robot.max.y, what_.c_str(), u.x_min, u.x_max, u.y_min, u.y_max);
  return std::string(text);
}

}  // namespace mechsim::sim
