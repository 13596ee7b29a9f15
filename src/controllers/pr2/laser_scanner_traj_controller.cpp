#include "controllers/pr2/laser_scanner_traj_controller.hpp"

#include <cmath>

#include "control/angles.hpp"

namespace mechsim::control {

bool ScanCommandPort::publish(const LaserScanProfile& profile) {
  std::lock_guard<std::mutex> lock(write_mutex_);
  const std::uint64_t sequence = accepted_.load(std::memory_order_relaxed) + 1;
  buffer_.write(Tagged{profile, sequence});
  accepted_.store(sequence, std::memory_order_release);
  return true;
}

bool ScanCommandPort::write(const PeriodicCommand& c, std::string* error) {
  LaserScanProfile p;
  std::string why;
  if (!LaserScanProfile::from_periodic(c, limits_, p, &why)) {
    return reject("port '" + name() + "': rejected periodic command (" + why + "); the previous profile stays", error);
  }
  return publish(p);
}

bool ScanCommandPort::write(const LaserTrajCommand& c, std::string* error) {
  LaserScanProfile p;
  std::string why;
  if (!LaserScanProfile::from_trajectory(c, limits_, p, &why)) {
    return reject("port '" + name() + "': rejected trajectory command (" + why + "); the previous profile stays", error);
  }
  return publish(p);
}

bool ScanCommandPort::write(std::string_view profile, double period, double amplitude, double offset,
                            std::string* error) {
  PeriodicCommand c{PeriodicProfile::Hold, period, amplitude, offset};
  if (!parse_periodic_profile(profile, c.profile)) {
    return reject("port '" + name() + "': rejected unknown profile '" + std::string(profile) +
                      "' (linear, blended_linear or sine); the previous profile stays",
                  error);
  }
  return write(c, error);
}

bool LaserScannerTrajController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string joint_path = join_param_path(params.path(), "joint");
  if (!params.has("joint")) throw ControllerConfigError("no joint given: parameter " + joint_path + " not found");
  joint_ = hardware.claim_joint(params.get<std::string>("joint"), HardwareInterface::Effort, joint_path);
  // pr2_controller_configuration_gazebo's YAML names the gains `gains` (what the PR2's own
  // controller reads); mechsim's used `pid`.
  pid_.init(params, params.has("gains") ? "gains" : "pid");
  ScanLimits limits;
  const double urdf_velocity = joint_.info().limits ? joint_.info().limits->velocity : 0.0;
  if (urdf_velocity > 0.0) limits.max_velocity = urdf_velocity;
  limits.max_velocity = params.get<double>("max_velocity", limits.max_velocity);
  limits.max_acceleration = params.get<double>("max_acceleration", limits.max_acceleration);
  if (!(limits.max_velocity > 0.0) || !std::isfinite(limits.max_velocity)) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "max_velocity") + " must be finite and > 0 (rad/s)");
  }
  if (!(limits.max_acceleration > 0.0) || !std::isfinite(limits.max_acceleration)) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "max_acceleration") +
                                " must be finite and > 0 (rad/s^2)");
  }
  command_.set_limits(limits);
  if (params.has("profile")) {
    const std::string profile = params.get<std::string>("profile");
    PeriodicCommand c;
    if (!parse_periodic_profile(profile, c.profile)) {
      throw ControllerConfigError("parameter " + join_param_path(params.path(), "profile") + ": unknown profile '" +
                                  profile + "' (linear, blended_linear or sine)");
    }
    c.period = params.get<double>("period");
    c.amplitude = params.get<double>("amplitude");
    c.offset = params.get<double>("offset", 0.0);
    if (!(c.period > 0.0) || !std::isfinite(c.period)) {
      throw ControllerConfigError("parameter " + join_param_path(params.path(), "period") + " must be finite and > 0 (s)");
    }
    if (!(c.amplitude >= 0.0) || !std::isfinite(c.amplitude) || !std::isfinite(c.offset)) {
      throw ControllerConfigError("parameter " + join_param_path(params.path(), "amplitude") +
                                  " must be finite and >= 0 (rad), offset finite");
    }
    LaserScanProfile checked;
    std::string why;
    if (!LaserScanProfile::from_periodic(c, limits, checked, &why)) {
      throw ControllerConfigError("parameters " + join_param_path(params.path(), "profile") + ": " + why);
    }
    initial_ = c;
  }
  state_.init(JointControllerState{});
  return true;
}

void LaserScannerTrajController::starting(double time) {
  LaserScanProfile start = LaserScanProfile::hold(joint_.position());
  if (initial_) {
    // Checked in init(): it cannot fail here.
    LaserScanProfile::from_periodic(*initial_, command_.limits(), start, nullptr);
  }
  command_.reset_from_rt(start);
  active_ = &command_.read_from_rt();
  active_sequence_ = active_->sequence;
  profile_start_ = time;
  pid_.reset();
}

UpdateStatus LaserScannerTrajController::update(double time, double period) {
  if (!(period > 0.0)) return UpdateStatus::Ok();
  active_ = &command_.read_from_rt();
  if (active_->sequence != active_sequence_) {
    active_sequence_ = active_->sequence;
    profile_start_ = time;
  }
  double set_point = 0.0, rate = 0.0;
  active_->profile.sample(time - profile_start_, set_point, rate);
  const double limited = enforce_position_limits(joint_.info(), set_point);
  if (limited != set_point) rate = 0.0;
  const double error = position_error(joint_.info(), joint_.position(), limited);
  double effort = pid_.compute_command(error, rate - joint_.velocity(), period);
  if (!std::isfinite(effort)) effort = 0.0;
  joint_.set_command(effort);
  state_.publish_from_rt([&](JointControllerState& s) {
    s.stamp = time;
    s.set_point = limited;
    s.process_value = joint_.position();
    s.process_value_dot = joint_.velocity();
    s.error = error;
    s.time_step = period;
    s.command = effort;
    s.gains = pid_.rt_gains();
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
