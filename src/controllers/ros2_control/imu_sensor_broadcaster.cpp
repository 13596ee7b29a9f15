#include "controllers/ros2_control/imu_sensor_broadcaster.hpp"

#include <cmath>

namespace mechsim::control {

namespace {

std::string required_string(const Params& params, const char* key) {
  const std::string path = join_param_path(params.path(), key);
  if (!params.has(key)) throw ControllerConfigError("parameter " + path + " not set (ros2_controllers requires it)");
  const std::string value = params.get<std::string>(key);
  if (value.empty()) throw ControllerConfigError("parameter " + path + " is empty");
  return value;
}

std::array<double, 9> covariance(const Params& params, const char* key) {
  std::array<double, 9> out{};
  if (!params.has(key)) return out;
  const auto v = params.get<std::vector<double>>(key);
  const std::string path = join_param_path(params.path(), key);
  if (v.size() != 9) throw ControllerConfigError("parameter " + path + " must list 9 values (row-major 3x3), got " + std::to_string(v.size()));
  for (std::size_t i = 0; i < 9; ++i) {
    if (!std::isfinite(v[i])) throw ControllerConfigError("parameter " + path + "[" + std::to_string(i) + "] is not finite");
    out[i] = v[i];
  }
  return out;
}

}  // namespace

bool ImuSensorBroadcaster::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const std::string name = required_string(params, "sensor_name");
  const std::string frame = required_string(params, "frame_id");
  orientation_covariance_ = covariance(params, "static_covariance_orientation");
  angular_velocity_covariance_ = covariance(params, "static_covariance_angular_velocity");
  linear_acceleration_covariance_ = covariance(params, "static_covariance_linear_acceleration");
  sensor_ = hardware.imu_sensor(name, join_param_path(params.path(), "sensor_name"));
  ImuSnapshot prototype;
  prototype.imu = sensor_.data();
  prototype.imu.frame_id = frame;
  prototype.imu.orientation_covariance = orientation_covariance_;
  prototype.imu.angular_velocity_covariance = angular_velocity_covariance_;
  prototype.imu.linear_acceleration_covariance = linear_acceleration_covariance_;
  imu_.init(prototype);
  return true;
}

UpdateStatus ImuSensorBroadcaster::update(double time, double /*period*/) {
  const ImuSensorData& d = sensor_.data();
  imu_.publish_from_rt([&](ImuSnapshot& s) {
    s.stamp = time;
    // The strings stay the prototype's (no allocation in the tick).
    s.imu.stamp = d.stamp;
    s.imu.count = d.count;
    s.imu.orientation = d.orientation;
    s.imu.angular_velocity = d.angular_velocity;
    s.imu.linear_acceleration = d.linear_acceleration;
  });
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
