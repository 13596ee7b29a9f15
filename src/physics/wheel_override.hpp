#pragma once
// What a world or scenario says about one link's part in the wheel-soil model (Physics::set_soil).

#include <optional>
#include <string>

namespace mechsim::physics {

// A world's or scenario's word on one link (sim/wheel_config.hpp), for Physics::set_soil: not a
// soil wheel (wheel false), or one with these dimensions and grousers. A link the model does not
// count as a wheel (physics/wheel_identify.hpp: a mesh, a sphere) becomes one: it turns on its
// link's revolute or continuous joint, the soil acts on its largest collision geom, and its
// radius and width must be given unless that geom is a cylinder or ellipsoid.
struct WheelOverride {
  std::string link;             // the link ("<model>::<link>" for another robot's)
  bool wheel = true;
  std::optional<double> radius, width;  // m; absent: the wheel's own
  double grouser_height = 0.0;  // m
  int grouser_count = 0;
  std::string origin;           // where it was written (file:line), for errors
};

}  // namespace mechsim::physics
