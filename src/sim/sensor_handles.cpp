#include "sim/sensor_handles.hpp"

#include <variant>

namespace mechsim::sim {

SensorHandles::SensorHandles() : hardware_(std::make_unique<control::SensorHardware>()) {}

SensorHandles::SensorHandles(const sensors::SensorSet& set) {
  std::vector<description::SensorSpec> specs;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const auto& details = set.spec(i).details;
    if (std::holds_alternative<description::ImuSpec>(details)) {
      imu_index_.push_back(i);
      specs.push_back(set.spec(i));
    } else if (std::holds_alternative<description::ForceTorqueSpec>(details)) {
      force_torque_index_.push_back(i);
      specs.push_back(set.spec(i));
    }
  }
  hardware_ = control::make_sensor_hardware(specs);  // same order within each kind
}

namespace {

void copy3(const description::Vec3& v, std::array<double, 3>& out) noexcept { out = {v.x, v.y, v.z}; }

}  // namespace

void SensorHandles::fill(sensors::SensorSet& set) noexcept {
  std::vector<control::ImuSensorData>& imus = hardware_->imus();
  for (std::size_t h = 0; h < imus.size(); ++h) {
    const std::size_t i = imu_index_[h];
    if (hardware_->imu_used(h) && !set.held(i)) set.set_held(i, true);
    const sensors::SensorReading& r = set.reading(i);
    control::ImuSensorData& d = imus[h];
    if (r.count == d.count) continue;
    const auto* imu = std::get_if<sensors::ImuReading>(&r.value);
    if (imu == nullptr) continue;
    d.count = r.count;
    d.stamp = r.stamp;
    d.orientation = {imu->orientation.x, imu->orientation.y, imu->orientation.z, imu->orientation.w};
    copy3(imu->angular_velocity, d.angular_velocity);
    copy3(imu->linear_acceleration, d.linear_acceleration);
    d.orientation_covariance = imu->orientation_covariance;
    d.angular_velocity_covariance = imu->angular_velocity_covariance;
    d.linear_acceleration_covariance = imu->linear_acceleration_covariance;
  }
  std::vector<control::ForceTorqueSensorData>& fts = hardware_->force_torque();
  for (std::size_t h = 0; h < fts.size(); ++h) {
    const std::size_t i = force_torque_index_[h];
    if (hardware_->force_torque_used(h) && !set.held(i)) set.set_held(i, true);
    const sensors::SensorReading& r = set.reading(i);
    control::ForceTorqueSensorData& d = fts[h];
    if (r.count == d.count) continue;
    const auto* wrench = std::get_if<sensors::WrenchReading>(&r.value);
    if (wrench == nullptr) continue;
    d.count = r.count;
    d.stamp = r.stamp;
    copy3(wrench->force, d.force);
    copy3(wrench->torque, d.torque);
  }
}

}  // namespace mechsim::sim
