// Simulation: the tick's exchange between the mechanism and the physics (simulation.hpp, the
// tick's steps 1 and 4): joint states read from the physics and propagated to the actuators, the
// PR2 gripper gaps computed from the fingers, and the controllers' commands (under the e-stop, the
// held ones; through pid_gains PIDs where given) written to the physics.
#include <cmath>

#include "mechanism/propagation.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

using mechanism::HardwareInterface;

physics::JointMode to_physics_mode(HardwareInterface iface) {
  switch (iface) {
    case HardwareInterface::Position: return physics::JointMode::Position;
    case HardwareInterface::Velocity: return physics::JointMode::Velocity;
    case HardwareInterface::Effort: break;
  }
  return physics::JointMode::Effort;
}

}  // namespace

void Simulation::read_physics() {
  mechanism::MechanismState& state = *mechanism_state_;
  if (state.base.floating) {
    physics::Twist V_WB;
    state.base.floating = root_link_ ? physics_->free_link_state(*root_link_, state.base.X_WB, V_WB)
                                     : physics_->root_state(state.base.X_WB, V_WB);
    state.base.linear = V_WB.linear;
    state.base.angular = V_WB.angular;
  }
  for (std::size_t j = 0; j < physics_joint_.size(); ++j) {
    const int p = physics_joint_[j];
    if (p < 0) continue;
    const auto pj = static_cast<std::size_t>(p);
    mechanism::JointState& js = state.joints[j];
    js.position = physics_->position(pj);
    js.velocity = physics_->velocity(pj);
    js.measured_effort = physics_->actuator_effort(pj);
  }
  read_gaps_from_fingers();
  mechanism::propagate_joint_to_actuator_position(*mechanism_, state);
}

void Simulation::read_gaps_from_fingers() {
  // Gap x = 2 t, t = t0 + r (sin(theta0 + q) - sin theta0) for the finger angle q (the
  // transmission's linkage); dx/dq = 2 r cos(theta0 + q) turns rates and torques. q is the mean
  // angle of the driven finger joints (collocated with the drive, so that the loop stays
  // passive while the soft mimic constraints flex); the torque is every finger's.
  mechanism::MechanismState& state = *mechanism_state_;
  for (const GapFromFingers& g : gap_from_fingers_) {
    double q = 0.0, rate = 0.0, torque = 0.0;
    for (const int k : g.measured) {
      const mechanism::JointState& f = state.joints[static_cast<std::size_t>(k)];
      q += f.position;
      rate += f.velocity;
    }
    for (const int k : g.fingers) torque += state.joints[static_cast<std::size_t>(k)].measured_effort;
    const double n = static_cast<double>(g.measured.size());
    q /= n;
    rate /= n;
    const double dx_dq = 2.0 * g.r * std::cos(g.theta0 + q);
    mechanism::JointState& gap = state.joints[static_cast<std::size_t>(g.gap)];
    gap.position = 2.0 * (g.t0 + g.r * (std::sin(g.theta0 + q) - std::sin(g.theta0)));
    gap.velocity = dx_dq * rate;
    gap.measured_effort = std::abs(dx_dq) > 1e-9 ? torque / dx_dq : 0.0;
  }
}

void Simulation::write_physics() {
  mechanism::MechanismState& state = *mechanism_state_;
  mechanism::propagate_actuator_to_joint_effort(*mechanism_, state);
  for (std::size_t j = 0; j < physics_joint_.size(); ++j) {
    const int p = physics_joint_[j];
    // Passive joints (PR2 fingers) follow their transmission's actuated joint, and simulated
    // ones (PR2 screws) carry torques meant for a backend that models the screw: only actuated
    // joints take commands.
    if (p < 0 || !commanded_[j]) continue;
    const auto pj = static_cast<std::size_t>(p);
    mechanism::JointState js = state.joints[j];
    if (e_stop_) {
      // DefaultRobotHWSim::writeSim under e-stop: no effort, no velocity, positions held.
      js.commanded_effort = 0.0;
      js.commanded_velocity = 0.0;
      js.commanded_position = e_stop_position_[j];
    }
    if (js.effort_limit != physics_effort_limit_[j]) {
      physics_->set_effort_limit(pj, js.effort_limit);
      physics_effort_limit_[j] = js.effort_limit;
    }
    // gazebo_ros_control's pid_gains turn a position/velocity command into an effort here.
    const bool pid = js.command_mode != HardwareInterface::Effort && pid_drive_.active(j);
    const HardwareInterface mode = pid ? HardwareInterface::Effort : js.command_mode;
    if (mode != physics_mode_[j]) {
      physics_->set_mode(pj, to_physics_mode(mode), servo_gains_[j]);
      physics_mode_[j] = mode;
    }
    if (pid) {
      physics_->set_effort(pj, pid_drive_.effort(j, mechanism_->joints[j], js, options_.period));
      continue;
    }
    switch (mode) {
      case HardwareInterface::Effort: physics_->set_effort(pj, effort_scale_[j] * js.commanded_effort); break;
      case HardwareInterface::Position: physics_->set_position_command(pj, js.commanded_position); break;
      case HardwareInterface::Velocity: physics_->set_velocity_command(pj, js.commanded_velocity); break;
    }
  }
  if (state.base_command.active) {
    const mechanism::BaseVelocityCommand& c = state.base_command;
    const physics::Twist V{{c.vx, c.vy, 0.0}, {0.0, 0.0, c.wz}};
    if (root_link_) {
      physics_->command_free_link_velocity(*root_link_, V);
    } else {
      physics_->command_root_velocity(V);
    }
  }
}

}  // namespace mechsim::sim
