#include "ros/pose_fusion.hpp"

#include <cmath>

namespace mechsim::ros {

double angle_difference(double a, double b) {
  double d = std::fmod(a - b, 2.0 * M_PI);
  if (d > M_PI) d -= 2.0 * M_PI;
  if (d <= -M_PI) d += 2.0 * M_PI;
  return d;
}

bool PoseFusion::update() {
  if (!odom_) return initialized_;
  const PlanarOdometry& odom = *odom_;
  const double var_odom = odom.var_yaw > 0.0 ? odom.var_yaw : kDefaultOdomYawVariance;
  if (!initialized_) {
    estimate_ = FusedPose{};
    estimate_.x = odom.x;
    estimate_.y = odom.y;
    estimate_.yaw = odom.yaw;
    initialized_ = true;
  } else {
    // The odometry's translation since the last update, in the robot's frame then.
    const PlanarOdometry& last = *last_odom_;
    const double dx = odom.x - last.x, dy = odom.y - last.y;
    const double forward = std::cos(last.yaw) * dx + std::sin(last.yaw) * dy;
    const double left = -std::sin(last.yaw) * dx + std::cos(last.yaw) * dy;
    double dyaw = angle_difference(odom.yaw, last.yaw);
    if (imu_ && last_imu_) {
      const double var_imu = imu_->var_yaw > 0.0 ? imu_->var_yaw : kDefaultImuYawVariance;
      const double w = var_imu / (var_imu + var_odom);
      dyaw = w * dyaw + (1.0 - w) * angle_difference(imu_->yaw, last_imu_->yaw);
    }
    estimate_.x += std::cos(estimate_.yaw) * forward - std::sin(estimate_.yaw) * left;
    estimate_.y += std::sin(estimate_.yaw) * forward + std::cos(estimate_.yaw) * left;
    estimate_.yaw = angle_difference(estimate_.yaw + dyaw, 0.0);
  }
  double var_yaw = var_odom;
  if (imu_) {
    if (!first_imu_) first_imu_ = imu_;
    estimate_.roll = angle_difference(imu_->roll, first_imu_->roll);
    estimate_.pitch = angle_difference(imu_->pitch, first_imu_->pitch);
    const double var_imu = imu_->var_yaw > 0.0 ? imu_->var_yaw : kDefaultImuYawVariance;
    var_yaw = 1.0 / (1.0 / var_odom + 1.0 / var_imu);
  }
  estimate_.covariance.fill(0.0);
  const double var_xy = odom.var_xy > 0.0 ? odom.var_xy : 0.0;
  estimate_.covariance[0] = var_xy;
  estimate_.covariance[7] = var_xy;
  estimate_.covariance[35] = var_yaw;
  last_odom_ = odom_;
  last_imu_ = imu_;
  return true;
}

}  // namespace mechsim::ros
