#include "physics/terramechanics.hpp"

#include <algorithm>
#include <cmath>

namespace mechsim::physics {
namespace {

// Gauss-Legendre, 6 points on [-1, 1]: exact for polynomials of degree 11.
constexpr double kNode[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                             0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr double kWeight[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                               0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

struct Sums {
  double n = 0.0, x = 0.0, y = 0.0, tau = 0.0, resist = 0.0, my_sin = 0.0, my_cos = 0.0;
};

}  // namespace

WheelSoilForces wheel_soil_forces(const SoilParameters& soil, const WheelShape& wheel, double sinkage, double slip,
                                  double lateral_shear, double rolling, double rut_depth) {
  WheelSoilForces f;
  const double r = wheel.radius, b = wheel.width;
  if (!(sinkage > 0.0) || !(r > 0.0) || !(b > 0.0)) return f;
  const double zr = std::isfinite(rut_depth) ? std::max(0.0, rut_depth) : 0.0;
  // Below the rut's floor (the surface itself without a rut).
  const double z = std::min(sinkage, r) - zr;
  if (!(z > 0.0)) return f;  // the rim does not reach the rut's floor: no soil under it
  const double s = std::clamp(slip, -1.0, 1.0);
  const bool ding = soil.model == WheelSoilModel::Ding;
  const double t1 = std::acos(1.0 - z / r);
  const double t2 = ding ? -std::acos(std::max(-1.0, 1.0 - soil.rear_ratio * z / r)) : -soil.exit_ratio * t1;
  const double tm = std::clamp((soil.c1 + soil.c2 * std::max(s, 0.0)) * t1, t2, t1);
  f.entry_angle = t1;
  f.exit_angle = t2;
  // sigma = K b^n (depth / b)^N: Bekker's K depth^n at N = n (Wong-Reece), Reece's dimensionless
  // form with Ding's slip sinkage exponent otherwise.
  const double N = ding ? soil.n + (s >= 0.0 ? soil.n1 * s : -soil.n2 * s) : soil.n;
  const double k = bekker_modulus(soil, b) * std::pow(b, soil.n);
  const double inv_b = 1.0 / b;
  const double cos1 = std::cos(t1), sin1 = std::sin(t1);
  const double tan_phi = std::tan(soil.friction_angle);
  const double span = t1 - t2;
  // Grousers: the shear acts at their tips, r_s = r + lambda_s h (Ding et al. 2009).
  double lug = 0.0;
  if (wheel.grouser_height > 0.0 && wheel.grouser_count > 0)
    lug = std::min(1.0, wheel.grouser_count * span / (2.0 * M_PI)) * wheel.grouser_height;
  const double rs = r + lug;
  f.shear_radius = rs;

  Sums sum;
  // sigma over [t2, tm] is the front's shape stretched: theta* = t1 - (theta - t2)/(tm - t2) (t1 - tm).
  const auto add = [&](double theta, double w, bool front) {
    double c_star = std::cos(theta);
    if (!front) c_star = std::cos(t1 - (theta - t2) / (tm - t2) * (t1 - tm));
    // The depth below the old surface of the soil under this point of the rim.
    const double depth = r * std::max(0.0, c_star - cos1) + zr;
    const double sigma = k * std::pow(depth * inv_b, N);
    // Wong and Reece's j = r [(t1 - theta) - (1 - s)(sin t1 - sin theta)], split into the slip's
    // part and the rolling rim's own (the arc being longer than its chord), which a wheel at rest
    // does not have; grousers add (r_s - r)(t1 - theta) while the wheel turns.
    const double jx = r * (s * (t1 - theta) + rolling * (1.0 - s) * ((t1 - theta) - (sin1 - std::sin(theta)))) +
                      rolling * lug * (t1 - theta);
    const double jy = span > 0.0 ? lateral_shear * (t1 - theta) / span : 0.0;
    const double j = std::hypot(jx, jy);
    double tx = 0.0, ty = 0.0;
    if (j > 0.0) {
      const double tau = (soil.cohesion + sigma * tan_phi) * (1.0 - std::exp(-j / soil.shear_modulus));
      tx = tau * jx / j;
      ty = tau * jy / j;
    }
    const double c = std::cos(theta), sn = std::sin(theta);
    sum.n += w * (sigma * c + tx * sn);
    sum.x += w * (tx * c - sigma * sn);
    sum.y += w * ty;
    sum.tau += w * tx;
    sum.resist += w * sigma * sn;
    sum.my_sin += w * ty * sn;
    sum.my_cos += w * ty * c;
  };
  const auto integrate = [&](double lo, double hi, bool front) {
    if (!(hi > lo)) return;
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (int i = 0; i < 6; ++i) add(mid + half * kNode[i], half * kWeight[i], front);
  };
  integrate(tm, t1, true);
  integrate(t2, tm, false);

  const double rb = r * b;
  f.normal = rb * sum.n;
  f.drawbar = rb * sum.x;
  f.resistance = rb * sum.resist;
  f.lateral = -rb * sum.y;  // the soil resists the slide
  f.torque = -rs * rb * sum.tau;
  // The lateral force -tau_y at the rim point r (sin theta x - cos theta n): moment r (sin theta n +
  // cos theta x) per unit force.
  f.moment_normal = -r * rb * sum.my_sin;
  f.moment_heading = -r * rb * sum.my_cos;
  return f;
}

SteadyWheel steady_wheel(const SoilParameters& soil, const WheelShape& wheel, double load, double slip,
                         double rut_depth) {
  SteadyWheel out;
  const auto at = [&](double z) { return wheel_soil_forces(soil, wheel, z, slip, 0.0, 1.0, rut_depth); };
  double lo = 0.0, hi = wheel.radius;
  if (at(hi).normal < load) {
    out.sinkage = hi;
    out.forces = at(hi);
    return out;
  }
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (at(mid).normal < load ? lo : hi) = mid;
  }
  out.sinkage = 0.5 * (lo + hi);
  out.forces = at(out.sinkage);
  out.ok = true;
  return out;
}

}  // namespace mechsim::physics
