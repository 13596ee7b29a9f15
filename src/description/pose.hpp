#pragma once
// Positions, orientations and poses as the description writes them (plain data).

namespace mechsim::description {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

// Unit quaternion (w, x, y, z).
struct Quat {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

// X_PC: pose of a child frame C in its parent frame P (metres, unit quaternion).
struct Pose {
  Vec3 position;
  Quat orientation;
};

}  // namespace mechsim::description
