#pragma once
// Differential-drive kinematics and odometry, shared by diff_drive_controller
// (controllers/drive/diff_drive_controller.hpp) and Gazebo's diff drive and skid-steer plugins
// (controllers/plugins/): a body twist into left and right wheel rim speeds, and wheel motion
// back into a planar pose.
//
// Frames: body frame B (x forward, y left), odometry frame O. A twist is (v, w): v m/s along
// B's x, w rad/s counter-clockwise about z. Wheels `separation` m apart, left at +separation/2.
// A "rim speed" is the ground speed a wheel would roll at without slip (m/s): joint velocity
// (rad/s) times radius (m). Nothing here allocates after init() or throws.

#include <cstddef>
#include <vector>

#include "controllers/drive/rover_drive_kinematics.hpp"  // PlanarPose, PlanarTwist

namespace mechsim::control {

struct WheelRimSpeeds {
  double left = 0.0;   // m/s
  double right = 0.0;  // m/s
};

// Rim speeds of the left and right wheels for the body twist (v, w).
inline WheelRimSpeeds diff_drive_rim_speeds(double v, double w, double separation) noexcept {
  return {v - w * separation / 2.0, v + w * separation / 2.0};
}

// Integrates a planar pose over a move of `ds` m along the heading while turning `dtheta` rad.
// `exact`: along the circular arc when |dtheta| > 1e-6 (ros_controllers' odometry), else, and
// always when false, the second-order Runge-Kutta step along the mid-way heading (Gazebo's
// encoder odometry). The yaw is not wrapped.
PlanarPose integrate_unicycle(const PlanarPose& pose, double ds, double dtheta, bool exact = true) noexcept;

// The mean of the last `size` samples pushed (diff_drive_controller's velocity rolling window).
class RollingMean {
 public:
  void init(std::size_t size);  // allocates; size >= 1
  void reset() noexcept;
  void push(double value) noexcept;
  double mean() const noexcept;  // 0 before the first push

 private:
  std::vector<double> samples_;
  std::size_t next_ = 0, count_ = 0;
  double sum_ = 0.0;
};

// diff_drive_controller's odometry: wheel joint positions (rad, each side's mean) give each
// step's left and right travel; their mean is the step's ds, their difference over the
// separation its dtheta; integrate_unicycle (exact) moves the pose; the velocities published are
// rolling means of ds/dt and dtheta/dt. Open loop: the commanded twist is integrated instead.
// Steps shorter than 0.1 ms are skipped (the wheels' travel accumulates into the next one).
class DiffDriveOdometry {
 public:
  // m, m, m; `window` samples for the velocity means (>= 1). Allocates.
  void init(double separation, double left_radius, double right_radius, std::size_t window);
  // Pose and velocities to zero; the wheels' travel counts from these positions (rad), at `time` (s).
  void reset(double left_position, double right_position, double time) noexcept;
  // Returns false when less than 0.1 ms passed since the last step (nothing changes).
  bool update(double left_position, double right_position, double time) noexcept;
  bool update_open_loop(double linear, double angular, double time) noexcept;

  const PlanarPose& pose() const noexcept { return pose_; }
  double linear() const noexcept { return linear_; }    // m/s, B's x
  double angular() const noexcept { return angular_; }  // rad/s

 private:
  bool advance(double ds, double dtheta, double time) noexcept;
  double separation_ = 1.0, left_radius_ = 1.0, right_radius_ = 1.0;
  double left_old_ = 0.0, right_old_ = 0.0;  // rad
  double stamp_ = 0.0;                       // s
  PlanarPose pose_;
  double linear_ = 0.0, angular_ = 0.0;
  RollingMean linear_mean_, angular_mean_;
};

// Gazebo's diff drive encoder odometry: each tick's wheel joint velocities (rad/s) times the
// radius over the period give the travel; integrate_unicycle along the mid-way heading; the twist
// is the step's |displacement| / dt (signed by the travel) and dtheta / dt.
struct EncoderOdometry {
  PlanarPose pose;
  double linear = 0.0, angular = 0.0;  // m/s, rad/s (body)

  void reset() noexcept { *this = EncoderOdometry{}; }
  void update(double left_velocity, double right_velocity, double radius, double separation, double dt) noexcept;
};

}  // namespace mechsim::control
