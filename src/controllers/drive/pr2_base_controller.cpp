#include "controllers/drive/pr2_base_controller.hpp"

#include <cmath>

#include "control/angles.hpp"

namespace mechsim::control {

bool Pr2BaseController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  // Claim first, so that an unknown joint is reported as such before any geometry parameter.
  drive_.claim(hardware, params, "caster_joints", 1, "wheel_joints", 1);
  config_ = read_pr2_base_config(params);

  drive_.init_pids(params, "caster_pid", "wheel_pid", SteeredDrive::Gains::JointOrShared);
  measured_headings_.assign(drive_.steering_count(), 0.0);
  target_headings_.assign(drive_.steering_count(), 0.0);
  status_.init(Pr2BaseStatus{});
  return true;
}

std::vector<Port*> Pr2BaseController::ports() {
  std::vector<Port*> out{&command_, &drive_.state_port(), &status_};
  drive_.append_gains_ports(out);
  return out;
}

void Pr2BaseController::starting(double time) {
  const Pr2BaseKinematics& k = config_.geometry.kinematics;
  for (std::size_t c = 0; c < drive_.steering_count(); ++c) {
    measured_headings_[c] = normalize_angle(k.casters[c].axis_sign * drive_.steering(c).position());
    target_headings_[c] = measured_headings_[c];
  }
  command_timeout_.start(command_, time);
  applied_ = {};
  drive_.reset_pids();
}

PlanarTwist Pr2BaseController::limit_command(const PlanarTwist& target, double period) const noexcept {
  PlanarTwist t = target;
  const double speed = std::hypot(t.vx, t.vy);
  if (speed > config_.max_translational_velocity) {
    const double s = config_.max_translational_velocity / speed;
    t.vx *= s;
    t.vy *= s;
  }
  t.wz = clamp_abs(t.wz, config_.max_rotational_velocity);
  return {step_towards(applied_.vx, t.vx, config_.max_translational_acceleration_x * period),
          step_towards(applied_.vy, t.vy, config_.max_translational_acceleration_y * period),
          step_towards(applied_.wz, t.wz, config_.max_rotational_acceleration * period)};
}

UpdateStatus Pr2BaseController::update(double time, double period) {
  if (!(period > 0.0)) return UpdateStatus::Ok();
  const Pr2BaseKinematics& k = config_.geometry.kinematics;
  const std::size_t nc = drive_.steering_count(), nw = drive_.wheel_count();

  // 1-2. Command, timeout, limits.
  const PlanarTwist target = command_timeout_.read(command_, time, config_.timeout);
  applied_ = limit_command(target, period);

  // 3. Caster headings.
  for (std::size_t c = 0; c < nc; ++c) {
    measured_headings_[c] = normalize_angle(k.casters[c].axis_sign * drive_.steering(c).position());
  }
  caster_headings(k, applied_, measured_headings_, target_headings_, target_headings_, config_.caster_hold_speed);
  max_caster_error_ = 0.0;
  reversed_ = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    double vx = 0.0, vy = 0.0;
    point_velocity(applied_, k.casters[c].x, k.casters[c].y, vx, vy);
    if (vx * std::cos(target_headings_[c]) + vy * std::sin(target_headings_[c]) < 0.0) ++reversed_;
    max_caster_error_ =
        std::fmax(max_caster_error_, std::abs(shortest_angular_distance(measured_headings_[c], target_headings_[c])));
  }

  // 4. Wheel set points from the measured caster state.
  const std::span<double> wheel_setpoints = drive_.wheel_setpoints();
  for (std::size_t w = 0; w < nw; ++w) {
    const std::size_t c = k.wheels[w].caster;
    const double heading = measured_headings_[c];
    const double rate = k.casters[c].axis_sign * drive_.steering(c).velocity();
    const double speed = std::isfinite(heading) && std::isfinite(rate) ? wheel_rolling_speed(k, w, applied_, heading, rate) : 0.0;
    wheel_setpoints[w] = k.wheels[w].axis_sign * speed / k.wheel_radius;
  }

  // 5. PIDs.
  const std::span<double> steering_setpoints = drive_.steering_setpoints();
  for (std::size_t c = 0; c < nc; ++c) steering_setpoints[c] = k.casters[c].axis_sign * target_headings_[c];
  drive_.update(period);
  publish(time, period);
  return UpdateStatus::Ok();
}

void Pr2BaseController::publish(double time, double period) noexcept {
  drive_.publish_state(time, period);
  status_.publish_from_rt([&](Pr2BaseStatus& st) {
    st.stamp = time;
    st.command = command_timeout_.value();
    st.applied = applied_;
    st.timed_out = command_timeout_.timed_out();
    st.max_caster_error = max_caster_error_;
    st.reversed_casters = reversed_;
  });
}

}  // namespace mechsim::control
