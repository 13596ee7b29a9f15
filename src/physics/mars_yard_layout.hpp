#pragma once
// Internal to the Mars Yard generator: lays out the landforms and rocks from the RNG, at
// their nominal sizes (the generator scales landform heights afterwards).

#include <random>

#include "physics/mars_yard.hpp"

namespace mechsim::physics::detail {

// Fills usable, start, canyon, river, dunes, craters, mounds and rocks of `yard`.
void lay_out_mars_yard(std::mt19937_64& rng, const MarsYardParams& params, MarsYard& yard);

}  // namespace mechsim::physics::detail
