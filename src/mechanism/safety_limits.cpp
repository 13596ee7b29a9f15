#include "mechanism/safety_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mechanism/propagation.hpp"

namespace mechsim::mechanism {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// std::clamp with lo > hi is undefined; a bad description must not be.
double clamp_to(double v, double lo, double hi) { return std::min(std::max(v, lo), hi); }

bool has_position_limits(const JointInfo& joint) {
  return joint.limits && !joint.continuous &&
         (joint.type == description::JointType::Revolute || joint.type == description::JointType::Prismatic);
}

}  // namespace

EffortBounds effort_bounds(const JointInfo& joint, const JointState& state) {
  if (!joint.limits) return {-kInf, kInf};
  const double effort = std::abs(joint.limits->effort);
  if (!joint.safety) return {-effort, effort};

  const double vmax = std::abs(joint.limits->velocity);
  const description::SafetyController& s = *joint.safety;
  double v_high = vmax;
  double v_low = -vmax;
  if (has_position_limits(joint)) {
    v_high = clamp_to(-s.k_position * (state.position - s.soft_upper_limit), -vmax, vmax);
    v_low = clamp_to(-s.k_position * (state.position - s.soft_lower_limit), -vmax, vmax);
  }
  const double high = clamp_to(-s.k_velocity * (state.velocity - v_high), -effort, effort);
  const double low = clamp_to(-s.k_velocity * (state.velocity - v_low), -effort, effort);
  return {low, high};
}

double limit_position_command(const JointInfo& joint, double command, double reference, double period) {
  double q = command;
  if (joint.limits && joint.limits->velocity > 0.0 && period > 0.0 && std::isfinite(reference)) {
    const double step = joint.limits->velocity * period;
    q = clamp_to(q, reference - step, reference + step);
  }
  if (has_position_limits(joint)) {
    double lower = joint.limits->lower;
    double upper = joint.limits->upper;
    if (joint.safety) {
      lower = std::max(lower, joint.safety->soft_lower_limit);
      upper = std::min(upper, joint.safety->soft_upper_limit);
    }
    q = clamp_to(q, lower, upper);
  }
  return q;
}

double limit_velocity_command(const JointInfo& joint, double command) {
  if (!joint.limits || !(joint.limits->velocity > 0.0)) return command;
  return clamp_to(command, -joint.limits->velocity, joint.limits->velocity);
}

namespace {

// Replaces non-finite commands (effort and velocity by 0, position by `reference`); returns how many.
int replace_non_finite(JointState& state, double reference) {
  int rejected = 0;
  if (!std::isfinite(state.commanded_effort)) {
    state.commanded_effort = 0.0;
    ++rejected;
  }
  if (!std::isfinite(state.commanded_velocity)) {
    state.commanded_velocity = 0.0;
    ++rejected;
  }
  if (!std::isfinite(state.commanded_position)) {
    state.commanded_position = std::isfinite(reference) ? reference : 0.0;
    ++rejected;
  }
  return rejected;
}

}  // namespace

int enforce_joint_limits(const JointInfo& joint, JointState& state, double period) {
  const double reference = std::isfinite(state.last_position_command) ? state.last_position_command : state.position;
  const int rejected = replace_non_finite(state, reference);
  const EffortBounds b = effort_bounds(joint, state);
  // A ros2_control command interface's min/max bound its mode's command (inf for other joints).
  const auto mode = static_cast<std::size_t>(state.command_mode);
  const double low = joint.command_min[mode], high = joint.command_max[mode];
  if (state.command_mode == HardwareInterface::Effort) state.commanded_effort = clamp_to(state.commanded_effort, low, high);
  if (state.command_mode == HardwareInterface::Velocity) state.commanded_velocity = clamp_to(state.commanded_velocity, low, high);
  state.commanded_effort = clamp_to(state.commanded_effort, b.low, b.high);
  state.commanded_velocity = limit_velocity_command(joint, state.commanded_velocity);
  if (state.command_mode == HardwareInterface::Position) {
    state.commanded_position = clamp_to(limit_position_command(joint, state.commanded_position, reference, period), low, high);
    state.last_position_command = state.commanded_position;
  } else {
    state.last_position_command = std::numeric_limits<double>::quiet_NaN();
  }
  return rejected;
}

void enforce_safety_limits(const MechanismModel& model, MechanismState& state, double period) {
  for (std::size_t i = 0; i < model.joints.size(); ++i) {
    const JointInfo& joint = model.joints[i];
    // A model plugin's joint has no safety limits (Gazebo's plugins set joints directly), but a
    // NaN never reaches the physics.
    if (joint.role == JointRole::Direct) {
      state.rejected_commands += static_cast<std::uint64_t>(replace_non_finite(state.joints[i], state.joints[i].position));
      continue;
    }
    if (joint.role != JointRole::Actuated) continue;
    state.rejected_commands += static_cast<std::uint64_t>(enforce_joint_limits(joint, state.joints[i], period));
  }
}

void enforce_safety_limits(const MechanismModel& model, MechanismState& state) {
  enforce_safety_limits(model, state, kDefaultPeriod);
}

}  // namespace mechsim::mechanism
