#pragma once
// Ray casting for range sensors (Physics::cast_rays): rays against the world's ground (plane or
// height field) and boxes, and the robot's shapes, excluding the sensor's own body.
//
// Height fields are intersected exactly by mechsim (ray_hfield below), not by MuJoCo 2.2.2's
// mj_ray: that one tests each triangle with a tolerance-free inside test in a projected plane, so
// a ray lying exactly on a grid line (or a cell's diagonal) can fall between two triangles, miss
// them both and report the bottom of the terrain block instead (metres too far). Every other
// primitive goes through MuJoCo's own per-geom routine (mju_rayGeom); meshes through a
// bounding-volume hierarchy of their triangles (mesh_bvh.hpp: mj_rayMesh tests every triangle).

#include <memory>
#include <vector>

#include "physics/mesh_bvh.hpp"
#include "physics/physics_model.hpp"

namespace mechsim::physics {

// Which shapes of the robot rays hit: its collision shapes (Gazebo's `ray` sensors collide rays
// with collision geometry) or its visual shapes (what a renderer sees: `gpu_ray`). World shapes
// (ground, terrain, boxes) are hit either way.
enum class RayTargets { Collision, Visual };

// The shapes one sensor's rays may hit: built once per sensor (allocates), then used by every
// cast. MuJoCo geom ids, valid for the PhysicsModel it was made from.
struct RayFilter {
  std::vector<int> geoms;    // primitives: tested with mju_rayGeom
  std::vector<int> hfields;  // height-field geoms: tested with ray_hfield
  std::vector<int> meshes;   // mesh geoms, tested with mesh_bvhs[k] (shared by geoms of one mesh)
  std::vector<std::shared_ptr<const MeshBvh>> mesh_bvhs;
};

// Every shape of `targets` and of the world except the robot's shapes rigidly attached to
// `exclude_body` (the MuJoCo body of PhysicsModel::links(); -1 excludes none): that body and every
// body welded to it through fixed joints (MuJoCo's body_weldid), as Gazebo lumps the links of a
// fixed joint into one and its ray sensors ignore their own link's collisions. World shapes are
// never excluded.
RayFilter make_ray_filter(const PhysicsModel& model, int exclude_body, RayTargets targets);

// A height field as MuJoCo defines its surface, in the height field's own frame (origin at the
// centre of its footprint, z up): samples on a regular grid over [-half_x, half_x] x
// [-half_y, half_y], row r at y = -half_y + r * 2 half_y / (rows - 1), column c at
// x = -half_x + c * 2 half_x / (cols - 1), height data[r * cols + c] * top (data in [0, 1]).
// Each cell is two flat triangles split along the diagonal from (c, r) to (c + 1, r + 1), i.e.
// the surface is the piecewise-linear interpolation on that triangulation (not bilinear). Below
// the surface the field is solid down to z = -base (its sides are walls).
struct HfieldGrid {
  int rows = 0, cols = 0;
  double half_x = 0.0, half_y = 0.0;
  double top = 0.0;   // height of data 1 (m)
  double base = 0.0;  // depth of the solid block below z = 0 (m)
  const float* data = nullptr;
};

// Distance t >= 0 along the ray p + t v (frame of the grid, v need not be unit: t is in units of
// |v|) to where it first enters the solid, or -1 when it does not. A ray starting inside the
// solid returns 0. Exact to rounding: the ray is followed cell by cell (a 2-D digital
// differential analyser), and within a cell along each of the two triangles' pieces the height
// above the surface is linear in t, so its zero is found in closed form.
double ray_hfield(const HfieldGrid& grid, const double p[3], const double v[3]);

}  // namespace mechsim::physics
