#include "sim/pid_gains_drive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "control/angles.hpp"

namespace mechsim::sim {

namespace {

using mechanism::HardwareInterface;

std::string gains_text(const control::PidGains& g) {
  std::ostringstream s;
  s << "p " << g.p << ", i " << g.i << ", d " << g.d << ", i_clamp [" << g.i_min << ", " << g.i_max << "]";
  if (g.antiwindup) s << ", antiwindup";
  return s.str();
}

// `path` ("/a/b/c") in `root`, a map, or nullopt.
std::optional<control::Params> find_map(const control::Params& root, const std::string& path) {
  const std::string key = path.substr(path.find_first_not_of('/'));
  std::optional<control::Params> found = root.find(key);
  if (found && found->is_map()) return found;
  return std::nullopt;
}

}  // namespace

PidGainsDrive::PidGainsDrive(const mechanism::MechanismModel& model,
                             const std::optional<description::RosControlPlugin>& plugin, const control::Params& root) {
  const std::size_t n = model.joints.size();
  pids_.resize(n);
  effort_limit_.assign(n, std::numeric_limits<double>::infinity());
  last_mode_.assign(n, HardwareInterface::Effort);
  const description::RosControlPlugin settings = plugin.value_or(description::RosControlPlugin{});
  for (std::size_t j = 0; j < n; ++j) {
    const mechanism::JointInfo& info = model.joints[j];
    if (info.role != mechanism::JointRole::Actuated) continue;
    if (!info.has_interface(HardwareInterface::Position) && !info.has_interface(HardwareInterface::Velocity)) continue;
    if (info.limits && info.limits->effort > 0.0) effort_limit_[j] = info.limits->effort;
    const std::string path = settings.pid_gains_path(info.name);
    const std::string what = "joint '" + info.name + "': position/velocity commands ";
    if (const auto gains = find_map(root, path); gains && gains->has("p")) {
      control::Pid pid;
      pid.init(*gains);
      notes_.push_back(what + "through a PID to effort (gazebo_ros_control pid_gains at " + path + ": " +
                       gains_text(pid.gains()) + ")");
      pids_[j] = std::move(pid);
      continue;
    }
    std::string note = what + "through mechsim's servo (no pid_gains at " + path + ")";
    // Gains one namespace away are the usual slip: say why they are not read.
    const description::RosControlPlugin other = [&] {
      description::RosControlPlugin o = settings;
      o.legacy_mode_ns = !settings.legacy();
      return o;
    }();
    if (settings.default_hw() && other.pid_gains_path(info.name) != path && find_map(root, other.pid_gains_path(info.name))) {
      note += "; gains at " + other.pid_gains_path(info.name) + " are not read: legacyModeNS is " +
              (settings.legacy() ? std::string(settings.legacy_mode_ns ? "true" : "absent (Gazebo's default: true)")
                                 : std::string("false"));
    }
    notes_.push_back(note);
  }
}

double PidGainsDrive::effort(std::size_t j, const mechanism::JointInfo& info, const mechanism::JointState& state,
                             double dt) noexcept {
  control::Pid& pid = *pids_[j];
  if (state.command_mode != last_mode_[j]) {
    pid.reset();
    last_mode_[j] = state.command_mode;
  }
  double error = 0.0;
  switch (state.command_mode) {
    case HardwareInterface::Position: error = control::position_error(info, state.position, state.commanded_position); break;
    case HardwareInterface::Velocity: error = state.commanded_velocity - state.velocity; break;
    case HardwareInterface::Effort: return state.commanded_effort;
  }
  const double limit = effort_limit_[j];
  return std::clamp(pid.compute_command(error, dt), -limit, limit);
}

void PidGainsDrive::reset() noexcept {
  for (std::optional<control::Pid>& pid : pids_) {
    if (pid) pid->reset();
  }
  std::fill(last_mode_.begin(), last_mode_.end(), HardwareInterface::Effort);
}

}  // namespace mechsim::sim
