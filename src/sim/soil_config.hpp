#pragma once
// A scenario's `world: {soil: ...}`: a named soil (physics/soil.hpp) or the user's values on top
// of one.
//
//   soil: dry_sand                       # a named set (mechsim world soils lists them)
//   soil:                                # or the user's own values, SI units
//     base: lunar_regolith               # optional: start from a named set
//     n: 1.0                             # pressure-sinkage exponent
//     k_c: 1400                          # N/m^(n+1)
//     k_phi: 820000                      # N/m^(n+2)
//     cohesion: 170                      # Pa
//     friction_angle_deg: 35
//     shear_modulus: 0.0178              # K (m), Janosi-Hanamoto
//     c1: 0.43                           # angle of largest stress (c1 + c2 slip) theta_1
//     c2: 0.32
//     exit_ratio: 0.0                    # theta_2 = -exit_ratio theta_1
//     bedrock_depth: 0.06                # m below the surface: the wheels' rigid contact
//     multi_pass: false                  # true: wheels run in the ruts others left
//                                        # (terramechanics.hpp, rut_depth)

#include "control/params.hpp"
#include "physics/soil.hpp"

namespace mechsim::sim {

// Throws ScenarioError naming the file, line and parameter: an unknown soil or key, a value out
// of range (physics::check_soil).
physics::SoilParameters read_soil(const control::Params& node);

}  // namespace mechsim::sim
