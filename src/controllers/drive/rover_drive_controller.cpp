#include "controllers/drive/rover_drive_controller.hpp"

#include <algorithm>
#include <cmath>

#include "control/angles.hpp"

namespace mechsim::control {

bool RoverDriveController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  // Claim first, so that an unknown joint is reported as such (naming its parameter) before
  // any geometry parameter that would mention it.
  drive_.claim(hardware, params, "steering_joints", 0, "wheel_joints", 2);
  config_ = read_rover_drive_config(params, hardware);

  drive_.init_pids(params, "steering_pid", "wheel_pid", SteeredDrive::Gains::Shared);
  if (config_.crab_heading_source == RoverDriveConfig::HeadingSource::Imu) {
    heading_imu_ = hardware.imu_sensor(config_.crab_heading_imu, join_param_path(params.path(), "crab_heading_imu"));
  }

  const std::size_t ns = drive_.steering_count(), nw = drive_.wheel_count();
  measured_headings_.assign(ns, 0.0);
  target_headings_.assign(ns, 0.0);
  setpoint_headings_.assign(ns, 0.0);
  rolling_speeds_.assign(nw, 0.0);
  measured_speeds_.assign(nw, 0.0);
  rolling_weights_.assign(nw, 1.0);
  lateral_weights_.assign(nw, 1.0);
  work_rolling_.assign(nw, 1.0);
  work_lateral_.assign(nw, 1.0);
  sensing_.assign(nw, 0);

  odom_.init(odometry_prototype(config_.odom_frame_id, config_.base_frame_id, config_.pose_covariance_diagonal,
                                config_.twist_covariance_diagonal));
  status_.init(RoverDriveStatus{});
  return true;
}

std::vector<Port*> RoverDriveController::ports() {
  std::vector<Port*> out{&command_, &mode_, &odom_, &drive_.state_port(), &status_};
  drive_.append_gains_ports(out);
  return out;
}

void RoverDriveController::starting(double time) {
  const RoverKinematics& k = config_.kinematics;
  for (std::size_t s = 0; s < drive_.steering_count(); ++s) {
    measured_headings_[s] = normalize_angle(k.steering_axis_signs[s] * drive_.steering(s).position());
    target_headings_[s] = measured_headings_[s];
    setpoint_headings_[s] = measured_headings_[s];
  }
  command_timeout_.start(command_, time);
  applied_ = {};
  heading_hold_ = false;
  heading_integral_ = 0.0;
  yaw_correction_ = 0.0;
  crab_sensing_ = false;
  drive_.reset_pids();
}

PlanarTwist RoverDriveController::limit_command(const PlanarTwist& target, double period) const noexcept {
  const double dv = config_.max_linear_acceleration * period;
  const double dw = config_.max_angular_acceleration * period;
  return {step_towards(applied_.vx, clamp_abs(target.vx, config_.max_linear_velocity), dv),
          step_towards(applied_.vy, clamp_abs(target.vy, config_.max_linear_velocity), dv),
          step_towards(applied_.wz, clamp_abs(target.wz, config_.max_angular_velocity), dw)};
}

