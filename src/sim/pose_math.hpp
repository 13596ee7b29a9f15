#pragma once
// Angles of a unit quaternion (w, x, y, z) as the runner, reports and tests need them.

#include <algorithm>
#include <cmath>

#include "description/robot_model.hpp"

namespace mechsim::sim {

// ZYX (yaw-pitch-roll) Euler angles, rad.
inline double yaw_of(const description::Quat& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}
inline double pitch_of(const description::Quat& q) {
  return std::asin(std::clamp(2.0 * (q.w * q.y - q.z * q.x), -1.0, 1.0));
}
inline double roll_of(const description::Quat& q) {
  return std::atan2(2.0 * (q.w * q.x + q.y * q.z), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
}
// Angle between the body's z axis and the world's (rad).
inline double tilt_of(const description::Quat& q) {
  return std::acos(std::clamp(1.0 - 2.0 * (q.x * q.x + q.y * q.y), -1.0, 1.0));
}

}  // namespace mechsim::sim
