#pragma once
// Test fixtures of the PR2 base tests: the PR2's base geometry (casters at (+-0.2246, +-0.2246)
// m, wheels 0.049 m either side of each pivot, radius 0.074792 m, every axis sign +1, as in
// pr2_description's base_v0) as kinematics and as YAML, and a mechanism with its 12 joints.

#include <memory>
#include <string>

#include "controllers/drive/pr2_base_kinematics.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control::testing {

inline constexpr double kPr2CasterXY = 0.2246;     // m
inline constexpr double kPr2WheelOffset = 0.049;   // m
inline constexpr double kPr2WheelRadius = 0.074792;  // m

// Caster order fl, fr, bl, br; wheels l then r of each caster.
Pr2BaseKinematics make_pr2_base();

// The geometry parameters of the same base, one key per line, indented by `indent` spaces.
std::string pr2_base_geometry_yaml(int indent);

// A controller map "base:" with a Pr2BaseController2 named base_controller and a Pr2Odometry
// named odometry, `extra` appended inside base_controller (indented by four spaces).
std::string pr2_base_yaml(const std::string& extra = "");

// The 12 continuous joints: *_caster_rotation_joint, *_caster_{l,r}_wheel_joint.
std::unique_ptr<TestRobot> make_pr2_base_robot();

}  // namespace mechsim::control::testing
