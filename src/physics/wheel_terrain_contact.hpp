#pragma once
// Private to src/physics: mechsim's own contact between a wheel (a MuJoCo cylinder whose axis is
// not near vertical) and a height field, installed in MuJoCo 2.2.2's collision table
// (mjCOLLISIONFUNC[hfield][cylinder]) by PhysicsModel::build.
//
// Why: MuJoCo 2.2.2 collides a convex geom with a height field prism by prism (two triangular
// prisms per cell, each by libccd's MPR) and returns one contact per prism it touches. A CC8 wheel
// (r 9 cm, 12 cm wide) on the Mars Yard's 5 cm grid overlaps ~24 prisms: up to 86 contacts for
// six wheels, MPR was a third of the step and the constraint solver most of the rest, and a
// contact near a prism's side got a normal up to 4-5 degrees off the surface's.
//
// What instead: the wheel's tread is three circles (its two rims and its middle plane); each
// circle's deepest points below the surface are found along its lower arc (80 degrees either
// side of straight down, every 20 degrees, then refined), and each local maximum of the
// penetration becomes one contact (at most two per circle: a wheel in a groove or against a
// step touches twice). A rim on a triangle's face gets the exact face contact: the circle's
// point deepest along the face's normal, with that normal (a rim edge on a side slope); a rim
// across a triangle edge (a ridge, a rock's corner) and the tread's middle get the wheel's own,
// radial normal, as MuJoCo gives a cylinder's round wall (mjc_fixNormal). The middle circle's
// contacts count only where the surface bulges between the rims (a rock narrower than the
// tread). A wheel on a plane gets two contacts, as on MuJoCo's ground plane; at most six.
// Cylinders whose axis is within 45 degrees of the height field's z (a wheel on its side, a post
// standing up) keep MuJoCo's own routine.
//
// Every other convex geom (box, sphere, capsule, ellipsoid, mesh) keeps MuJoCo's routine behind a
// cheap test: MuJoCo 2.2.2 walks every prism under the geom's bounding box, touching or not (the
// CC8's 0.75 x 0.55 m chassis box, 20 cm above the ground: 330 prisms a step for no contact);
// a geom whose box is above every height sample under it cannot touch and is skipped.

#include "physics/hfield_surface.hpp"

namespace mechsim::physics::detail {

// Cylinders whose axis is closer than this (cosine) to the height field's z rest on a flat end:
// MuJoCo's routine handles faces (three or more contacts), the rim method does not.
inline constexpr double kWheelMaxAxisZ = 0.7071;

// A point where a circle dips below a height field's surface (the height field's frame, m).
struct RimContact {
  double point[3] = {0, 0, 0};   // the circle's deepest point
  double normal[3] = {0, 0, 1};  // surface normal there, out of the solid
  double depth = 0.0;            // penetration along the normal (m), > 0 when overlapping
  double gap = 0.0;              // the same, measured vertically (m)
};

// The contacts of the circle (centre c, unit axis a, radius r; height-field frame) with the
// surface: local maxima of penetration deeper than -margin, deepest first, at most 2. A rim
// (`tread` false) touching a triangle's face gets the face's normal (a rim edge on a side slope);
// anything else, and every contact of the tread's middle (`tread` true), the wheel's radial normal,
// the surface normal of a cylinder's tread. Returns how many were written to `out`.
// Allocation-free.
int rim_contacts(const HfieldSurface& surface, const double c[3], const double a[3], double r, double margin,
                 bool tread, RimContact out[2]);

// Replaces MuJoCo's height field-cylinder collision with mechsim's, puts the cheap test in front
// of its height field routines for other shapes, and moves a soil wheel's contacts with the
// ground (height field or plane, whatever the wheel's shape: a cylinder, a narrow wheel's
// ellipsoid, a link the world made a wheel) down to its bedrock (the geom's user number, written by
// Physics::set_soil; 0 for every other geom). Once per process; every later call does nothing.
// MuJoCo's table is process-global: the entry written is a pure function of the model and data it
// is given, the same for every simulation, so instances still share nothing mutable.
void install_wheel_terrain_contact();

}  // namespace mechsim::physics::detail
