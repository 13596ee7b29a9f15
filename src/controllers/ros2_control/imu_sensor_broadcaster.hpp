#pragma once
// ros2_controllers' imu_sensor_broadcaster/IMUSensorBroadcaster: every update, the IMU's last
// sample (its <ros2_control><sensor> state interfaces: orientation, angular_velocity,
// linear_acceleration) in the "imu" port (sensor_msgs/Imu; the wire layer publishes ~/imu),
// stamped with the update's time, in frame_id, with the static covariances. Claims nothing.
//
// Parameters: sensor_name (required: a simulated IMU, the Gazebo <sensor> the ros2_control
// <sensor> of that name binds to), frame_id (required), static_covariance_orientation,
// static_covariance_angular_velocity, static_covariance_linear_acceleration (9 values each,
// row-major; zeros).

#include <array>

#include "control/controller.hpp"
#include "controllers/sensor/sensor_state_controllers.hpp"

namespace mechsim::control {

inline constexpr const char* kImuSensorBroadcasterType = "imu_sensor_broadcaster/IMUSensorBroadcaster";

class ImuSensorBroadcaster : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&imu_}; }

  StatePort<ImuSnapshot>& imu_port() { return imu_; }

 private:
  ImuSensorHandle sensor_;
  std::array<double, 9> orientation_covariance_{}, angular_velocity_covariance_{}, linear_acceleration_covariance_{};
  StatePort<ImuSnapshot> imu_{"imu"};
};

}  // namespace mechsim::control
