#pragma once
// The robot as a controller sees it: joint handles over the mechanism state, looked up by
// name during init() and recorded as resource claims (ros_control's hardware interfaces and
// ClaimResources). Handles are real-time safe: plain pointer reads and writes.

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "control/sensor_hardware.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::control {

using mechanism::HardwareInterface;

// ros_control's class name for an interface: "hardware_interface::EffortJointInterface".
const char* interface_name(HardwareInterface iface);
// Short form used in listings: "effort", "position", "velocity".
const char* interface_short_name(HardwareInterface iface);
// Accepts "EffortJointInterface", "hardware_interface/EffortJointInterface",
// "hardware_interface::EffortJointInterface" (and the Position/Velocity ones). False if unknown.
bool parse_interface_name(std::string_view text, HardwareInterface& out);

// A configuration error of a controller (unknown joint, missing interface, bad value). The
// message names the controller's parameter path and the joint.
class ControllerConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Read access to one joint (JointStateInterface): no claim.
class JointStateHandle {
 public:
  JointStateHandle() = default;
  JointStateHandle(const mechanism::JointInfo* info, const mechanism::JointState* state) : info_(info), state_(state) {}
  const std::string& name() const { return info_->name; }
  const mechanism::JointInfo& info() const { return *info_; }
  double position() const noexcept { return state_->position; }        // rad or m
  double velocity() const noexcept { return state_->velocity; }        // rad/s or m/s
  double effort() const noexcept { return state_->measured_effort; }   // N m or N

 private:
  const mechanism::JointInfo* info_ = nullptr;
  const mechanism::JointState* state_ = nullptr;
};

// Read/write access to one claimed joint through one hardware interface.
class JointHandle {
 public:
  JointHandle() = default;
  JointHandle(const mechanism::JointInfo* info, mechanism::JointState* state, HardwareInterface iface)
      : info_(info), state_(state), iface_(iface) {}
  const std::string& name() const { return info_->name; }
  const mechanism::JointInfo& info() const { return *info_; }
  HardwareInterface interface() const { return iface_; }
  double position() const noexcept { return state_->position; }
  double velocity() const noexcept { return state_->velocity; }
  double effort() const noexcept { return state_->measured_effort; }
  // Writes the command of this handle's interface (effort N m or N, position rad or m,
  // velocity rad/s or m/s) and selects that interface for the joint this tick.
  void set_command(double value) noexcept;
  double command() const noexcept;
  // Bounds the physics' effort on this joint in every mode (N m or N; 0: the joint's own), as a
  // Gazebo plugin's joint "fmax" does. Stays until changed (JointState::effort_limit).
  void set_effort_limit(double limit) noexcept { state_->effort_limit = limit; }

 private:
  const mechanism::JointInfo* info_ = nullptr;
  mechanism::JointState* state_ = nullptr;
  HardwareInterface iface_ = HardwareInterface::Effort;
};

// Read/write access to the floating base, a physics port (mechanism/base_state.hpp): its state
// as the physics last reported it and a planar velocity command the physics applies before its
// next step. Real-time safe: plain reads and writes.
class BaseHandle {
 public:
  BaseHandle() = default;
  BaseHandle(const mechanism::BaseState* state, mechanism::BaseVelocityCommand* command) : state_(state), command_(command) {}
  const mechanism::BaseState& state() const noexcept { return *state_; }
  // Linear (vx, vy) in m/s and angular wz in rad/s, all in the world frame (see BaseVelocityCommand).
  void set_planar_velocity(double vx, double vy, double wz) noexcept { *command_ = {true, vx, vy, wz}; }
  // The physics leaves the base alone again.
  void release() noexcept { command_->active = false; }
  bool valid() const noexcept { return command_ != nullptr; }

 private:
  const mechanism::BaseState* state_ = nullptr;
  mechanism::BaseVelocityCommand* command_ = nullptr;
};

// Who is asking. ros_control controllers see what gazebo_ros_control's hardware offers: the joints
// transmissions drive, through the interfaces the transmissions name. Gazebo model plugins call
// the physics' joints directly: they may command any joint of the mechanism (Direct joints
// included, mechanism/direct_joints.hpp) in any mode, and claim the floating base.
enum class HardwareAccess : std::uint8_t { RosControl, ModelPlugin };

