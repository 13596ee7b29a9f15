#pragma once
// Rover wheel odometry beyond the plain least squares of rover_drive_kinematics.hpp: a
// weighted estimate (each wheel's rolling row and no-side-slip row weighted on its own) and a
// robust one (iteratively reweighted least squares) that stops trusting a wheel whose rolling
// speed and heading disagree with what the other wheels say.
//
// Why weights. A wheel's rolling row (the tyre's ground speed along its heading equals its
// rolling speed) holds only while the tyre does not slip along its heading, and its lateral row
// (no speed across the heading) only while it does not slide sideways. A wheel held at a speed
// set point by a stiff PID reports the set point, whatever the ground does; a wheel that is not
// driven rolls with the ground. The controller knows which is which (drive mode, which wheels it
// powers) and says so through the weights. The robust pass handles what it cannot know: a
// wheel spinning in the air or stuck in sand.
//
// Frames and units as in rover_drive_kinematics.hpp: body frame B, twists of B's origin (m/s,
// rad/s), headings (rad), rolling speeds (m/s). No function here allocates or throws.

#include <span>

#include "controllers/drive/rover_drive_kinematics.hpp"

namespace mechsim::control {

// The two rows of wheel `i` at `heading` (rad; ignored for fixed wheels): a_rolling . (vx, vy,
// wz) is the tyre's ground speed along the heading, a_lateral . (vx, vy, wz) across it (m/s).
void wheel_odometry_rows(const RoverKinematics& k, std::size_t i, double heading, double a_rolling[3],
                         double a_lateral[3]) noexcept;

// Weighted least squares over the wheels' rows. `rolling_weights` and `lateral_weights`
// (wheel_count each, >= 0; an empty span means 1 for every wheel) weigh each row's squared
// residual. Returns false (twist left alone) when the weighted rows do not determine a twist.
// `rms_residual` (m/s), when given: the weighted root mean square of the rows' residuals,
// sqrt(sum w e^2 / sum w) over the rows with w > 0.
bool estimate_twist_weighted(const RoverKinematics& k, std::span<const double> headings, std::span<const double> speeds,
                             std::span<const double> rolling_weights, std::span<const double> lateral_weights,
                             PlanarTwist& twist, double* rms_residual = nullptr) noexcept;

struct RobustOdometryOptions {
  // Reweighting passes after the first weighted solve; 0 gives the weighted solve alone.
  int iterations = 3;
  // m/s: the Cauchy scale c. A wheel whose residual (over its weighted rows) is r keeps the
  // fraction 1 / (1 + (r / c)^2) of its weights: half at r = c, a hundredth at r = 10 c.
  // <= 0 disables the reweighting.
  double scale = 0.05;
};

// Iteratively reweighted least squares (a Cauchy M-estimator) starting from the given weights.
// `work_rolling`, `work_lateral` (wheel_count each) are scratch; on return they hold the last
// weights tried. `wheel_trust` (wheel_count, optional) receives each wheel's final factor in
// (0, 1]. Returns false when even the first solve fails; a later pass that would fail keeps the
// previous estimate.
bool estimate_twist_robust(const RoverKinematics& k, std::span<const double> headings, std::span<const double> speeds,
                           std::span<const double> rolling_weights, std::span<const double> lateral_weights,
                           const RobustOdometryOptions& options, std::span<double> work_rolling,
                           std::span<double> work_lateral, PlanarTwist& twist, double* rms_residual = nullptr,
                           std::span<double> wheel_trust = {}) noexcept;

}  // namespace mechsim::control
