#pragma once
// Position errors as ros_control's position controllers compute them (the `angles` package's
// definitions): continuous joints wrap, limited joints do not.

#include <cmath>
#include <numbers>

#include "mechanism/mechanism_model.hpp"

namespace mechsim::control {

// Maps an angle to (-pi, pi].
inline double normalize_angle(double angle) noexcept {
  const double two_pi = 2.0 * std::numbers::pi;
  double a = std::fmod(angle + std::numbers::pi, two_pi);
  if (a <= 0.0) a += two_pi;
  return a - std::numbers::pi;
}

// The signed angle from `from` to `to` the short way round (rad, in (-pi, pi]).
inline double shortest_angular_distance(double from, double to) noexcept { return normalize_angle(to - from); }

// Clamps a position command into the joint's limits, as ros_control's enforceJointLimits does
// for revolute and prismatic joints (continuous joints have none).
inline double enforce_position_limits(const mechanism::JointInfo& joint, double command) noexcept {
  if (joint.continuous || !joint.limits) return command;
  if (joint.type != description::JointType::Revolute && joint.type != description::JointType::Prismatic) return command;
  if (joint.limits->lower > joint.limits->upper) return command;
  return std::fmin(std::fmax(command, joint.limits->lower), joint.limits->upper);
}

// Position error (set point - position) of a joint: the shortest angular distance on a
// continuous joint; the plain difference on a prismatic joint and on a limited revolute joint.
// For a revolute joint whose command was clamped into its limits, angles'
// shortest_angular_distance_with_limits picks the way round that stays within the limits,
// which for a range below 2 pi is exactly the plain difference of the unwrapped positions.
inline double position_error(const mechanism::JointInfo& joint, double position, double set_point) noexcept {
  if (joint.continuous || joint.type == description::JointType::Continuous) {
    return shortest_angular_distance(position, set_point);
  }
  return set_point - position;
}

}  // namespace mechsim::control
