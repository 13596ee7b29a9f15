#pragma once
// The Bekker-Wong model of a rigid wheel in soil (Wong and Reece, "Prediction of rigid wheel
// performance based on the analysis of soil-wheel stresses", J. Terramechanics 4(1), 1967; the
// lateral shear as Ishigami et al., J. Field Robotics 24(3), 2007): pure functions, no MuJoCo.
//
// The wheel (radius r, width b) has sunk z into the soil; its rim meets the soil between the
// entry angle theta_1 = acos(1 - z / r) ahead of the bottom and the exit angle theta_2 =
// -exit_ratio theta_1 behind it (angles from straight down, positive towards the heading). On
// the rim:
//   normal stress   sigma(theta) = (k_c / b + k_phi) r^n (cos theta - cos theta_1)^n ahead of the
//                   angle of largest stress theta_m = (c1 + c2 slip) theta_1, and the same shape
//                   stretched over [theta_2, theta_m] behind it (Wong and Reece);
//   shear           tau = (c + sigma tan phi) (1 - exp(-j / K)) (Janosi and Hanamoto), along the
//                   soil's displacement j = (j_x, j_y): j_x(theta) = r [(theta_1 - theta) - (1 -
//                   slip)(sin theta_1 - sin theta)] along the heading, j_y growing linearly from 0
//                   at entry to `lateral_shear` at exit across it;
// and the forces on the wheel are their integrals over the rim (r b d theta per unit angle).
// Slip: (r omega - v) / (r omega) driving (0..1), (r omega - v) / v braking (-1..0).
//
// Two models, chosen per soil (SoilParameters::model):
// - wong_reece (the default): the above, with theta_2 = -exit_ratio theta_1 (0: no rebound, as Wong
//   and Reece assumed for sand).
// - ding: Ding, Deng, Gao, Tao, Iagnemma and Liu, "Interaction mechanics model for rigid driving
//   wheels of planetary rovers moving on sandy terrain with consideration of multiple physical
//   effects", J. Field Robotics 32(6), 2015 (after Ding et al., "Experimental study and analysis on
//   driving wheels' performance for planetary exploration rovers moving in deformable soil",
//   J. Terramechanics 48(1), 2011), built for small, lightly loaded rover wheels in sand, where the
//   plate-based Wong-Reece wheel meets too much compaction resistance: its whole normal stress
//   lies ahead of the lowest point (theta_2 = 0), so the stress leans back by about theta_1 / 2,
//   0.35-0.45 of the load for a wheel sunk a third of its radius. In Ding's model
//   * the rim stays in contact behind its lowest point up to where the soil, springing and flowing
//     back, stands rear_ratio x z above it: theta_2 = -acos(1 - rear_ratio z / r) (Ding's lambda;
//     the stress behind theta_m is Wong and Reece's stretched shape over [theta_2, theta_m]). A
//     millimetre of rebound under a 6 cm wheel is a fifth of its contact arc: the stress there
//     pushes the wheel forward and carries part of the load, so it sinks less and meets less
//     resistance;
//   * slip sinkage: the exponent grows with slip, N = n + n1 s (driving) or n + n2 |s| (braking),
//     in Reece's dimensionless form sigma = (k_c / b + k_phi) b^n (z(theta) / b)^N with z(theta) =
//     r (cos theta - cos theta_1), which is Bekker's (k_c / b + k_phi) z^n at N = n (Ding et al.
//     write Reece's moduli; mechsim keeps Bekker's, which plate tests give, in the same form).
// - Grousers (lugs; both models): a wheel with grousers of height h shears the soil at their tips,
//   r_s = r + lambda_s h (Ding, Gao, Deng, Yoshida and Nagatani, "Slip ratio for lugged wheel of
//   planetary rover in deformable soil: definition and estimation", IROS 2009), so the shear
//   displacement gains (r_s - r)(theta_1 - theta) and the shear's moment arm is r_s. mechsim takes
//   lambda_s as the share of a grouser spacing the contact spans, min(1, count (theta_1 -
//   theta_2) / 2 pi): fully effective once a grouser is always in the soil.

