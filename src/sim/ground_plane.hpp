#pragma once
// The local ground plane under a robot's footprint, for spawning on slopes: a least-squares plane
// through a height field's surface over a rectangle, and the roll and pitch that put a body's z
// axis on the plane's normal while keeping its heading.

#include "physics/heightmap.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::sim {

// z = z0 + gx (x - x0) + gy (y - y0) (m; gradients dimensionless).
struct GroundPlane {
  double x0 = 0.0, y0 = 0.0, z0 = 0.0;
  double gx = 0.0, gy = 0.0;
  double slope() const;  // rad, 0 = level
};

// The plane fitted (least squares) to the bilinear surface of `map` sampled over `footprint`
// (at the grid's spacing, at most 64 samples a side), evaluated at (x0, y0).
GroundPlane fit_ground_plane(const physics::Heightmap& map, const physics::Region& footprint, double x0, double y0);

// Roll and pitch (rad, URDF fixed-axis convention, R = Rz(yaw) Ry(pitch) Rx(roll)) whose body z
// axis is the plane's upward normal, for a body heading `yaw` (its x axis, projected on the
// horizontal, points along yaw).
struct RollPitch {
  double roll = 0.0, pitch = 0.0;
};
RollPitch roll_pitch_on(const GroundPlane& plane, double yaw);

}  // namespace mechsim::sim
