#pragma once
// The robot as a controller sees it: joint handles over the mechanism state, looked up by
// name during init() and recorded as resource claims (ros_control's hardware interfaces and
// ClaimResources). Handles are real-time safe: plain pointer reads and writes.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

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

 private:
  const mechanism::JointInfo* info_ = nullptr;
  mechanism::JointState* state_ = nullptr;
  HardwareInterface iface_ = HardwareInterface::Effort;
};

struct ResourceClaim {
  HardwareInterface interface = HardwareInterface::Effort;
  std::vector<std::string> joints;  // in claim order, no duplicates
};

// One controller's view of the robot during init(). Not thread-safe; configuration time only.
class RobotHardware {
 public:
  RobotHardware(const mechanism::MechanismModel& model, mechanism::MechanismState& state);

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

 private:
  const mechanism::MechanismModel& model_;
  mechanism::MechanismState& state_;
  std::vector<ResourceClaim> claims_;
};

}  // namespace mechsim::control
