#pragma once
// A scenario's `world: {wheels: ...}`: which links the soil treats as wheels, over what the
// description says (physics/wheel_identify.hpp: a collision cylinder turning about its own axis on
// a revolute or continuous joint, narrow or wide). Each key is a link ("<robot>::<link>" for
// another robot's):
//
//   wheels:
//     caster_wheel_link: false                    # not a soil wheel (rigid contact)
//     wheel_link: {grousers: {height: 0.005, count: 12}}       # a wheel's grousers (m)
//     wheel_link_2: {radius: 0.06, width: 0.05}   # its dimensions for the soil (m)
//     hub_link: {radius: 0.1, width: 0.04}        # a mesh or sphere on a turning joint made a wheel
//
// Every override applies only with a soil (world.soil). Errors name the file, line and key.

#include <vector>

#include "control/params.hpp"
#include "physics/wheel_override.hpp"

namespace mechsim::sim {

// Throws ScenarioError: not a map, an unknown key, a value out of range.
std::vector<physics::WheelOverride> read_wheel_overrides(const control::Params& node);

}  // namespace mechsim::sim
