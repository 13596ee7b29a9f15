#pragma once
// pr2_mechanism_controllers/LaserScannerTrajController: sweeps the PR2's tilting laser
// (laser_tilt_mount_joint) through a periodic profile with a position PID on the effort
// interface. The profile is set at run time through the "command" port (pr2_msgs/PeriodicCmd:
// profile, period, amplitude, offset; the set_periodic_cmd service and topic of the PR2) and
// restarts from phase 0 at the tick that takes it.
//
// Profiles (t = time since the profile was taken, T = period, A = amplitude, c = offset):
//   "linear"  the PR2's: a triangle wave from c - A up to c + A at T/2 and back down at T,
//             at constant speed 4A/T
//   "sine"    c + A sin(2 pi t / T) (smooth; starts at c going up)
// The set point is clamped into the joint's URDF limits; the PID gets the profile's rate as
// the error rate (error_dot = desired rate - joint rate).
//
// Parameters (under the controller's namespace; units in brackets):
//   type       pr2_mechanism_controllers/LaserScannerTrajController
//   joint      e.g. laser_tilt_mount_joint
//   pid        {p, i, d, i_clamp, ...}  [N m/rad ...]
//   profile, period [s], amplitude [rad], offset [rad]
//              optional (a mechsim addition): a profile to run from start; without them the
//              controller holds the position it started at until a command arrives
//
// Ports:
//   "command"  PeriodicCommandPort (non-finite values, period <= 0, amplitude < 0 and unknown
//              profiles are rejected and counted; the previous profile stays)
//   "state"    StatePort<JointControllerState>: set point (rad), position, velocity, error =
//              set point - position, effort command (N m), gains
//   "gains"    PidGainsPort

#include <string>
#include <string_view>

#include "control/controller.hpp"
#include "control/pid.hpp"

namespace mechsim::control {

inline constexpr const char* kLaserScannerTrajControllerType = "pr2_mechanism_controllers/LaserScannerTrajController";

enum class PeriodicProfile : unsigned char { Hold, Linear, Sine };
const char* periodic_profile_name(PeriodicProfile p) noexcept;  // "hold", "linear", "sine"
bool parse_periodic_profile(std::string_view text, PeriodicProfile& out);  // "linear", "sine"

// pr2_msgs/PeriodicCmd. Hold keeps `offset` (rad).
struct PeriodicCommand {
  PeriodicProfile profile = PeriodicProfile::Hold;
  double period = 1.0;     // s, > 0
  double amplitude = 0.0;  // rad, >= 0
  double offset = 0.0;     // rad
};

// The profile's position (rad) and rate (rad/s) at `t` seconds from its start (t >= 0).
void periodic_profile_sample(const PeriodicCommand& command, double t, double& position, double& velocity) noexcept;

class PeriodicCommandPort : public Port, public RejectionLog {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::PeriodicCommand; }
  // Non-real-time. False (and `error` set) when rejected.
  bool write(const PeriodicCommand& command, std::string* error = nullptr);
  // The message's form: profile by name ("linear", "sine").
  bool write(std::string_view profile, double period, double amplitude, double offset, std::string* error = nullptr);
  PeriodicCommand latest() const { return buffer_.latest(); }
  std::uint64_t accepted() const noexcept { return accepted_.load(std::memory_order_acquire); }
  const PeriodicCommand& read_from_rt() noexcept { return buffer_.read_from_rt(); }
  void reset_from_rt(const PeriodicCommand& c) noexcept {
    buffer_.reset_from_rt([&c](PeriodicCommand& v) { v = c; });
  }

 private:
  RealtimeBuffer<PeriodicCommand> buffer_;
  std::atomic<std::uint64_t> accepted_{0};
};

class LaserScannerTrajController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&command_, &state_, &gains_}; }

  PeriodicCommandPort& command_port() { return command_; }
  StatePort<JointControllerState>& state_port() { return state_; }
  Pid& pid() { return pid_; }
  // The profile being run (real-time side; for tests and reports from the tick's thread).
  const PeriodicCommand& active_profile() const noexcept { return active_; }

 private:
  JointHandle joint_;
  Pid pid_;
  PeriodicCommand initial_;  // from the parameters (Hold when none)
  PeriodicCommand active_;
  double profile_start_ = 0.0;  // s
  std::uint64_t last_command_seq_ = 0;

  PeriodicCommandPort command_{"command"};
  StatePort<JointControllerState> state_{"state"};
  PidGainsPort gains_{"gains", &pid_};
};

}  // namespace mechsim::control
