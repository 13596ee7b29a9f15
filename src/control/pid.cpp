#include "control/pid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mechsim::control {
namespace {

// Well defined even for lo > hi (a user may swap i_clamp_min/max): lo wins, as boost's clamp
// which control_toolbox used.
double clamp(double v, double lo, double hi) noexcept { return v < lo ? lo : (hi < v ? hi : v); }

}  // namespace

Pid::Pid(double p, double i, double d, double i_max, double i_min, bool antiwindup)
    : gains_(PidGains{p, i, d, i_max, i_min, antiwindup}) {}

Pid::Pid(const Pid& other) : gains_(other.gains()) {}

Pid& Pid::operator=(const Pid& other) {
  if (this != &other) {
    gains_.init(other.gains());
    reset();
  }
  return *this;
}

PidGains Pid::gains_from_params(const Params& params) {
  if (!params.has("p")) {
    throw ParamsError("No p gain specified for pid. Namespace: " + params.path(),
                      join_param_path(params.path(), "p"));
  }
  PidGains g;
  g.p = params.get<double>("p");
  g.i = params.get<double>("i", 0.0);
  g.d = params.get<double>("d", 0.0);
  const double i_clamp = params.get<double>("i_clamp", 0.0);
  g.i_max = std::abs(i_clamp);
  g.i_min = -std::abs(i_clamp);
  if (params.has("i_clamp_min")) g.i_min = -std::abs(params.get<double>("i_clamp_min"));
  if (params.has("i_clamp_max")) g.i_max = std::abs(params.get<double>("i_clamp_max"));
  g.antiwindup = params.get<bool>("antiwindup", false);
  for (double v : {g.p, g.i, g.d, g.i_min, g.i_max}) {
    if (!std::isfinite(v)) throw ParamsError("pid gains must be finite. Namespace: " + params.path(), params.path());
  }
  return g;
}

void Pid::init(const Params& params) {
  gains_.init(gains_from_params(params));
  reset();
}

void Pid::init(const PidGains& gains) {
  gains_.init(gains);
  reset();
}

void Pid::init(const Params& parent, std::string_view ns) {
  auto params = parent.find(ns);
  if (!params || !params->is_map()) {
    const std::string path = join_param_path(parent.path(), ns);
    throw ParamsError("No p gain specified for pid. Namespace: " + path, join_param_path(path, "p"));
  }
  init(*params);
}

void Pid::set_gains(const PidGains& gains) { gains_.write(gains); }

void Pid::set_gains(double p, double i, double d, double i_max, double i_min, bool antiwindup) {
  set_gains(PidGains{p, i, d, i_max, i_min, antiwindup});
}

PidGains Pid::gains() const { return gains_.latest(); }

void Pid::reset(bool keep_i_term) noexcept {
  p_error_last_ = 0.0;
  p_error_ = 0.0;
  d_error_ = 0.0;
  cmd_ = 0.0;
  if (!keep_i_term) i_error_ = 0.0;
}

double Pid::compute_command(double error, double dt) noexcept {
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(error)) return 0.0;
  const double error_dot = (error - p_error_last_) / dt;
  if (!std::isfinite(error_dot)) return 0.0;
  p_error_last_ = error;
  return compute_command(error, error_dot, dt);
}

double Pid::compute_command(double error, double error_dot, double dt) noexcept {
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(error) || !std::isfinite(error_dot)) return 0.0;
  const PidGains& g = gains_.read_from_rt();

  p_error_ = error;
  d_error_ = error_dot;
  const double p_term = g.p * p_error_;

  i_error_ += dt * p_error_;
  if (g.antiwindup && g.i != 0.0) {
    // Keep the integrated error where i * i_error stays within [i_min, i_max].
    const double a = g.i_min / g.i;
    const double b = g.i_max / g.i;
    i_error_ = clamp(i_error_, std::min(a, b), std::max(a, b));
  }
  double i_term = g.i * i_error_;
  if (!g.antiwindup) i_term = clamp(i_term, g.i_min, g.i_max);

  const double d_term = g.d * d_error_;
  cmd_ = p_term + i_term + d_term;
  return cmd_;
}

}  // namespace mechsim::control
