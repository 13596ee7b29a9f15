#pragma once
// PID controller with control_toolbox's (ROS 1, 1.17+) semantics:
//   p_term = p * error
//   i_error += dt * error;   with antiwindup, i_error is clamped so that i * i_error stays
//                            within [i_min, i_max]; without it, i_term is clamped instead
//   i_term = i * i_error
//   d_term = d * error_dot   (error_dot given, or (error - previous error) / dt)
//   command = p_term + i_term + d_term
// Configuration (init): `p` required, `i`, `d` default 0; `i_clamp` sets i_max = |i_clamp| and
// i_min = -|i_clamp| (default 0: no integral action unless a clamp is given, exactly as
// control_toolbox); `i_clamp_min`/`i_clamp_max` override each side (i_min = -|i_clamp_min|,
// i_max = |i_clamp_max|); `antiwindup` (default false).
//
// Gains live in a realtime double buffer: set_gains() from any non-real-time thread,
// compute_command() in the tick never blocks (it tries the lock and keeps the previous gains
// when a writer holds it). compute_command() neither allocates nor throws. Unlike
// control_toolbox, a call with dt <= 0 or a non-finite input returns 0 and leaves every error
// term untouched (control_toolbox stores the bad error before checking).

#include <string>

#include "control/params.hpp"
#include "control/realtime_buffer.hpp"

namespace mechsim::control {

struct PidGains {
  double p = 0.0;
  double i = 0.0;
  double d = 0.0;
  double i_max = 0.0;  // upper bound of the integral contribution (command units)
  double i_min = 0.0;  // lower bound of the integral contribution (command units)
  bool antiwindup = false;
  friend bool operator==(const PidGains&, const PidGains&) = default;
};

class Pid {
 public:
  Pid() = default;
  // control_toolbox's argument order: p, i, d, i_max, i_min, antiwindup.
  Pid(double p, double i, double d, double i_max, double i_min, bool antiwindup = false);
  // Copies take the gains only; the copy starts with zero errors (control_toolbox does the same).
  Pid(const Pid& other);
  Pid& operator=(const Pid& other);

  // Reads the gains from `params` (the pid namespace, e.g. /cc8/x/pid). Throws ParamsError
  // "No p gain specified for pid. Namespace: <path>" when `p` is missing, and names the path of
  // any mistyped gain.
  void init(const Params& params);
  // Starts with `gains` (read elsewhere: ros2_controllers' defaults differ).
  void init(const PidGains& gains);
  static PidGains gains_from_params(const Params& params);

  // Non-real-time: replaces the gains; the tick picks them up at its next compute_command().
  void set_gains(const PidGains& gains);
  void set_gains(double p, double i, double d, double i_max, double i_min, bool antiwindup = false);
  // The latest gains written (non-real-time).
  PidGains gains() const;
  // Real-time: the gains the last compute_command() used.
  const PidGains& rt_gains() const noexcept { return gains_.current_rt(); }
  // Reads the gains from `parent`/`ns` (ros_control's NodeHandle(n, "pid")); a missing
  // namespace gives the same "No p gain specified for pid" error as a missing `p`.
  void init(const Params& parent, std::string_view ns);

  // Real-time. error = set point - process value; dt in seconds. Returns the command.
  double compute_command(double error, double dt) noexcept;
  double compute_command(double error, double error_dot, double dt) noexcept;

  // Clears the error terms and the command (the i term too unless keep_i_term).
  void reset(bool keep_i_term = false) noexcept;

  double current_command() const noexcept { return cmd_; }
  void set_current_command(double cmd) noexcept { cmd_ = cmd; }
  struct Errors {
    double p = 0.0, i = 0.0, d = 0.0;  // proportional error, integrated error, error derivative
  };
  Errors current_errors() const noexcept { return {p_error_, i_error_, d_error_}; }

 private:
  RealtimeBuffer<PidGains> gains_;
  double p_error_last_ = 0.0;
  double p_error_ = 0.0;
  double i_error_ = 0.0;
  double d_error_ = 0.0;
  double cmd_ = 0.0;
};

}  // namespace mechsim::control
