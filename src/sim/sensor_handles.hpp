#pragma once
// The simulation's side of the controllers' sensor interfaces (control/sensor_hardware.hpp): the
// IMU and force-torque sensors of a SensorSet as handles, filled from each new sample. Run in
// the tick after the sensors sample (step 5), so that the controllers of the next tick read the
// last sample; a sensor some controller took a handle on is held (sampled at its rate whether
// or not anything else consumes it).

#include <cstddef>
#include <memory>
#include <vector>

#include "control/sensor_hardware.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sim {

class SensorHandles {
 public:
  SensorHandles();
  // One handle per IMU and force-torque sensor of `set` (the simulated ones), at rest until fill().
  explicit SensorHandles(const sensors::SensorSet& set);

  const control::SensorHardware& hardware() const { return *hardware_; }
  // Copies every new sample of the set into its handle; holds the sensors controllers use. No
  // allocation (the handles' storage is sized at construction).
  void fill(sensors::SensorSet& set) noexcept;

 private:
  std::unique_ptr<control::SensorHardware> hardware_;
  std::vector<std::size_t> imu_index_, force_torque_index_;  // per handle: its sensor in the set
};

}  // namespace mechsim::sim
