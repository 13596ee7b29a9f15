#include "controllers/sensor/sensor_state_controllers.hpp"

#include <cmath>

namespace mechsim::control {

template <class Snapshot>
bool SensorStateController<Snapshot>::read_rate(const Params& params, const char* type, std::string& error) {
  const std::string path = join_param_path(params.path(), "publish_rate");
  if (!params.has("publish_rate")) {
    error = std::string(type) + ": parameter " + path + " not set (the publishing rate, Hz)";
    return false;
  }
  publish_rate_ = params.get<double>("publish_rate");
  if (!(publish_rate_ > 0.0) || !std::isfinite(publish_rate_)) {
    error = std::string(type) + ": parameter " + path + " must be a finite rate > 0 in Hz, got " +
            std::to_string(publish_rate_);
    return false;
  }
  return true;
}

template <class Snapshot>
void SensorStateController<Snapshot>::add_port(const Snapshot& prototype, const std::string& name) {
  ports_.push_back(std::make_unique<StatePort<Snapshot>>(name));
  ports_.back()->init(prototype);
  last_publish_.push_back(0.0);
}

template <class Snapshot>
std::vector<Port*> SensorStateController<Snapshot>::ports() {
  std::vector<Port*> out;
  for (const auto& p : ports_) out.push_back(p.get());
  return out;
}

template <class Snapshot>
void SensorStateController<Snapshot>::starting(double time) {
  for (double& t : last_publish_) t = time;
}

template <class Snapshot>
template <class Fill>
void SensorStateController<Snapshot>::publish_due(std::size_t i, double time, Fill&& fill) noexcept {
  const double interval = 1.0 / publish_rate_;
  if (!(last_publish_[i] + interval < time)) return;
  const bool published = ports_[i]->publish_from_rt([&](Snapshot& s) {
    s.stamp = time;
    fill(s);
  });
  // As ros_controllers: a snapshot skipped because a reader held it is retried next tick.
  if (published) last_publish_[i] += interval;
}

template class SensorStateController<ImuSnapshot>;
template class SensorStateController<WrenchSnapshot>;

bool ImuSensorController::init(RobotHardware& hardware, const Params& params, std::string& error) {
  if (!read_rate(params, kImuSensorControllerType, error)) return false;
  sensors_ = hardware.imu_sensors();
  if (sensors_.empty()) {
    error = std::string(kImuSensorControllerType) + " (" + params.path() +
            "): the robot has no IMU (hardware_interface::ImuSensorInterface has no handle; IMUs come from the "
            "description's <sensor type=\"imu\"> blocks and IMU plugins)";
    return false;
  }
  for (const ImuSensorHandle& h : sensors_) add_port(ImuSnapshot{0.0, h.data()}, h.name());
  return true;
}

UpdateStatus ImuSensorController::update(double time, double /*period*/) {
  for (std::size_t i = 0; i < sensors_.size(); ++i) {
    const ImuSensorData& d = sensors_[i].data();
    // The numbers only: name and frame_id are the prototype's (no string copy in the tick).
    publish_due(i, time, [&d](ImuSnapshot& s) {
      s.imu.stamp = d.stamp;
      s.imu.count = d.count;
      s.imu.orientation = d.orientation;
      s.imu.angular_velocity = d.angular_velocity;
      s.imu.linear_acceleration = d.linear_acceleration;
      s.imu.orientation_covariance = d.orientation_covariance;
      s.imu.angular_velocity_covariance = d.angular_velocity_covariance;
      s.imu.linear_acceleration_covariance = d.linear_acceleration_covariance;
    });
  }
  return UpdateStatus::Ok();
}

bool ForceTorqueSensorController::init(RobotHardware& hardware, const Params& params, std::string& error) {
  if (!read_rate(params, kForceTorqueSensorControllerType, error)) return false;
  sensors_ = hardware.force_torque_sensors();
  if (sensors_.empty()) {
    error = std::string(kForceTorqueSensorControllerType) + " (" + params.path() +
            "): the robot has no force-torque sensor (hardware_interface::ForceTorqueSensorInterface has no handle; "
            "they come from the description's <sensor type=\"force_torque\"> blocks and gazebo_ros_ft_sensor plugins)";
    return false;
  }
  for (const ForceTorqueSensorHandle& h : sensors_) add_port(WrenchSnapshot{0.0, h.data()}, h.name());
  return true;
}

UpdateStatus ForceTorqueSensorController::update(double time, double /*period*/) {
  for (std::size_t i = 0; i < sensors_.size(); ++i) {
    const ForceTorqueSensorData& d = sensors_[i].data();
    publish_due(i, time, [&d](WrenchSnapshot& s) {
      s.wrench.stamp = d.stamp;
      s.wrench.count = d.count;
      s.wrench.force = d.force;
      s.wrench.torque = d.torque;
    });
  }
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
