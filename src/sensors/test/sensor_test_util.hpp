#pragma once
// Helpers of the sensors tests: a robot with sensors from inline URDF, and its physics.

#include <memory>
#include <string>

#include "description/robot_model.hpp"
#include "description/sensor_spec.hpp"
#include "physics/physics.hpp"
#include "physics/physics_model.hpp"

namespace mechsim::sensors::test {

// The sensor test robot: `base` (0.4 m cube, 10 kg) and, on a fixed joint 0.5 m above the base's
// centre, `head` (0.1 m cube, 1 kg, centre of mass 5 cm forward), plus `gazebo` (sensor blocks).
std::string robot_urdf(const std::string& gazebo);

description::RobotModel parse(const std::string& urdf);

// A world of the ground plane and a fixed box `wall` (0.2 x 4 x 1 m) with its near face at x = wall_x
// (none when wall_x <= 0); the robot spawned resting on the ground at the origin.
std::shared_ptr<const physics::PhysicsModel> build(const description::RobotModel& robot, double wall_x,
                                                   physics::BuildOptions options = {});

}  // namespace mechsim::sensors::test
