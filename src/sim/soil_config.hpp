#pragma once
// A scenario's `world: {soil: ...}`: a named soil (physics/soil.hpp), a soil file (what `mechsim
// soil fit` writes), or the user's values on top of either.
//
//   soil: dry_sand                       # a named set (mechsim world soils lists them)
//   soil: fitted/cmu_sand.soil.yaml      # a soil file (.yaml/.yml; relative to the scenario)
//   soil:                                # or the user's own values, SI units
//     base: lunar_regolith               # optional: start from a named set or a soil file
//     model: ding                        # wong_reece (default) | ding (physics/terramechanics.hpp)
//     n: 1.0                             # pressure-sinkage exponent
//     k_c: 1400                          # N/m^(n+1) (may be < 0 with k_phi > 0: a plate fit in sand)
//     k_phi: 820000                      # N/m^(n+2)
//     cohesion: 170                      # Pa
//     friction_angle_deg: 35
//     shear_modulus: 0.0178              # K (m), Janosi-Hanamoto
//     c1: 0.43                           # angle of largest stress (c1 + c2 slip) theta_1
//     c2: 0.32
//     exit_ratio: 0.0                    # wong_reece: theta_2 = -exit_ratio theta_1
//     rear_ratio: 0.05                   # ding: theta_2 = -acos(1 - rear_ratio z / r)
//     n1: 0.0                            # ding: slip sinkage, exponent n + n1 s (driving)
//     n2: 0.0                            #       and n + n2 |s| (braking)
//     bedrock_depth: 0.06                # m below the surface: the wheels' rigid contact
//     multi_pass: false                  # true: wheels run in the ruts others left
//                                        # (terramechanics.hpp, rut_depth)
//
// A soil file is the map form with `name` and `source` (and no `base`): its values are taken as
// they are, under its name.

#include <filesystem>
#include <string>

#include "control/params.hpp"
#include "physics/soil.hpp"

namespace mechsim::sim {

// Throws ScenarioError naming the file, line and parameter: an unknown soil or key, a value out
// of range (physics::check_soil), a soil file that cannot be read. `base` is the folder relative
// soil files are found from (the scenario's).
physics::SoilParameters read_soil(const control::Params& node, const std::filesystem::path& base = {});

// The map's soil keys (as above, without base) laid over `start`. Throws ScenarioError.
physics::SoilParameters read_soil_over(const control::Params& node, const physics::SoilParameters& start);

// A named soil, or a soil file (a name ending in .yaml or .yml; relative to `base`), as `mechsim
// bench --soil` and `mechsim tune` take them. Throws ScenarioError.
physics::SoilParameters soil_by_name(const std::string& name, const std::filesystem::path& base = {});

// The soil as a soil file's text (read_soil reads it back to the same values), `comment` (lines
// without their '#') at its top.
std::string soil_yaml(const physics::SoilParameters& soil, const std::string& comment = {});

}  // namespace mechsim::sim
