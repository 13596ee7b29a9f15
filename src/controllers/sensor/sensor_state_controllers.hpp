#pragma once
// ros_controllers' sensor publishers over the sensor interfaces (control/sensor_hardware.hpp):
//   imu_sensor_controller/ImuSensorController                   every ImuSensorInterface handle
//   force_torque_sensor_controller/ForceTorqueSensorController  every ForceTorqueSensorInterface handle
// Parameter: publish_rate (Hz, required, finite and > 0). Each handle gets a state port named
// after it (the handle's name, i.e. the sensor's); a snapshot is due when more than 1/publish_rate
// has passed since the last one (the first one 1/publish_rate after starting), ros_controllers'
// timing, per handle. A snapshot holds the handle's values as they are at the update (the
// sensor's last sample: a 100 Hz IMU published at 200 Hz repeats each sample), stamped with the
// update's time and the handle's frame_id, as ros_controllers stamps its messages. The ROS node
// publishes each port as sensor_msgs/Imu or geometry_msgs/WrenchStamped on <robot ns>/<handle
// name>: ros_controllers advertises on the controller manager's node handle (root_nh), not the
// controller's. Claims nothing (ros_control's sensor interfaces claim no resource). A robot
// without a sensor of the kind is refused at init, naming the controller type.

#include <memory>
#include <vector>

#include "control/controller.hpp"
#include "control/sensor_hardware.hpp"

namespace mechsim::control {

// What one ImuSensorController port carries per publish.
struct ImuSnapshot {
  double stamp = 0.0;  // s: the update that published it (header.stamp)
  ImuSensorData imu;   // name, frame_id, the last sample (imu.stamp: its sample time)
};

struct WrenchSnapshot {
  double stamp = 0.0;
  ForceTorqueSensorData wrench;
};

template <>
constexpr PortKind state_port_kind<ImuSnapshot>() { return PortKind::ImuState; }
template <>
constexpr PortKind state_port_kind<WrenchSnapshot>() { return PortKind::WrenchState; }

inline constexpr const char* kImuSensorControllerType = "imu_sensor_controller/ImuSensorController";
inline constexpr const char* kForceTorqueSensorControllerType = "force_torque_sensor_controller/ForceTorqueSensorController";

// The part both share: publish_rate, one port per handle, the timing.
template <class Snapshot>
class SensorStateController : public Controller {
 public:
  void starting(double time) override;
  std::vector<Port*> ports() override;
  double publish_rate() const { return publish_rate_; }
  StatePort<Snapshot>* sensor_port(std::size_t i) { return ports_[i].get(); }
  std::size_t sensor_count() const { return ports_.size(); }

 protected:
  // Reads publish_rate; false with `error` naming the parameter.
  bool read_rate(const Params& params, const char* type, std::string& error);
  void add_port(const Snapshot& prototype, const std::string& name);
  // Publishes port i when due; `fill` copies the handle's values into the snapshot.
  template <class Fill>
  void publish_due(std::size_t i, double time, Fill&& fill) noexcept;

 private:
  double publish_rate_ = 0.0;  // Hz
  std::vector<double> last_publish_;  // s, per port
  std::vector<std::unique_ptr<StatePort<Snapshot>>> ports_;
};

class ImuSensorController : public SensorStateController<ImuSnapshot> {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  UpdateStatus update(double time, double period) override;

 private:
  std::vector<ImuSensorHandle> sensors_;
};

class ForceTorqueSensorController : public SensorStateController<WrenchSnapshot> {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  UpdateStatus update(double time, double period) override;

 private:
  std::vector<ForceTorqueSensorHandle> sensors_;
};

}  // namespace mechsim::control
