#pragma once
// pr2_mechanism_controllers/Pr2Odometry: the PR2's wheel odometry, a separate controller as on
// the PR2 (it claims nothing, so it runs beside whichever base controller drives). Each tick it
// reads the caster angles and rates and the wheel velocities, estimates the body twist by
// iteratively re-weighted least squares over the wheels (controllers/drive/pr2_base_kinematics.hpp:
// estimate_base_twist) and integrates it exactly into a planar pose.
//
// Parameters (under the controller's namespace; units in brackets):
//   type                 pr2_mechanism_controllers/Pr2Odometry
//   Geometry: as the base controller (controllers/drive/pr2_base_params.hpp), filled from the URDF by
//   control::fill_pr2_base_geometry when absent.
//   odom_frame           default "odom"
//   base_footprint_frame default "base_footprint" (the child frame of the odometry)
//   ils_max_iterations   [-] re-weighting iterations, default 3 (0: plain least squares)
//   ils_weight_type      "Gaussian" (default), "Cauchy" or "Uniform" (plain least squares)
//   odom/initial_x, odom/initial_y [m], odom/initial_yaw [rad]  start pose, default 0
//   sigma_x, sigma_y [m], sigma_theta [rad]  pose standard deviations, default 0.002, 0.002,
//                        0.017 (the PR2's); their squares fill the pose covariance diagonal
//                        (z, roll, pitch get 1e6: not estimated)
//
// Ports:
//   "odom"   StatePort<OdometrySnapshot> (controllers/drive/rover_drive_ports.hpp): pose of
//            base_footprint_frame in odom_frame, twist in base_footprint_frame, residual (m/s)
//
// The pose persists across restarts; reset_odometry() puts it back to the initial pose.

#include <atomic>
#include <vector>

#include "control/controller.hpp"
#include "controllers/drive/pr2_base_params.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/drive/steered_drive.hpp"  // PlanarOdometry

namespace mechsim::control {

class Pr2OdometryController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&odom_}; }

  StatePort<OdometrySnapshot>& odometry_port() { return odom_; }
  const Pr2BaseGeometry& geometry() const { return geometry_; }
  // Any thread: the next update() puts the pose back to the initial pose.
  void reset_odometry() { reset_.store(true, std::memory_order_release); }

 private:
  Pr2BaseGeometry geometry_;
  std::vector<JointStateHandle> casters_;
  std::vector<JointStateHandle> wheels_;
  int iterations_ = 3;
  IlsWeight weight_ = IlsWeight::Gaussian;
  PlanarPose initial_;

  std::vector<double> headings_;  // rad
  std::vector<double> rates_;     // rad/s
  std::vector<double> speeds_;    // m/s
  Pr2OdometryScratch scratch_;
  PlanarOdometry odometry_;
  std::atomic<bool> reset_{false};

  StatePort<OdometrySnapshot> odom_{"odom"};
};

}  // namespace mechsim::control
