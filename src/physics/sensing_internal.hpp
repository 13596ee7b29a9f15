#pragma once
// Private to src/physics/*.cpp: what Physics' sensing queries (ray casts, accelerations, joint
// wrenches) compute on MuJoCo's model and data. ray_cast.cpp and sensing.cpp implement them;
// physics.cpp forwards to them with its own mjModel/mjData.

#include <cstddef>

#include "physics/mujoco_internal.hpp"
#include "physics/physics.hpp"
#include "physics/ray_cast.hpp"

namespace mechsim::physics::detail {

// The height field of geom `geom` as a grid (ray_cast.hpp), and a world-frame ray against it.
HfieldGrid hfield_grid(const mjModel* m, int geom);
double ray_hfield_geom(const mjModel* m, const mjData* d, int geom, const mjtNum pnt[3], const mjtNum vec[3]);

// Physics::cast_rays on fresh kinematics.
void cast_rays(const mjModel* m, const mjData* d, const RayFilter& filter, const description::Vec3& origin,
               const description::Vec3* directions, std::size_t count, double near, double far, double* ranges,
               int* hit_geoms = nullptr);

// Physics::link_acceleration and joint_wrench: run MuJoCo's post-constraint RNE on fresh
// kinematics (it fills cacc, cfrc_int and cfrc_ext), then read body `body` at world point p.
Acceleration point_acceleration(const mjModel* m, mjData* d, int body, const description::Vec3& p_W);
Wrench wrench_from_parent(const mjModel* m, mjData* d, int body, const description::Vec3& p_W);

}  // namespace mechsim::physics::detail