UpdateStatus RoverDriveController::update(double time, double period) {
  if (!(period > 0.0)) return UpdateStatus::Ok();  // nothing to integrate; the commands stay
  const RoverKinematics& k = config_.kinematics;
  const std::size_t ns = drive_.steering_count(), nw = drive_.wheel_count();

  // 1-2. The command, its timeout and limits.
  const PlanarTwist target = command_timeout_.read(command_, time, config_.cmd_vel_timeout);
  applied_ = limit_command(target, period);

  // 3-4. Mode and inverse kinematics.
  requested_mode_ = mode_.read_from_rt();
  choice_ = select_drive_mode(k, requested_mode_, applied_);
  if (choice_.unsupported) ++unsupported_count_;
  for (std::size_t s = 0; s < ns; ++s) {
    measured_headings_[s] = normalize_angle(k.steering_axis_signs[s] * drive_.steering(s).position());
  }
  const bool crab = choice_.mode == DriveMode::Crab;
  const bool moving = std::hypot(choice_.twist.vx, choice_.twist.vy) > 1e-6;
  select_sensing_wheels(crab && moving);
  update_heading_hold(target, moving, period);
  // The heading hold's yaw rate rides on the crab twist: the front and rear wheels steer a
  // little apart and the wheel speeds follow, as for any twist of A.
  PlanarTwist realised = choice_.twist;
  realised.wz += yaw_correction_;
  inverse_kinematics(k, realised, target_headings_, measured_headings_, target_headings_, rolling_speeds_);

  // 5-6. Steering rate limit; wheels wait for the steering.
  const double max_step = config_.max_steering_rate * period;
  max_steering_error_ = 0.0;
  bool steering_measured = true;  // false when a steering joint reports a non-finite angle
  for (std::size_t s = 0; s < ns; ++s) {
    // Plain difference: both lie within +-max_steering_angle, so the path between them does too.
    setpoint_headings_[s] = step_towards(setpoint_headings_[s], target_headings_[s], max_step);
    const double e = std::abs(shortest_angular_distance(measured_headings_[s], target_headings_[s]));
    steering_measured = steering_measured && std::isfinite(e);
    max_steering_error_ = std::fmax(max_steering_error_, e);
  }
  if (!steering_measured) {
    alignment_scale_ = 0.0;  // do not drive blind
  } else if (max_steering_error_ <= config_.steering_tolerance) {
    alignment_scale_ = 1.0;
  } else if (max_steering_error_ >= config_.steering_stop_error) {
    alignment_scale_ = 0.0;
  } else {
    alignment_scale_ = (config_.steering_stop_error - max_steering_error_) /
                       (config_.steering_stop_error - config_.steering_tolerance);
  }
  const std::span<double> wheel_setpoints = drive_.wheel_setpoints();
  double fastest = 0.0;
  for (std::size_t i = 0; i < nw; ++i) {
    wheel_setpoints[i] = k.wheels[i].axis_sign * rolling_speeds_[i] / k.wheel_radius * alignment_scale_;
    fastest = std::fmax(fastest, std::abs(wheel_setpoints[i]));
  }
  wheel_speed_scale_ = fastest > config_.max_wheel_speed ? config_.max_wheel_speed / fastest : 1.0;
  for (double& w : wheel_setpoints) w *= wheel_speed_scale_;

  // 7. PIDs.
  const std::span<double> steering_setpoints = drive_.steering_setpoints();
  for (std::size_t s = 0; s < ns; ++s) steering_setpoints[s] = k.steering_axis_signs[s] * setpoint_headings_[s];
  drive_.update(period, sensing_);

  // 8. Odometry, then the snapshots.
  update_odometry(time, period);
  publish(time, period);
  return UpdateStatus::Ok();
}

void RoverDriveController::select_sensing_wheels(bool crabbing) noexcept {
  const RoverKinematics& k = config_.kinematics;
  crab_sensing_ = false;
  for (std::size_t i = 0; i < sensing_.size(); ++i) {
    bool sensing = false;
    if (crabbing) {
      switch (config_.crab_sensing_mode) {
        case RoverDriveConfig::CrabSensing::None: break;
        case RoverDriveConfig::CrabSensing::Listed: sensing = config_.crab_sensing[i] != 0; break;
        case RoverDriveConfig::CrabSensing::TrailingSide:
          sensing = k.wheels[i].steering >= 0 && k.wheels[i].y * choice_.twist.vy < 0.0;
          break;
      }
    }
    sensing_[i] = sensing ? 1 : 0;
    crab_sensing_ = crab_sensing_ || sensing;
  }
}

