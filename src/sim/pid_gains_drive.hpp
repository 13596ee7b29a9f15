#pragma once
// gazebo_ros_control's pid_gains: DefaultRobotHWSim drives a joint commanded through a position
// or velocity interface with a PID to effort when the parameter server holds gains for it at
// <pid_gains_path>/{p, i, d, i_clamp, ...} (description/ros_control_plugin.hpp says which path), and
// with Gazebo's own position/velocity setting otherwise (mechsim: its implicit servo, DESIGN.md).
// With gains, each physics step (gazebo_ros_control's writeSim):
//   position: error = set point - position (shortest way round on a continuous joint)
//   velocity: error = commanded velocity - velocity
//   effort   = clamp(pid(error, dt), -effort limit, +effort limit)   (N m or N; URDF <limit effort>,
//              unbounded when the joint has none), applied as an effort
// The PID is control_toolbox's (control/pid.hpp), its derivative the difference of errors over dt
// as DefaultRobotHWSim calls it. mechsim resets it when the joint's command mode changes (Gazebo
// fixes one mode per joint at load).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "control/pid.hpp"
#include "description/ros_control_plugin.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::sim {

class PidGainsDrive {
 public:
  PidGainsDrive() = default;
  // Looks up gains for every actuated joint of `model` with a position or velocity interface.
  // `plugin`: the description's gazebo_ros_control plugin (none: legacy paths, as its default);
  // `root`: the parameter tree's root (the absolute paths are looked up in it). Throws
  // control::ParamsError naming the path for mistyped gains.
  PidGainsDrive(const mechanism::MechanismModel& model, const std::optional<description::RosControlPlugin>& plugin,
                const control::Params& root);

  // Whether mechanism joint `joint` is driven through a PID.
  bool active(std::size_t joint) const { return joint < pids_.size() && pids_[joint].has_value(); }
  // Real-time (no allocation, no throw): the effort for the joint's position or velocity command.
  double effort(std::size_t joint, const mechanism::JointInfo& info, const mechanism::JointState& state,
                double dt) noexcept;
  void reset() noexcept;

  // One line per joint with a position or velocity interface: which drive it gets and why.
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  std::vector<std::optional<control::Pid>> pids_;       // per mechanism joint
  std::vector<double> effort_limit_;                    // N m or N; infinity when none
  std::vector<mechanism::HardwareInterface> last_mode_;  // the mode the PID last ran in
  std::vector<std::string> notes_;
};

}  // namespace mechsim::sim
