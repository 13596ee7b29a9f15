#include "controllers/trajectory/trajectory_query.hpp"

namespace mechsim::control {

TrajectoryQueryPort::TrajectoryQueryPort(std::string name, std::vector<std::string> joints, std::size_t capacity)
    : Port(std::move(name)), joints_(std::move(joints)), snapshot_(joints_.size(), capacity) {}

bool TrajectoryQueryPort::sample(double time, std::vector<SplineState>& out, std::string* error) const {
  if (!running_.load(std::memory_order_acquire)) {
    if (error) *error = "the controller is not running";
    return false;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  out.resize(joints_.size());
  for (std::size_t j = 0; j < joints_.size(); ++j) out[j] = snapshot_.sample(j, time);
  return true;
}

bool TrajectoryQueryPort::publish_from_rt(const Trajectory& trajectory) noexcept {
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return false;
  for (std::size_t j = 0; j < joints_.size(); ++j) snapshot_.copy_joint(trajectory, j);
  return true;
}

}  // namespace mechsim::control
