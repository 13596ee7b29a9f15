#pragma once
// The mimic joint plugins, libroboticsgroup_gazebo_mimic_joint_plugin.so and
// libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so, as a model plugin controller: the
// follower <mimicJoint> tracks multiplier * position(<joint>) + offset.
//   - Without hasPID the plugin sets the follower's position every step. mechsim's physics
//     realises that as a joint equality constraint, like a URDF <mimic> (physics/body_plan.cpp,
//     description/mimic_plugin.hpp): the controller claims the follower, so that nothing else
//     drives it, and reports the tracking on "state"; maxEffort and sensitiveness do not bound a
//     constraint.
//   - With hasPID the follower gets effort = clamp(PID(target - position), +-maxEffort) every
//     tick while |target - position| >= sensitiveness (else no effort that tick), the PID's
//     gains read from the parameter server: <hasPID>'s text as a namespace (upatras), else
//     gazebo_ros_control/pid_gains/<mimicJoint> (p, i, d, i_clamp, ...; relative to the robot
//     namespace).
// A follower that a mimic plugin drives gets no constraint from its URDF <mimic> tag (Gazebo
// ignores the tag; the plugin is what moves it there).
//
// Elements: joint, mimicJoint (required); multiplier 1, offset 0 (rad or m), sensitiveness 0
// (>= 0), maxEffort (> 0; default 1.0 for roboticsgroup's, the follower's URDF effort limit for
// upatras'), hasPID (roboticsgroup: a boolean, <hasPID/> true; upatras: present or not),
// robotNamespace.
// Ports: "state" StatePort<JointControllerState>: set point = the target, process value = the
// follower's position, error, command = the effort (0 without PID).

#include "control/pid.hpp"
#include "control/ports.hpp"
#include "controllers/plugins/model_plugin.hpp"

namespace mechsim::control {

class MimicJointPlugin : public ModelPlugin {
 public:
  MimicJointPlugin(PluginContext context, bool upatras) : context_(std::move(context)), upatras_(upatras) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&state_}; }

  static std::vector<std::string> joints(const Params& params);
  bool has_pid() const { return has_pid_; }
  double max_effort() const { return max_effort_; }

 private:
  PluginContext context_;
  bool upatras_ = false;
  bool has_pid_ = false;
  double multiplier_ = 1.0, offset_ = 0.0, sensitiveness_ = 0.0, max_effort_ = 1.0;
  JointStateHandle leader_;
  JointHandle follower_;
  Pid pid_;
  StatePort<JointControllerState> state_{"state"};
};

}  // namespace mechsim::control