#include "physics/soil.hpp"

namespace mechsim::physics {

struct WheelShape {
  double radius = 0.0;  // m, of the rim (grousers stand on it)
  double width = 0.0;   // m
  double grouser_height = 0.0;  // m; 0: a smooth wheel
  int grouser_count = 0;        // around the rim
};

// What the soil exerts on the wheel, in the wheel's contact frame: normal n (out of the soil),
// heading x (the direction the wheel rolls) and lateral y = n x x, the axle (a spin about +y
// rolls the wheel towards +x). Moments are about the wheel's centre.
struct WheelSoilForces {
  double normal = 0.0;    // N along n: the load the soil carries
  double drawbar = 0.0;   // N along x: drawbar pull (thrust minus resistance), > 0 pulls forward
  double resistance = 0.0;  // N: the normal stress's part of it, r b integral sigma sin theta (the
                            // compaction resistance; drawbar = shear's thrust - resistance)
  double lateral = 0.0;   // N along y: opposes the wheel's sideways slide
  double torque = 0.0;    // N m about y: the shear's moment -r^2 b integral tau; < 0 resists a driven wheel
  double moment_normal = 0.0;   // N m about n from the lateral shear (self-aligning)
  double moment_heading = 0.0;  // N m about x from the lateral shear
  double entry_angle = 0.0, exit_angle = 0.0;  // theta_1, theta_2 (rad)
  double shear_radius = 0.0;  // m: r_s, where the shear acts (the rim's radius without grousers)
};

// The forces for sinkage `sinkage` (m, >= 0; above the wheel's radius counts as the radius), the
// slip (clamped to [-1, 1]) and `lateral_shear`, how far (m) the rim has slid sideways (+y) over
// the soil by the exit. Zero when sinkage <= 0.
// Allocation-free (a fixed Gauss-Legendre rule over each side of theta_m).
// `rolling` in [0, 1] scales the rim's own share of j_x, r (1 - slip) [(theta_1 - theta) - (sin
// theta_1 - sin theta)]: 1 for a rolling wheel (Wong and Reece), 0 for one at rest, whose shear
// is its slip's alone.
//
// Multi-pass: `rut_depth` (m) is how deep an earlier wheel compacted the soil along this one's
// path (its sinkage there, below the same surface). Soil loaded before gives under a new load only
// once the load exceeds the earlier one (Wong's repetitive loading, with the unloading-reloading
// line taken as rigid), so the rut's floor is the surface the rim meets, and a point of the rim
// sunk d below the floor meets the virgin curve's stress at its depth below the old surface,
// (k_c / b + k_phi) (rut_depth + d)^n: the stress starts at the earlier pass's pressure instead of
// zero. Angles, the stress's shape and the shear count from the rut's floor. A wheel in a rut as
// deep as its own sinkage sinks a little further and meets less compaction resistance: why a
// rover's middle and rear wheels roll more easily than its front ones. `sinkage` stays the depth
// below the old surface; the rim above the rut's floor meets nothing.
WheelSoilForces wheel_soil_forces(const SoilParameters& soil, const WheelShape& wheel, double sinkage, double slip,
                                  double lateral_shear = 0.0, double rolling = 1.0, double rut_depth = 0.0);

// A wheel carrying `load` (N) at steady slip `slip`, as a single-wheel test rig measures it:
// the sinkage where the soil's normal force equals the load (bisection), and the forces there.
struct SteadyWheel {
  double sinkage = 0.0;  // m
  WheelSoilForces forces;
  bool ok = false;       // false when the soil cannot carry the load before the wheel sinks its radius
};
SteadyWheel steady_wheel(const SoilParameters& soil, const WheelShape& wheel, double load, double slip,
                         double rut_depth = 0.0);

}  // namespace mechsim::physics
