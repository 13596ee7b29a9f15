#include "controllers/drive/diff_drive_controller.hpp"

#include <cmath>

#include "controllers/ros2_control/ros2_diff_drive_params.hpp"

namespace mechsim::control {

bool DiffDriveController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  config_ = ros2_ ? read_ros2_diff_drive_config(params) : read_diff_drive_config(params);
  const char* left_key = ros2_ ? "left_wheel_names" : "left_wheel";
  const char* right_key = ros2_ ? "right_wheel_names" : "right_wheel";
  const auto claim = [&](const std::vector<std::string>& names, const char* key, std::vector<JointHandle>& out) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      std::string path = join_param_path(params.path(), key);
      if (names.size() > 1 || ros2_) {
        path += '[';
        path += std::to_string(i);
        path += ']';
      }
      out.push_back(hardware.claim_joint(names[i], HardwareInterface::Velocity, path));
    }
  };
  claim(config_.left_wheels, left_key, left_);
  claim(config_.right_wheels, right_key, right_);
  odometry_.init(config_.separation(), config_.left_radius(), config_.right_radius(),
                 static_cast<std::size_t>(config_.velocity_rolling_window_size));
  odom_.init(odometry_prototype(config_.odom_frame_id, config_.base_frame_id, config_.pose_covariance_diagonal,
                                config_.twist_covariance_diagonal, PlanarPose{}));
  TwistSnapshot out;
  out.frame_id = config_.base_frame_id;
  command_out_.init(out);
  return true;
}

double DiffDriveController::mean_position(const std::vector<JointHandle>& wheels) const noexcept {
  double sum = 0.0;
  for (const JointHandle& w : wheels) sum += w.position();
  return sum / static_cast<double>(wheels.size());
}

double DiffDriveController::mean_velocity(const std::vector<JointHandle>& wheels) const noexcept {
  double sum = 0.0;
  for (const JointHandle& w : wheels) sum += w.velocity();
  return sum / static_cast<double>(wheels.size());
}

void DiffDriveController::brake() noexcept {
  for (JointHandle& w : left_) w.set_command(0.0);
  for (JointHandle& w : right_) w.set_command(0.0);
}

void DiffDriveController::starting(double time) {
  brake();
  command_timeout_.start(command_, time);
  last0_linear_ = last0_angular_ = last1_linear_ = last1_angular_ = 0.0;
  // The wheels' travel counts from where they are (ros_controllers counts from 0, which makes a
  // jump when the wheels start elsewhere).
  left_travel_ = mean_position(left_);
  right_travel_ = mean_position(right_);
  last_time_ = time;
  odometry_.reset(left_travel_, right_travel_, time);
}

void DiffDriveController::stopping(double /*time*/) { brake(); }

UpdateStatus DiffDriveController::update(double time, double period) {
  if (config_.open_loop) {
    odometry_.update_open_loop(last0_linear_, last0_angular_, time);
  } else if (config_.position_feedback) {
    odometry_.update(mean_position(left_), mean_position(right_), time);
  } else {
    // ros2_controllers' updateFromVelocity: each side's velocity over the step.
    const double dt = time - last_time_;
    left_travel_ += mean_velocity(left_) * dt;
    right_travel_ += mean_velocity(right_) * dt;
    odometry_.update(left_travel_, right_travel_, time);
  }
  last_time_ = time;
  odom_.publish_from_rt([&](OdometrySnapshot& o) {
    o.stamp = time;
    o.x = odometry_.pose().x;
    o.y = odometry_.pose().y;
    o.yaw = std::remainder(odometry_.pose().yaw, 2.0 * M_PI);
    o.linear = {odometry_.linear(), 0.0, 0.0};
    o.angular = {0.0, 0.0, odometry_.angular()};
    o.valid = true;
  });

  const PlanarTwist command = command_timeout_.read(command_, time, config_.cmd_vel_timeout);
  const double linear = config_.linear.limit(command.vx, last0_linear_, last1_linear_, period);
  const double angular = config_.angular.limit(command.wz, last0_angular_, last1_angular_, period);
  last1_linear_ = last0_linear_;
  last1_angular_ = last0_angular_;
  last0_linear_ = linear;
  last0_angular_ = angular;
  if (config_.publish_cmd) {
    command_out_.publish_from_rt([&](TwistSnapshot& t) {
      t.stamp = time;
      t.twist.linear = {linear, 0.0, 0.0};
      t.twist.angular = {0.0, 0.0, angular};
    });
  }

  const WheelRimSpeeds rim = diff_drive_rim_speeds(linear, angular, config_.separation());
  const double left = rim.left / config_.left_radius(), right = rim.right / config_.right_radius();
  for (JointHandle& w : left_) w.set_command(left);
  for (JointHandle& w : right_) w.set_command(right);
  return UpdateStatus::Ok();
}

std::vector<Port*> DiffDriveController::ports() {
  std::vector<Port*> out{&command_, &odom_};
  if (config_.publish_cmd) out.push_back(&command_out_);
  return out;
}

}  // namespace mechsim::control