void RoverDriveController::update_heading_hold(const PlanarTwist& target, bool moving, double period) noexcept {
  const bool enabled = config_.crab_heading_p > 0.0 || config_.crab_heading_i > 0.0;
  // Off unless crabbing (moving) without a commanded rotation; each crab motion holds the
  // heading it starts with.
  const bool wz_commanded = std::abs(target.wz) > 1e-9;
  // The yaw the hold acts on: the odometry's, or the IMU's last sample (its orientation's yaw).
  const bool from_imu = heading_imu_.valid();
  const bool yaw_valid = from_imu ? heading_imu_.data().count > 0 : odometry_.valid;
  const double yaw = from_imu ? yaw_of(heading_imu_.data().orientation) : odometry_.pose.yaw;
  if (!enabled || choice_.mode != DriveMode::Crab || wz_commanded || !yaw_valid || !moving) {
    heading_hold_ = false;
    heading_integral_ = 0.0;
    yaw_correction_ = 0.0;
    return;
  }
  if (!heading_hold_) {
    heading_hold_ = true;
    held_yaw_ = yaw;
    heading_integral_ = 0.0;
  }
  const double error = shortest_angular_distance(yaw, held_yaw_);
  if (!std::isfinite(error)) {
    yaw_correction_ = 0.0;
    return;
  }
  const double limit = config_.crab_heading_max_rate;
  if (config_.crab_heading_i > 0.0) {
    // Anti-windup: the integral alone never asks for more than the bound.
    heading_integral_ = clamp_abs(heading_integral_ + error * period, limit / config_.crab_heading_i);
  }
  yaw_correction_ = clamp_abs(config_.crab_heading_p * error + config_.crab_heading_i * heading_integral_, limit);
}

void RoverDriveController::update_odometry(double /*time*/, double period) noexcept {
  const RoverKinematics& k = config_.kinematics;
  if (reset_odometry_.exchange(false, std::memory_order_acq_rel)) {
    odometry_.pose = {};
    heading_hold_ = false;  // the held yaw was in the old frame: hold the new one
  }
  const bool crab = choice_.mode == DriveMode::Crab && drive_.steering_count() > 0;
  for (std::size_t i = 0; i < drive_.wheel_count(); ++i) {
    measured_speeds_[i] = k.wheels[i].axis_sign * drive_.wheel(i).velocity() * k.wheel_radius;
    const bool fixed = k.wheels[i].steering < 0;
    // In crab the fixed wheels slide sideways by design; their no-side-slip rows would be wrong.
    lateral_weights_[i] = crab && fixed ? 0.0 : crab_sensing_ ? config_.crab_lateral_weight : 1.0;
    rolling_weights_[i] = crab_sensing_ && sensing_[i] == 0 ? config_.crab_driven_rolling_weight : 1.0;
  }
  PlanarTwist twist;
  if (estimate_twist_robust(k, measured_headings_, measured_speeds_, rolling_weights_, lateral_weights_,
                            config_.odometry_robust, work_rolling_, work_lateral_, twist, &odometry_.residual)) {
    odometry_.advance(twist, period);
  }
}

void RoverDriveController::publish(double time, double period) noexcept {
  drive_.publish_state(time, period);
  odometry_.publish(odom_, time);
  status_.publish_from_rt([&](RoverDriveStatus& st) {
    st.stamp = time;
    st.requested_mode = requested_mode_;
    st.active_mode = choice_.mode;
    st.command = command_timeout_.value();
    st.applied = choice_.twist;
    st.timed_out = command_timeout_.timed_out();
    st.unsupported = choice_.unsupported;
    st.unsupported_count = unsupported_count_;
    st.alignment_scale = alignment_scale_;
    st.max_steering_error = max_steering_error_;
    st.wheel_speed_scale = wheel_speed_scale_;
    st.crab_sensing = crab_sensing_;
    st.sensing_wheels = 0;
    for (std::size_t i = 0; i < sensing_.size() && i < 32; ++i) {
      if (sensing_[i] != 0) st.sensing_wheels |= std::uint32_t{1} << i;
    }
    st.heading_hold = heading_hold_;
    st.held_yaw = held_yaw_;
    st.yaw_correction = yaw_correction_;
  });
}

}  // namespace mechsim::control
