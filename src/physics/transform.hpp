#pragma once
// Small rigid-transform helpers on description::Pose (X_AB: pose of frame B in frame A).
// Quaternions are unit (w, x, y, z); angles in radians; lengths in metres.

#include <cmath>

#include "description/robot_model.hpp"

namespace mechsim::physics {

using description::Pose;
using description::Quat;
using description::Vec3;

inline Quat quat_multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

inline Quat quat_conjugate(const Quat& q) { return {q.w, -q.x, -q.y, -q.z}; }

inline Quat quat_normalized(const Quat& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (n <= 0.0) return {};
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// v expressed in the frame that q rotates into: R(q) v.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
  const Quat p{0.0, v.x, v.y, v.z};
  const Quat r = quat_multiply(quat_multiply(q, p), quat_conjugate(q));
  return {r.x, r.y, r.z};
}

// X_AC = X_AB * X_BC.
inline Pose compose(const Pose& X_AB, const Pose& X_BC) {
  const Vec3 p = rotate(X_AB.orientation, X_BC.position);
  return {{X_AB.position.x + p.x, X_AB.position.y + p.y, X_AB.position.z + p.z},
          quat_normalized(quat_multiply(X_AB.orientation, X_BC.orientation))};
}

// X_BA from X_AB.
inline Pose inverse(const Pose& X_AB) {
  const Quat qi = quat_conjugate(X_AB.orientation);
  const Vec3 p = rotate(qi, X_AB.position);
  return {{-p.x, -p.y, -p.z}, qi};
}

// Fixed-axis roll (x), pitch (y), yaw (z) as URDF uses them: R = Rz(yaw) Ry(pitch) Rx(roll).
inline Quat quat_from_rpy(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2);
  const double cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
          cr * cp * sy - sr * sp * cy};
}

}  // namespace mechsim::physics
