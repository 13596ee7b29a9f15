#pragma once
// The robot's sensors as controllers see them: ros_control's ImuSensorInterface and
// ForceTorqueSensorInterface. One handle per IMU / force-torque sensor of the robot, named by the
// sensor's name (the <sensor name> of its Gazebo block, or its model plugin's name), with the
// frame its ROS plugin publishes in. The control layer knows no sensor code: whoever runs the
// tick (sim::Simulation) fills a SensorHardware from its sensors' latest samples before the
// controllers update, so a handle holds the last sample (a 100 Hz IMU changes every 10 ticks at
// 1 kHz). Handles are real-time safe: plain reads of data that only the tick writes.

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::description {
struct SensorSpec;  // description/sensor_spec.hpp
}  // namespace mechsim::description

namespace mechsim::control {

// What hardware_interface::ImuSensorHandle exposes, as plain data.
struct ImuSensorData {
  std::string name;      // handle name: the sensor's name
  std::string frame_id;  // the frame the values are in
  double stamp = 0.0;    // s of simulated time of the sample
  std::uint64_t count = 0;  // samples so far (changes with each new one)
  // Orientation of the sensor frame (x, y, z, w), in the world or the frame it started in.
  std::array<double, 4> orientation{0.0, 0.0, 0.0, 1.0};
  std::array<double, 3> angular_velocity{};     // rad/s, sensor frame
  std::array<double, 3> linear_acceleration{};  // m/s^2, sensor frame, gravity included (+9.81 up at rest)
  std::array<double, 9> orientation_covariance{}, angular_velocity_covariance{},
      linear_acceleration_covariance{};  // row-major 3x3
};

// What hardware_interface::ForceTorqueSensorHandle exposes, as plain data.
struct ForceTorqueSensorData {
  std::string name;
  std::string frame_id;
  double stamp = 0.0;
  std::uint64_t count = 0;
  std::array<double, 3> force{};   // N, frame_id
  std::array<double, 3> torque{};  // N m, frame_id
};

// The sensors of one simulation. Sized once before any controller loads (handles point into the
// vectors); the tick writes the values; `used` flags which sensors some controller took a handle
// on (set at configuration time by any thread, read by the tick: the owner keeps those sampled).
class SensorHardware {
 public:
  SensorHardware() = default;
  SensorHardware(std::vector<ImuSensorData> imus, std::vector<ForceTorqueSensorData> force_torque)
      : imus_(std::move(imus)), force_torque_(std::move(force_torque)),
        imu_used_(imus_.size()), force_torque_used_(force_torque_.size()) {}
  SensorHardware(const SensorHardware&) = delete;
  SensorHardware& operator=(const SensorHardware&) = delete;

  std::vector<ImuSensorData>& imus() { return imus_; }
  const std::vector<ImuSensorData>& imus() const { return imus_; }
  std::vector<ForceTorqueSensorData>& force_torque() { return force_torque_; }
  const std::vector<ForceTorqueSensorData>& force_torque() const { return force_torque_; }

  bool imu_used(std::size_t i) const { return imu_used_[i].load(std::memory_order_relaxed); }
  bool force_torque_used(std::size_t i) const { return force_torque_used_[i].load(std::memory_order_relaxed); }
  void mark_imu_used(std::size_t i) const { imu_used_[i].store(true, std::memory_order_relaxed); }
  void mark_force_torque_used(std::size_t i) const { force_torque_used_[i].store(true, std::memory_order_relaxed); }

 private:
  std::vector<ImuSensorData> imus_;
  std::vector<ForceTorqueSensorData> force_torque_;
  mutable std::vector<std::atomic<bool>> imu_used_, force_torque_used_;
};

// hardware_interface::ImuSensorHandle: read only, no claim (ros_control's sensor interfaces
// claim nothing).
class ImuSensorHandle {
 public:
  ImuSensorHandle() = default;
  explicit ImuSensorHandle(const ImuSensorData* data) : data_(data) {}
  const std::string& name() const { return data_->name; }
  const std::string& frame_id() const { return data_->frame_id; }
  const ImuSensorData& data() const noexcept { return *data_; }
  bool valid() const noexcept { return data_ != nullptr; }

 private:
  const ImuSensorData* data_ = nullptr;
};

class ForceTorqueSensorHandle {
 public:
  ForceTorqueSensorHandle() = default;
  explicit ForceTorqueSensorHandle(const ForceTorqueSensorData* data) : data_(data) {}
  const std::string& name() const { return data_->name; }
  const std::string& frame_id() const { return data_->frame_id; }
  const ForceTorqueSensorData& data() const noexcept { return *data_; }
  bool valid() const noexcept { return data_ != nullptr; }

 private:
  const ForceTorqueSensorData* data_ = nullptr;
};

// The handles a robot's sensor specs give: one per IMU and per force-torque spec, in their order,
// named by the spec's name, frame_id the plugin's frame (without a leading '/'), else the link.
// Values stay at rest until the owner fills them.
std::unique_ptr<SensorHardware> make_sensor_hardware(const std::vector<description::SensorSpec>& specs);

// Yaw (rad, about the reference frame's z) of an orientation (x, y, z, w): the heading of the
// sensor's x axis, as tf's getYaw gives it.
double yaw_of(const std::array<double, 4>& q) noexcept;

}  // namespace mechsim::control
