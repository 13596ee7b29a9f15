#include "controllers/pr2/laser_scanner_traj_controller.hpp"

#include <cmath>
#include <numbers>

#include "control/angles.hpp"

namespace mechsim::control {

const char* periodic_profile_name(PeriodicProfile p) noexcept {
  switch (p) {
    case PeriodicProfile::Hold: return "hold";
    case PeriodicProfile::Linear: return "linear";
    case PeriodicProfile::Sine: return "sine";
  }
  return "?";
}

bool parse_periodic_profile(std::string_view text, PeriodicProfile& out) {
  if (text == "linear") {
    out = PeriodicProfile::Linear;
  } else if (text == "sine") {
    out = PeriodicProfile::Sine;
  } else {
    return false;
  }
  return true;
}

void periodic_profile_sample(const PeriodicCommand& c, double t, double& position, double& velocity) noexcept {
  const double phase = std::fmod(std::fmax(t, 0.0), c.period) / c.period;  // [0, 1)
  switch (c.profile) {
    case PeriodicProfile::Hold:
      position = c.offset;
      velocity = 0.0;
      return;
    case PeriodicProfile::Linear: {
      const double speed = 4.0 * c.amplitude / c.period;
      if (phase < 0.5) {
        position = c.offset - c.amplitude + 4.0 * c.amplitude * phase;
        velocity = speed;
      } else {
        position = c.offset + c.amplitude - 4.0 * c.amplitude * (phase - 0.5);
        velocity = -speed;
      }
      return;
    }
    case PeriodicProfile::Sine: {
      const double w = 2.0 * std::numbers::pi / c.period;
      position = c.offset + c.amplitude * std::sin(2.0 * std::numbers::pi * phase);
      velocity = c.amplitude * w * std::cos(2.0 * std::numbers::pi * phase);
      return;
    }
  }
  position = c.offset;
  velocity = 0.0;
}

bool PeriodicCommandPort::write(const PeriodicCommand& c, std::string* error) {
  const auto fail = [&](const std::string& why) {
    return reject("port '" + name() + "': rejected periodic command (" + why + "); the previous profile stays", error);
  };
  if (!std::isfinite(c.period) || !std::isfinite(c.amplitude) || !std::isfinite(c.offset)) return fail("a value is not finite");
  if (!(c.period > 0.0)) return fail("period " + std::to_string(c.period) + " s is not > 0");
  if (c.amplitude < 0.0) return fail("amplitude " + std::to_string(c.amplitude) + " rad is negative");
  switch (c.profile) {
    case PeriodicProfile::Hold:
    case PeriodicProfile::Linear:
    case PeriodicProfile::Sine:
      break;
    default:
      return fail("unknown profile " + std::to_string(static_cast<int>(c.profile)));
  }
  buffer_.write(c);
  accepted_.fetch_add(1, std::memory_order_acq_rel);
  return true;
}

bool PeriodicCommandPort::write(std::string_view profile, double period, double amplitude, double offset,
                                std::string* error) {
  PeriodicCommand c{PeriodicProfile::Hold, period, amplitude, offset};
  if (!parse_periodic_profile(profile, c.profile)) {
    return reject("port '" + name() + "': rejected unknown profile '" + std::string(profile) +
                      "' (linear or sine); the previous profile stays",
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
  if (params.has("profile")) {
    const std::string profile = params.get<std::string>("profile");
    PeriodicCommand c;
    if (!parse_periodic_profile(profile, c.profile)) {
      throw ControllerConfigError("parameter " + join_param_path(params.path(), "profile") + ": unknown profile '" +
                                  profile + "' (linear or sine)");
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
    initial_ = c;
  }
  state_.init(JointControllerState{});
  return true;
}

void LaserScannerTrajController::starting(double time) {
  active_ = initial_;
  if (active_.profile == PeriodicProfile::Hold) active_.offset = joint_.position();
  command_.reset_from_rt(active_);
  last_command_seq_ = command_.accepted();
  profile_start_ = time;
  pid_.reset();
}

UpdateStatus LaserScannerTrajController::update(double time, double period) {
  if (!(period > 0.0)) return UpdateStatus::Ok();
  const PeriodicCommand& c = command_.read_from_rt();
  const std::uint64_t seq = command_.accepted();
  if (seq != last_command_seq_) {
    last_command_seq_ = seq;
    active_ = c;
    profile_start_ = time;
  }
  double set_point = 0.0, rate = 0.0;
  periodic_profile_sample(active_, time - profile_start_, set_point, rate);
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
