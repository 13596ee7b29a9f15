#pragma once
// The one place where mechsim states its contact parameters. Every collision geom of a robot
// and of the world gets these unless the description overrides them (gazebo <mu1>/<mu2>).
//
// Why these values: Gazebo's ODE surface default is mu = 1 (mechsim follows it so a URDF
// without <mu1> behaves as in Gazebo); torsional and rolling friction and the soft-contact
// parameters are MuJoCo's own defaults, which are stable at 1 ms steps.
//
// Two surfaces' friction, as Gazebo's ODE combines it (gazebo/physics/ode/ODEPhysics.cc,
// ODEPhysics::Collide): the contact's mu is the smaller of the two surfaces' mu, its mu2 the
// smaller of their mu2 (mu along fdir1, mu2 across it; ODE's friction pyramid). mechsim writes
// every collision geom with one sliding coefficient (isotropic_friction) and ranks the geoms'
// MuJoCo priorities by it, lowest friction highest (mjcf_writer.cpp): MuJoCo takes the
// parameters of the geom with the higher priority, so each contact gets the smaller coefficient
// of its two geoms, on either side, whatever kind of geom each is (robot link, world object,
// ground).

#include <array>
#include <optional>

namespace mechsim::physics {

struct ContactDefaults {
  // Sliding friction coefficient (dimensionless) used when a link has no gazebo mu1/mu2.
  double sliding_friction = 1.0;
  // Torsional (m) and rolling (m) friction coefficients, MuJoCo's friction[1], friction[2].
  double torsional_friction = 0.005;
  double rolling_friction = 0.0001;
  // MuJoCo solref: (time constant s, damping ratio). time constant >= 2 timesteps.
  std::array<double, 2> solref{0.02, 1.0};
  // MuJoCo solimp: (dmin, dmax, width m, midpoint, power).
  std::array<double, 5> solimp{0.9, 0.95, 0.001, 0.5, 2.0};
  // Distance (m) at which contacts become active; 0 = only on penetration.
  double margin = 0.0;
  // Contact dimensionality: 3 = normal + 2D sliding friction.
  int condim = 3;
  // Elliptic friction cones. MuJoCo's pyramidal cone regularises the normal direction in
  // proportion to mu^2, so Gazebo-style "no slip" coefficients (the PR2 wheels' mu = 100) make
  // contacts sink centimetres; the elliptic cone keeps the normal stiff at any mu.
  bool elliptic_cone = true;
  // Narrow wheels (PlannedGeom::narrow_wheel) touch the ground at one point: they are given to
  // MuJoCo as an ellipsoid with the cylinder's radius in the wheel plane and its half length
  // across, which rolls on exactly the same circle. MuJoCo's cylinder-on-plane contact has two
  // stiff points at the rim's edges, each with the full friction; with the PR2's mu = 100
  // (its Gazebo tags) their scrub torque, about 100 N x 2 cm per wheel, held the casters
  // against their 6.5 N m motors and the base could not turn in place. A tyre's narrow,
  // compliant patch has no such torque, so neither has the point contact. Wide wheels (the
  // CC8's) stay cylinders.
  bool point_contact_wheels = true;
  // Joint limits use the same soft-constraint model; stiffer than contacts so a limit stop
  // behaves like Gazebo ODE's hard stop (time constant >= 2 timesteps at 1 kHz).
  std::array<double, 2> limit_solref{0.005, 1.0};
  // Sliding friction of height-field terrain (mechsim's own worlds: mars_yard_2024, slope,
  // heightmap files), SDF's surface default. The ground plane's is WorldSpec::ground_mu/mu2.
  double ground_friction = 1.0;
};

// Gazebo's surface default for a coefficient a description leaves out (SDF <mu>, <mu2>; URDF
// <mu1>, <mu2>).
inline constexpr double kGazeboDefaultMu = 1.0;

// The one sliding coefficient of a geom whose surface has mu1 along fdir1 and mu2 across it:
// MuJoCo 2.2.2's geoms have one (its contact frame's tangents are chosen by its collision code,
// so no direction can be given), so an anisotropic surface is approximated by the mean of the
// two. A coefficient left out is Gazebo's default, 1.
inline double isotropic_friction(std::optional<double> mu1, std::optional<double> mu2) {
  return 0.5 * (mu1.value_or(kGazeboDefaultMu) + mu2.value_or(kGazeboDefaultMu));
}

}  // namespace mechsim::physics
