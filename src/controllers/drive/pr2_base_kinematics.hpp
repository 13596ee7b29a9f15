#pragma once
// Kinematics of the PR2's base as pure functions: four powered casters, each a steering
// (rotation) joint carrying two wheels side by side on its axle. A body twist gives each caster
// a heading and each wheel a rolling speed; the measured headings and wheel speeds give the body
// twist back by (iteratively re-weighted) least squares, as pr2_mechanism_controllers'
// Pr2Odometry does.
//
// Frames and conventions. Base frame B: base_link (or base_footprint), x forward, y left, z up.
// A caster's heading is the angle (rad, counter-clockwise seen from above) of its wheels'
// rolling direction in B; caster joint angle = caster axis sign * heading (+1 for the PR2,
// whose caster axes point up). Each caster pivot (a point of the rotation axis) is fixed in B.
// A wheel sits `offset` metres along the caster's own y axis from the pivot (+0.049 for the
// PR2's left wheels, -0.049 for its right ones) with its axle along that axis; its rolling
// speed (m/s) is the speed of its centre along the heading, and wheel joint velocity = wheel
// axis sign * rolling speed / wheel radius (+1 for the PR2: axes along +y roll forward).
//
// Why the wheel speed has a caster-rate term: a wheel beside the pivot moves when the caster
// turns in place, so turning a caster while standing still needs the two wheels to roll in
// opposite directions (the PR2 steers its casters this way: it has no steering motor torque to
// scrub the tyres). The rolling speed is
//   v_B(p) . d  -  offset * caster_rate
// where p is the wheel centre, d = (cos h, sin h) the rolling direction, v_B(p) the velocity
// the body twist gives the point p, and caster_rate the caster joint's rate (rad/s of heading).
//
// No function here allocates or throws; spans must have the sizes stated.

#include <cstddef>
#include <span>
#include <vector>

#include "controllers/drive/rover_drive_kinematics.hpp"  // PlanarTwist, PlanarPose, integrate_pose

namespace mechsim::control {

struct Pr2Caster {
  double x = 0.0;          // m, pivot in B
  double y = 0.0;          // m, pivot in B
  double axis_sign = 1.0;  // +1: a positive joint angle turns the caster counter-clockwise
};

struct Pr2Wheel {
  std::size_t caster = 0;  // index of the caster carrying the wheel
  double offset = 0.0;     // m, along the caster's y axis from the pivot (left positive)
  double axis_sign = 1.0;  // +1: a positive joint velocity rolls the wheel forward
};

struct Pr2BaseKinematics {
  double wheel_radius = 0.0;  // m (the effective radius: nominal radius * radius multiplier)
  std::vector<Pr2Caster> casters;
  std::vector<Pr2Wheel> wheels;
};

// Velocity (m/s, in B) of the point (x, y) of B under a body twist.
inline void point_velocity(const PlanarTwist& twist, double x, double y, double& vx, double& vy) noexcept {
  vx = twist.vx - twist.wz * y;
  vy = twist.vy + twist.wz * x;
}

// The heading (rad, in (-pi, pi]) that rolls a caster's wheels along (vx, vy), of the two that
// do (theta, and theta + pi with the wheels reversed) the one nearer `current` (rad): a caster
// turns at most pi/2. `reversed` tells which was chosen.
double caster_steer_target(double vx, double vy, double current, bool& reversed) noexcept;

// Target headings (caster_count) for a body twist: each caster's pivot velocity, folded as
// caster_steer_target does around `current` (caster_count, rad); a caster whose pivot moves
// slower than `hold_speed` (m/s) keeps `hold` (caster_count, rad).
void caster_headings(const Pr2BaseKinematics& k, const PlanarTwist& twist, std::span<const double> current,
                     std::span<const double> hold, std::span<double> headings, double hold_speed = 1e-5) noexcept;

// Rolling speed (m/s) of wheel `w` under a body twist with its caster at `heading` (rad) and
// turning at `caster_rate` (rad/s of heading).
double wheel_rolling_speed(const Pr2BaseKinematics& k, std::size_t w, const PlanarTwist& twist, double heading,
                           double caster_rate) noexcept;

// Odometry weights of the iteratively re-weighted least squares (ils_weight_type).
enum class IlsWeight : unsigned char { Gaussian, Cauchy, Uniform };

// Scratch space of estimate_base_twist, sized once (configuration time) for `wheel_count`.
struct Pr2OdometryScratch {
  std::vector<double> rows;      // 2 * wheel_count rows of 3 coefficients
  std::vector<double> rhs;       // 2 * wheel_count
  std::vector<double> weights;   // 2 * wheel_count
  std::vector<double> residual;  // 2 * wheel_count (m/s)
  std::vector<double> sorted;    // 2 * wheel_count, for the median
  void resize(std::size_t wheel_count);
};

// The body twist of B that best explains the measured caster headings and rates (caster_count,
// rad and rad/s) and wheel rolling speeds (wheel_count, m/s): per wheel, the velocity the twist
// gives its centre must equal (rolling speed + offset * caster rate) along the heading and zero
// across it (two rows, x and y in B). Solved by least squares, then re-weighted
// `iterations` times from the residuals (robust scale 1.4826 * median |residual|, floored at
// 1 mm/s), so that one slipping wheel is discounted rather than spread over the estimate.
// Returns false (twist untouched) when the rows do not determine a twist. `rms_residual` (m/s,
// optional) is the unweighted root mean square residual of the final estimate.
bool estimate_base_twist(const Pr2BaseKinematics& k, std::span<const double> headings,
                         std::span<const double> caster_rates, std::span<const double> speeds,
                         Pr2OdometryScratch& scratch, PlanarTwist& twist, int iterations = 3,
                         IlsWeight weight = IlsWeight::Gaussian, double* rms_residual = nullptr) noexcept;

}  // namespace mechsim::control
