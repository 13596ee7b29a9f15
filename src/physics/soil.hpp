#pragma once
// Soil parameters of the wheel-soil models (terramechanics.hpp), named sets from published
// tables, and the user's own values on top of a named set (or fitted to plate tests: soil_fit.hpp).
//
// Units are SI throughout: Bekker's moduli k_c in N/m^(n+1) and k_phi in N/m^(n+2) (the tables
// give kN/m^(n+1) and kN/m^(n+2): multiplied by 1000 here), cohesion in Pa, angles in radians,
// lengths in m.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::physics {

// Which wheel-soil model a soil uses (terramechanics.hpp says what each one is).
enum class WheelSoilModel {
  WongReece,  // Wong and Reece (1967): the plate-based Bekker-Wong rigid wheel
  Ding,       // Ding et al. (2011, 2015): rear contact, slip sinkage; for small, lightly loaded wheels
};
// "wong_reece" / "ding", and back (nullopt for an unknown name).
const char* model_name(WheelSoilModel model);
std::optional<WheelSoilModel> find_model(std::string_view name);

struct SoilParameters {
  std::string name;        // the named set it came from ("" for none), for reports
  double n = 1.0;          // pressure-sinkage exponent (dimensionless)
  // Bekker's p = (k_c / b + k_phi) z^n, b the smaller side of the loaded area (a plate's radius,
  // a wheel's width). k_c may be negative, as plate tests in sand often give (the pressure at a
  // sinkage grows with the plate's size); then k_c / b + k_phi must stay > 0 for each wheel's
  // width (positive_modulus), which Physics::set_soil checks wheel by wheel.
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
  // The wheel-soil model (terramechanics.hpp) and the Ding model's own parameters.
  WheelSoilModel model = WheelSoilModel::WongReece;
  // Ding: the rim leaves the soil behind the wheel at the height rear_ratio x sinkage above its
  // lowest point, theta_2 = -acos(1 - rear_ratio z / r) (the soil's rebound and flow back, lambda
  // in Ding et al. 2015). exit_ratio is Wong-Reece's alone.
  double rear_ratio = 0.05;
  // Ding: slip sinkage, the pressure-sinkage exponent n + n1 s driving (s > 0) and n + n2 |s|
  // braking, in Reece's dimensionless form (terramechanics.hpp). 0: no slip sinkage beyond the
  // Wong-Reece stress shift. Wheel-test parameters: plate tests do not give them.
  double n1 = 0.0, n2 = 0.0;
  // Citation of the values (shown in reports and `mechsim world soils`).
  std::string source;
};

// The named sets (see soil.cpp for each one's source), in a stable order.
const std::vector<SoilParameters>& named_soils();
// The set called `name`, or nullopt.
std::optional<SoilParameters> find_soil(std::string_view name);

// Empty when the values make sense (n in (0, 3], k_phi >= 0, k_c >= 0 or k_phi > 0 (a negative
// k_c needs a positive k_phi), not both 0, cohesion >= 0, friction angle in [0, 80 deg), K > 0,
// 0 <= c1 + c2 <= 1 with c1 >= 0, exit_ratio and rear_ratio in [0, 1], n + n1 and n + n2 in
// (0, 3], bedrock_depth > 0); otherwise what is wrong, naming the parameter.
std::string check_soil(const SoilParameters& soil);

// k_c / width + k_phi (N/m^(n+2)): Bekker's modulus for a loaded area `width` (m) wide.
double bekker_modulus(const SoilParameters& soil, double width);
// Empty when bekker_modulus(soil, width) > 0; otherwise what is wrong, with the narrowest width
// the soil can carry (a fit with k_c < 0 holds above it only).
std::string check_soil_width(const SoilParameters& soil, double width);

}  // namespace mechsim::physics
