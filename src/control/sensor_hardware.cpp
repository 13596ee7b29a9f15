#include "control/sensor_hardware.hpp"

#include <variant>

#include "description/sensor_spec.hpp"

namespace mechsim::control {

namespace {

// The frame a sensor's values are in, as its ROS plugin names it (tf2's form: no leading '/'),
// else the link it is attached to.
std::string sensor_frame(const description::SensorSpec& spec) {
  std::string frame = spec.plugin && !spec.plugin->frame.empty() ? spec.plugin->frame : spec.link;
  while (!frame.empty() && frame.front() == '/') frame.erase(0, 1);
  return frame;
}

}  // namespace

std::unique_ptr<SensorHardware> make_sensor_hardware(const std::vector<description::SensorSpec>& specs) {
  std::vector<ImuSensorData> imus;
  std::vector<ForceTorqueSensorData> force_torque;
  for (const description::SensorSpec& spec : specs) {
    if (std::holds_alternative<description::ImuSpec>(spec.details)) {
      ImuSensorData d;
      d.name = spec.name;
      d.frame_id = sensor_frame(spec);
      imus.push_back(std::move(d));
    } else if (std::holds_alternative<description::ForceTorqueSpec>(spec.details)) {
      ForceTorqueSensorData d;
      d.name = spec.name;
      d.frame_id = sensor_frame(spec);
      force_torque.push_back(std::move(d));
    }
  }
  return std::make_unique<SensorHardware>(std::move(imus), std::move(force_torque));
}

}  // namespace mechsim::control
