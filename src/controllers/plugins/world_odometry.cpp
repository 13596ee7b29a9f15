#include "controllers/plugins/world_odometry.hpp"

#include <cmath>

namespace mechsim::control {

double yaw_of(const description::Quat& q) noexcept {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

void fill_world_odometry(OdometrySnapshot& o, const mechanism::BaseState& base, double time) noexcept {
  const description::Quat& q = base.X_WB.orientation;
  const double yaw = yaw_of(q);
  const double c = std::cos(yaw), s = std::sin(yaw);
  o.stamp = time;
  o.x = base.X_WB.position.x;
  o.y = base.X_WB.position.y;
  o.z = base.X_WB.position.z;
  o.yaw = yaw;
  o.has_attitude = true;
  o.attitude = {q.w, q.x, q.y, q.z};
  o.linear = {c * base.linear.x + s * base.linear.y, c * base.linear.y - s * base.linear.x, 0.0};
  o.angular = {0.0, 0.0, base.angular.z};
  o.in_world = true;
  o.valid = base.floating;
}

OdometrySnapshot plugin_odometry_prototype(const std::string& frame_id, const std::string& child_frame_id,
                                           const std::array<double, 6>& pose_diagonal,
                                           const std::array<double, 6>& twist_diagonal) {
  OdometrySnapshot o;
  o.frame_id = frame_id;
  o.child_frame_id = child_frame_id;
  for (std::size_t i = 0; i < 6; ++i) {
    o.pose_covariance[i * 7] = pose_diagonal[i];
    o.twist_covariance[i * 7] = twist_diagonal[i];
  }
  return o;
}

void fill_encoder_odometry(OdometrySnapshot& o, const EncoderOdometry& e, double time) noexcept {
  o.stamp = time;
  o.x = e.pose.x;
  o.y = e.pose.y;
  o.yaw = std::remainder(e.pose.yaw, 2.0 * M_PI);
  o.linear = {e.linear, 0.0, 0.0};
  o.angular = {0.0, 0.0, e.angular};
  o.valid = true;
}

}  // namespace mechsim::control
