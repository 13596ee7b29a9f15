#pragma once
// Soil parameters of the Bekker-Wong wheel-soil model (terramechanics.hpp), named sets from
// published tables, and the user's own values on top of a named set.
//
// Units are SI throughout: Bekker's moduli k_c in N/m^(n+1) and k_phi in N/m^(n+2) (the tables
// give kN/m^(n+1) and kN/m^(n+2): multiplied by 1000 here), cohesion in Pa, angles in radians,
// lengths in m.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::physics {

struct SoilParameters {
  std::string name;        // the named set it came from ("" for none), for reports
  double n = 1.0;          // pressure-sinkage exponent (dimensionless)
  double k_c = 0.0;        // cohesive modulus of deformation, N/m^(n+1)
  double k_phi = 0.0;      // frictional modulus of deformation, N/m^(n+2)
  double cohesion = 0.0;   // c, Pa
  double friction_angle = 0.0;  // phi, rad (internal friction)
  double shear_modulus = 0.025;  // K, Janosi-Hanamoto shear deformation modulus, m
  // Wong and Reece (1967): the angle of the largest normal stress is (c1 + c2 slip) theta_1.
  // Their fit for sand: c1 = 0.43, c2 = 0.32.
  double c1 = 0.43, c2 = 0.32;
  // Exit angle as a fraction of the entry angle (rebound of the soil behind the wheel): theta_2 =
  // -exit_ratio * theta_1. 0: the soil does not spring back (Wong and Reece's assumption).
  double exit_ratio = 0.0;
  // Depth (m) below the soil surface where a rigid bedrock stops the wheel (MuJoCo's rigid
  // contact there): a bound on sinkage for soils too soft for the load.
  double bedrock_depth = 0.06;
  // Multi-pass (opt-in): a wheel that follows another in its rut meets soil the first one
  // compacted (terramechanics.hpp, rut_depth). false: every wheel meets virgin soil.
  bool multi_pass = false;
  // Citation of the values (shown in reports and `mechsim world soils`).
  std::string source;
};

// The named sets (see soil.cpp for each one's source), in a stable order.
const std::vector<SoilParameters>& named_soils();
// The set called `name`, or nullopt.
std::optional<SoilParameters> find_soil(std::string_view name);

// Empty when the values make sense (n in (0, 3], moduli >= 0 and not both 0, cohesion >= 0,
// friction angle in [0, 80 deg), K > 0, 0 <= c1 + c2 <= 1 with c1 >= 0, exit_ratio in [0, 1],
// bedrock_depth > 0); otherwise what is wrong, naming the parameter.
std::string check_soil(const SoilParameters& soil);

}  // namespace mechsim::physics
