#include "physics/soil.hpp"

#include <cmath>
#include <cstdio>

namespace mechsim::physics {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A set from a table in kN/m^(n+1), kN/m^(n+2), kPa and degrees.
SoilParameters table_row(const char* name, double n, double k_c_kN, double k_phi_kN, double c_kPa, double phi_deg,
                         double K_m, const char* source) {
  SoilParameters s;
  s.name = name;
  s.n = n;
  s.k_c = 1000.0 * k_c_kN;
  s.k_phi = 1000.0 * k_phi_kN;
  s.cohesion = 1000.0 * c_kPa;
  s.friction_angle = phi_deg * kDeg;
  s.shear_modulus = K_m;
  s.source = source;
  return s;
}

// Wong, J. Y., Theory of Ground Vehicles, 4th ed., Wiley 2008, Table 2.3 "Terrain values"
// (after Bekker and others): n, k_c, k_phi, c, phi. The table gives no shear deformation modulus
// K; mechsim takes 1 cm, of the order Janosi and Hanamoto (1961) report for sands and loams, and
// says so in each set's source: set `shear_modulus` for a soil you have measured.
std::vector<SoilParameters> make_named_soils() {
  std::vector<SoilParameters> out;
  out.push_back(table_row("dry_sand", 1.1, 0.99, 1528.43, 1.04, 28.0, 0.01,
                          "dry sand (Land Locomotion Lab, 0 % moisture): "
                          "Wong, Theory of Ground Vehicles, 4th ed. (2008), Table 2.3; K assumed 1 cm"));
  out.push_back(table_row("lete_sand", 0.79, 102.0, 5301.0, 1.3, 31.1, 0.01,
                          "LETE sand (Wong): Wong, Theory of Ground Vehicles, 4th ed. (2008), Table 2.3; K assumed 1 cm"));
  out.push_back(table_row("sandy_loam", 0.7, 5.27, 1515.04, 1.72, 29.0, 0.01,
                          "sandy loam (Land Locomotion Lab, 15 % moisture): "
                          "Wong, Theory of Ground Vehicles, 4th ed. (2008), Table 2.3; K assumed 1 cm"));
  out.push_back(table_row("clayey_soil", 0.5, 13.19, 692.15, 4.14, 13.0, 0.01,
                          "clayey soil (Thailand, 38 % moisture): "
                          "Wong, Theory of Ground Vehicles, 4th ed. (2008), Table 2.3; K assumed 1 cm"));
  out.push_back(table_row("snow", 1.6, 4.37, 196.72, 1.03, 19.7, 0.01,
                          "snow (U.S.): Wong, Theory of Ground Vehicles, 4th ed. (2008), Table 2.3; K assumed 1 cm"));
  // Lunar regolith as Bekker (Introduction to Terrain-Vehicle Systems, 1969) gave it for the
  // Apollo rovers' design, the values the Lunar Sourcebook (Carrier, Olhoeft and Mendell 1991,
  // ch. 9) and planetary rover studies since quote: n = 1, k_c = 1.4 kN/m^2, k_phi = 820 kN/m^3,
  // c = 0.17 kPa, phi = 35 deg, K = 1.78 cm.
  out.push_back(table_row("lunar_regolith", 1.0, 1.4, 820.0, 0.17, 35.0, 0.0178,
                          "lunar regolith: Bekker (1969) as quoted in the Lunar Sourcebook (Carrier et al. 1991), "
                          "n 1, k_c 1.4 kN/m^2, k_phi 820 kN/m^3, c 0.17 kPa, phi 35 deg, K 1.78 cm"));
  return out;
}

}  // namespace

const char* model_name(WheelSoilModel model) {
  return model == WheelSoilModel::Ding ? "ding" : "wong_reece";
}

std::optional<WheelSoilModel> find_model(std::string_view name) {
  if (name == "wong_reece") return WheelSoilModel::WongReece;
  if (name == "ding") return WheelSoilModel::Ding;
  return std::nullopt;
}

const std::vector<SoilParameters>& named_soils() {
  static const std::vector<SoilParameters> soils = make_named_soils();
  return soils;
}

std::optional<SoilParameters> find_soil(std::string_view name) {
  for (const SoilParameters& s : named_soils())
    if (s.name == name) return s;
  return std::nullopt;
}

std::string check_soil(const SoilParameters& s) {
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(s.n) || !(s.n > 0.0 && s.n <= 3.0)) return "n must be in (0, 3], got " + std::to_string(s.n);
  if (!finite(s.k_c) || !finite(s.k_phi) || s.k_phi < 0.0 || (s.k_c < 0.0 && !(s.k_phi > 0.0)) || (s.k_c == 0.0 && s.k_phi == 0.0))
    return "k_phi must be >= 0 and k_c >= 0 or k_phi > 0, not both 0 (N/m^(n+1), N/m^(n+2))";
  if (!finite(s.cohesion) || s.cohesion < 0.0) return "cohesion must be >= 0 (Pa), got " + std::to_string(s.cohesion);
  if (!finite(s.friction_angle) || s.friction_angle < 0.0 || s.friction_angle >= 80.0 * kDeg)
    return "friction angle must be in [0, 80) degrees, got " + std::to_string(s.friction_angle / kDeg);
  if (!finite(s.shear_modulus) || !(s.shear_modulus > 0.0)) return "shear modulus K must be > 0 (m), got " + std::to_string(s.shear_modulus);
  if (!finite(s.c1) || !finite(s.c2) || s.c1 < 0.0 || s.c1 + s.c2 < 0.0 || s.c1 + s.c2 > 1.0 || s.c1 > 1.0)
    return "c1 and c2 must give an angle of largest stress (c1 + c2 slip) theta_1 within the contact: c1 in [0, 1], "
           "c1 + c2 in [0, 1]";
  if (!finite(s.exit_ratio) || s.exit_ratio < 0.0 || s.exit_ratio > 1.0) return "exit ratio must be in [0, 1]";
  if (!finite(s.rear_ratio) || s.rear_ratio < 0.0 || s.rear_ratio > 1.0) return "rear ratio must be in [0, 1]";
  if (!finite(s.n1) || !finite(s.n2) || !(s.n + s.n1 > 0.0 && s.n + s.n1 <= 3.0) || !(s.n + s.n2 > 0.0 && s.n + s.n2 <= 3.0))
    return "n1 and n2 must keep the slip sinkage exponents n + n1 and n + n2 in (0, 3]";
  if (!finite(s.bedrock_depth) || !(s.bedrock_depth > 0.0)) return "bedrock depth must be > 0 (m)";
  return {};
}

double bekker_modulus(const SoilParameters& soil, double width) { return soil.k_c / width + soil.k_phi; }

std::string check_soil_width(const SoilParameters& soil, double width) {
  if (bekker_modulus(soil, width) > 0.0) return {};
  char text[256];
  std::snprintf(text, sizeof text,
                "k_c / b + k_phi = %.4g N/m^(n+2) is not > 0 for a width b of %.4g m (k_c %.4g, k_phi %.4g): this soil "
                "carries widths above %.4g m only",
                bekker_modulus(soil, width), width, soil.k_c, soil.k_phi, soil.k_phi > 0.0 ? -soil.k_c / soil.k_phi : 0.0);
  return text;
}

}  // namespace mechsim::physics
