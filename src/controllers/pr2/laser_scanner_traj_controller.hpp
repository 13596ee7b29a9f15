#pragma once
// pr2_mechanism_controllers/LaserScannerTrajController: sweeps the PR2's tilting laser
// (laser_tilt_mount_joint) through a looping profile (laser_scan_profile.hpp) with a position PID
// on the effort interface. The profile is set at run time through the "command" port: a periodic
// command (pr2_msgs/PeriodicCmd: linear, blended_linear, or mechsim's sine) or a via-point
// trajectory (pr2_msgs/LaserTrajCmd: linear or blended_linear); the PR2's set_periodic_cmd and
// set_traj_cmd services and topics. A new profile starts from its beginning at the tick that
// takes it.
// The set point is clamped into the joint's URDF limits; the PID gets the profile's rate as the
// error rate (error_dot = desired rate - joint rate).
//
// Parameters (under the controller's namespace; units in brackets):
//   type       pr2_mechanism_controllers/LaserScannerTrajController
//   joint      e.g. laser_tilt_mount_joint
//   pid        {p, i, d, i_clamp, ...}  [N m/rad ...]
//   max_velocity [rad/s], max_acceleration [rad/s^2]
//              the limits trajectories are timed with when a command gives none (defaults:
//              the joint's URDF velocity limit, else 2 rad/s; 20 rad/s^2)
//   profile, period [s], amplitude [rad], offset [rad]
//              optional (a mechsim addition): a profile to run from start; without them the
//              controller holds the position it started at until a command arrives
//
// Ports:
//   "command"  ScanCommandPort (bad values, unknown profiles: rejected and counted; the previous
//              profile stays)
//   "state"    StatePort<JointControllerState>: set point (rad), position, velocity, error =
//              set point - position, effort command (N m), gains
//   "gains"    PidGainsPort

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "control/controller.hpp"
#include "control/pid.hpp"
#include "controllers/pr2/laser_scan_profile.hpp"

namespace mechsim::control {

inline constexpr const char* kLaserScannerTrajControllerType = "pr2_mechanism_controllers/LaserScannerTrajController";

// The profile port: commands are checked and timed (laser_scan_profile.hpp) when written, outside
// the tick; the tick swaps in the newest one.
class ScanCommandPort : public Port, public RejectionLog {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::PeriodicCommand; }
  // Non-real-time, before the tick uses the port: the limits commands without their own are
  // timed with.
  void set_limits(const ScanLimits& limits) { limits_ = limits; }
  const ScanLimits& limits() const { return limits_; }
  // Non-real-time. False (and `error` set) when rejected.
  bool write(const PeriodicCommand& command, std::string* error = nullptr);
  bool write(const LaserTrajCommand& command, std::string* error = nullptr);
  // The message's form: profile by name ("linear", "blended_linear", "sine").
  bool write(std::string_view profile, double period, double amplitude, double offset, std::string* error = nullptr);
  std::uint64_t accepted() const noexcept { return accepted_.load(std::memory_order_acquire); }

  // A profile and the number of the write that made it (0: set by the controller).
  struct Tagged {
    LaserScanProfile profile;
    std::uint64_t sequence = 0;
  };
  const Tagged& read_from_rt() noexcept { return buffer_.read_from_rt(); }
  void reset_from_rt(const LaserScanProfile& p) noexcept {
    buffer_.reset_from_rt([&p](Tagged& v) { v.profile = p; v.sequence = 0; });
  }

 private:
  bool publish(const LaserScanProfile& profile);

  ScanLimits limits_;
  std::mutex write_mutex_;  // orders sequence numbers with the buffer's writes
  RealtimeBuffer<Tagged> buffer_;
  std::atomic<std::uint64_t> accepted_{0};
};

class LaserScannerTrajController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&command_, &state_, &gains_}; }

  ScanCommandPort& command_port() { return command_; }
  StatePort<JointControllerState>& state_port() { return state_; }
  Pid& pid() { return pid_; }
  // The profile being run (real-time side; for tests and reports from the tick's thread).
  const LaserScanProfile& active_profile() const noexcept { return active_->profile; }

 private:
  JointHandle joint_;
  Pid pid_;
  std::optional<PeriodicCommand> initial_;  // from the parameters (hold the start position when none)
  const ScanCommandPort::Tagged* active_ = nullptr;
  double profile_start_ = 0.0;  // s
  std::uint64_t active_sequence_ = 0;

  ScanCommandPort command_{"command"};
  StatePort<JointControllerState> state_{"state"};
  PidGainsPort gains_{"gains", &pid_};
};

}  // namespace mechsim::control
