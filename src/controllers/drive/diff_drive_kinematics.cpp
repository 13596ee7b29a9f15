#include "controllers/drive/diff_drive_kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace mechsim::control {

PlanarPose integrate_unicycle(const PlanarPose& pose, double ds, double dtheta, bool exact) noexcept {
  PlanarPose out = pose;
  if (exact && std::abs(dtheta) > 1e-6) {
    // On the arc of radius ds / dtheta.
    const double r = ds / dtheta;
    out.yaw = pose.yaw + dtheta;
    out.x += r * (std::sin(out.yaw) - std::sin(pose.yaw));
    out.y -= r * (std::cos(out.yaw) - std::cos(pose.yaw));
    return out;
  }
  const double heading = pose.yaw + dtheta / 2.0;
  out.x += ds * std::cos(heading);
  out.y += ds * std::sin(heading);
  out.yaw += dtheta;
  return out;
}

void RollingMean::init(std::size_t size) {
  samples_.assign(std::max<std::size_t>(size, 1), 0.0);
  reset();
}

void RollingMean::reset() noexcept {
  std::fill(samples_.begin(), samples_.end(), 0.0);
  next_ = count_ = 0;
  sum_ = 0.0;
}

void RollingMean::push(double value) noexcept {
  if (samples_.empty()) return;
  if (count_ == samples_.size()) sum_ -= samples_[next_];
  else ++count_;
  samples_[next_] = value;
  sum_ += value;
  next_ = (next_ + 1) % samples_.size();
}

double RollingMean::mean() const noexcept { return count_ > 0 ? sum_ / static_cast<double>(count_) : 0.0; }

void DiffDriveOdometry::init(double separation, double left_radius, double right_radius, std::size_t window) {
  separation_ = separation;
  left_radius_ = left_radius;
  right_radius_ = right_radius;
  linear_mean_.init(window);
  angular_mean_.init(window);
}

void DiffDriveOdometry::reset(double left_position, double right_position, double time) noexcept {
  left_old_ = left_position;
  right_old_ = right_position;
  stamp_ = time;
  pose_ = {};
  linear_ = angular_ = 0.0;
  linear_mean_.reset();
  angular_mean_.reset();
}

bool DiffDriveOdometry::advance(double ds, double dtheta, double time) noexcept {
  const double dt = time - stamp_;
  if (dt < 1e-4) return false;
  stamp_ = time;
  pose_ = integrate_unicycle(pose_, ds, dtheta, true);
  linear_mean_.push(ds / dt);
  angular_mean_.push(dtheta / dt);
  linear_ = linear_mean_.mean();
  angular_ = angular_mean_.mean();
  return true;
}

bool DiffDriveOdometry::update(double left_position, double right_position, double time) noexcept {
  if (time - stamp_ < 1e-4) return false;  // keep the old positions: the travel goes to the next step
  const double left = (left_position - left_old_) * left_radius_;
  const double right = (right_position - right_old_) * right_radius_;
  left_old_ = left_position;
  right_old_ = right_position;
  return advance((left + right) / 2.0, (right - left) / separation_, time);
}

bool DiffDriveOdometry::update_open_loop(double linear, double angular, double time) noexcept {
  const double dt = time - stamp_;
  if (dt < 1e-4) return false;
  return advance(linear * dt, angular * dt, time);
}

void EncoderOdometry::update(double left_velocity, double right_velocity, double radius, double separation,
                             double dt) noexcept {
  if (!(dt > 0.0)) return;
  const double left = left_velocity * radius * dt;
  const double right = right_velocity * radius * dt;
  const double ds = (left + right) / 2.0;
  const double dtheta = (right - left) / separation;
  const PlanarPose before = pose;
  pose = integrate_unicycle(pose, ds, dtheta, false);
  const double moved = std::hypot(pose.x - before.x, pose.y - before.y);
  linear = (ds < 0.0 ? -moved : moved) / dt;
  angular = dtheta / dt;
}

}  // namespace mechsim::control