struct ResourceClaim {
  HardwareInterface interface = HardwareInterface::Effort;
  std::vector<std::string> joints;  // in claim order, no duplicates
};

// A sensor interface a controller reads: ros_control's sensor interfaces claim nothing, but
// list_controllers names them with the handles (here: the sensors) the controller took.
struct SensorUse {
  std::string interface;             // "hardware_interface::ImuSensorInterface", "...ForceTorqueSensorInterface"
  std::vector<std::string> sensors;  // handle names, in the order taken, no duplicates
};

// One controller's view of the robot during init(). Not thread-safe; configuration time only.
class RobotHardware {
 public:
  RobotHardware(const mechanism::MechanismModel& model, mechanism::MechanismState& state,
                HardwareAccess access = HardwareAccess::RosControl);

  // Claims `joint` for writing through `iface`. Throws ControllerConfigError naming the joint,
  // `param_path` (the parameter that named it) and what is available when the joint is unknown
  // or its transmission does not offer the interface.
  JointHandle claim_joint(const std::string& joint, HardwareInterface iface, std::string_view param_path = {});
  // Read-only access; throws ControllerConfigError for an unknown joint.
  JointStateHandle joint_state(const std::string& joint, std::string_view param_path = {}) const;

  const mechanism::MechanismModel& model() const { return model_; }
  std::size_t joint_count() const { return model_.joints.size(); }
  JointStateHandle joint_state(std::size_t index) const;
  int find_joint(std::string_view name) const;  // -1 when absent

  const std::vector<ResourceClaim>& claims() const { return claims_; }

  // The floating base's state (read only, no claim). BaseState::floating is false for a robot
  // fixed to the world, or when the caller built no physics (tests).
  const mechanism::BaseState& base_state() const { return state_.base; }
  // Claims the floating base for velocity commands. Model plugins only; throws
  // ControllerConfigError naming `param_path` for a ros_control controller or a robot fixed to
  // the world.
  BaseHandle claim_base(std::string_view param_path = {});
  bool claims_base() const { return claims_base_; }
  HardwareAccess access() const { return access_; }
  // Who drives a Direct joint (mechanism/direct_joints.hpp), for the error a ros_control claim on
  // it gets: given the joint's index, a description ("Gazebo model plugin 'x' (...)") or "".
  void set_direct_joint_owner(std::function<std::string(int)> owner) { direct_owner_ = std::move(owner); }

  // The robot's IMU and force-torque sensors (control/sensor_hardware.hpp); null or empty when the
  // simulation has none (or runs without sensors).
  void set_sensors(const SensorHardware* sensors) { sensors_ = sensors; }
  // ImuSensorInterface::getHandle: the handle of the IMU named `name`; throws ControllerConfigError
  // naming `param_path` and the robot's IMUs when there is none of that name.
  ImuSensorHandle imu_sensor(const std::string& name, std::string_view param_path = {});
  // Every IMU's handle, in the description's order (ImuSensorInterface::getNames).
  std::vector<ImuSensorHandle> imu_sensors();
  ForceTorqueSensorHandle force_torque_sensor(const std::string& name, std::string_view param_path = {});
  std::vector<ForceTorqueSensorHandle> force_torque_sensors();
  // The IMUs' names, without taking a handle.
  std::vector<std::string> imu_sensor_names() const;
  // What the handles taken so far read (sensor_uses: one entry per interface).
  const std::vector<SensorUse>& sensor_uses() const { return sensor_uses_; }

 private:
  const mechanism::MechanismModel& model_;
  mechanism::MechanismState& state_;
  HardwareAccess access_;
  std::vector<ResourceClaim> claims_;
  bool claims_base_ = false;
  std::function<std::string(int)> direct_owner_;
  const SensorHardware* sensors_ = nullptr;
  std::vector<SensorUse> sensor_uses_;
  void use_sensor(const char* interface, const std::string& name);
};

}  // namespace mechsim::control
