#pragma once
// ros_controllers' query_state service (control_msgs/QueryTrajectoryState, the PR2's
// pr2_controllers_msgs/QueryTrajectoryState): the desired position, velocity and acceleration
// of each joint at any time, sampled from the trajectory the controller runs. ros_controllers
// samples a shared copy of the trajectory outside the real-time loop; here the tick hands its
// trajectory over whenever it changed (a copy into fixed storage under a try-lock: a reader
// sampling at that moment delays the copy by a tick, never the tick), and sample() runs in the
// caller's thread, so the service answers while the simulation is paused too.

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include "control/ports.hpp"
#include "controllers/trajectory/trajectory.hpp"

namespace mechsim::control {

class TrajectoryQueryPort : public Port {
 public:
  TrajectoryQueryPort(std::string name, std::vector<std::string> joints, std::size_t capacity);
  PortKind kind() const override { return PortKind::TrajectoryQuery; }
  const std::vector<std::string>& joint_names() const { return joints_; }

  // Non-real-time: the desired state of each joint (joint_names() order) at `time` (s, the
  // simulation's clock). False, with `error` set, while the controller is not running
  // (ros_controllers: "Controller is not running").
  bool sample(double time, std::vector<SplineState>& out, std::string* error = nullptr) const;

  // Real-time: takes a copy of the running trajectory; false (nothing copied) while a reader
  // holds the lock: the caller tries again at its next tick.
  bool publish_from_rt(const Trajectory& trajectory) noexcept;
  // Real-time: started / stopped.
  void set_running_from_rt(bool running) noexcept { running_.store(running, std::memory_order_release); }

 private:
  std::vector<std::string> joints_;
  std::atomic<bool> running_{false};
  mutable std::mutex mutex_;
  Trajectory snapshot_;  // under mutex_
};

}  // namespace mechsim::control
