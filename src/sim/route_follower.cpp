#include "sim/route_follower.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mechsim::sim {

double wrap_angle(double angle) {
  angle = std::fmod(angle + std::numbers::pi, 2.0 * std::numbers::pi);
  if (angle <= 0.0) angle += 2.0 * std::numbers::pi;
  return angle - std::numbers::pi;
}

RouteFollower::RouteFollower(std::vector<std::array<double, 2>> waypoints, RouteParams params)
    : waypoints_(std::move(waypoints)), params_(params) {}

control::Twist RouteFollower::update(double x, double y, double yaw) {
  control::Twist twist;
  if (!started_) {
    segment_start_ = {x, y};
    started_ = true;
  }
  while (next_ < waypoints_.size() &&
         std::hypot(waypoints_[next_][0] - x, waypoints_[next_][1] - y) < params_.tolerance) {
    segment_start_ = waypoints_[next_];
    ++next_;
  }
  if (done()) return twist;

  // Look-ahead point: project the base on the segment, then walk `lookahead` along it (clamped
  // to the waypoint).
  const auto& a = segment_start_;
  const auto& b = waypoints_[next_];
  const double sx = b[0] - a[0], sy = b[1] - a[1];
  const double length = std::hypot(sx, sy);
  double tx = b[0], ty = b[1];
  if (length > 1e-9) {
    const double along = std::clamp(((x - a[0]) * sx + (y - a[1]) * sy) / length + params_.lookahead, 0.0, length);
    tx = a[0] + sx / length * along;
    ty = a[1] + sy / length * along;
  }
  const double dx = tx - x, dy = ty - y;
  const double distance = std::hypot(dx, dy);
  const double alpha = wrap_angle(std::atan2(dy, dx) - yaw);  // heading error to the target
  if (std::abs(alpha) > params_.turn_in_place_angle) {
    twist.angular.z = std::copysign(params_.max_yaw_rate, alpha);
    return twist;
  }
  // Pure pursuit: curvature 2 sin(alpha) / L; slow down when the curvature asks for more yaw
  // rate than allowed, so the path is kept rather than the speed.
  const double curvature = distance > 1e-6 ? 2.0 * std::sin(alpha) / distance : 0.0;
  double v = params_.speed;
  if (std::abs(curvature * v) > params_.max_yaw_rate) v = params_.max_yaw_rate / std::abs(curvature);
  twist.linear.x = v;
  twist.angular.z = curvature * v;
  return twist;
}

}  // namespace mechsim::sim
