#pragma once
// The fusion behind mechsim's robot_pose_ekf (apps/pose_ekf_node.cpp): a planar pose (x, y, yaw)
// from wheel odometry and an IMU's orientation, as robot_pose_ekf publishes it on
// robot_pose_ekf/odom_combined and as odom_combined -> base_footprint on /tf. Not an extended
// Kalman filter: a documented complementary fusion of the two sources' increments, which is what
// robot_pose_ekf's filter amounts to for odometry and an IMU (it too fuses relative measurements,
// weighted by their covariances):
//
//   - the estimate starts at the first odometry pose (robot_pose_ekf initialises from odometry);
//   - at each update, the heading moves by w * dyaw_odom + (1 - w) * dyaw_imu, the increments since
//     the previous update, w = var_imu / (var_imu + var_odom) (inverse-variance weights; a variance
//     of 0 or less in a message means unknown: odometry 0.01 rad^2, the IMU (0.00017 rad)^2 as
//     robot_pose_ekf assumes for an IMU without covariance);
//   - the position moves by the odometry's translation increment, taken in the robot's frame and
//     turned by the fused heading;
//   - roll and pitch are the IMU's, less its first sample's (its mounting), z stays 0 (as
//     robot_pose_ekf without visual odometry or GPS);
//   - the yaw variance is the fused one, 1 / (1/var_odom + 1/var_imu); x and y carry the
//     odometry's.
// Without IMU samples the estimate follows the odometry alone, without odometry it does not start.
// Plain C++17, no ROS (tested in ros_test).

#include <array>
#include <optional>

namespace mechsim::ros {

struct PlanarOdometry {
  double x = 0.0, y = 0.0, yaw = 0.0;  // m, m, rad in the odometry frame
  double var_xy = 0.0, var_yaw = 0.0;  // m^2, rad^2; <= 0: unknown
};

struct ImuAttitude {
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // rad (the IMU's orientation, fixed axes)
  double var_yaw = 0.0;                       // rad^2; <= 0: unknown
};

struct FusedPose {
  double x = 0.0, y = 0.0, z = 0.0;        // m
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // rad
  std::array<double, 36> covariance{};     // row-major 6x6 (x y z roll pitch yaw), as ROS's
};

class PoseFusion {
 public:
  static constexpr double kDefaultOdomYawVariance = 0.01;
  static constexpr double kDefaultImuYawVariance = 0.00017 * 0.00017;

  void add_odometry(const PlanarOdometry& odom) { odom_ = odom; }
  void add_imu(const ImuAttitude& imu) { imu_ = imu; }
  // The IMU went quiet (robot_pose_ekf's sensor_timeout): the heading follows the odometry alone
  // until it speaks again.
  void drop_imu() { imu_.reset(), last_imu_.reset(); }
  // Folds in what came since the last update; false until an odometry sample has come.
  bool update();
  bool initialized() const { return initialized_; }
  const FusedPose& estimate() const { return estimate_; }

 private:
  std::optional<PlanarOdometry> odom_, last_odom_;
  std::optional<ImuAttitude> imu_, last_imu_, first_imu_;
  bool initialized_ = false;
  FusedPose estimate_;
};

// The angle a - b wrapped into (-pi, pi].
double angle_difference(double a, double b);

}  // namespace mechsim::ros
