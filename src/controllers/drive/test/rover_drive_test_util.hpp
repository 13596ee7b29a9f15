#pragma once
// Test fixtures of the rover drive tests: a hand-sized rover (steered corners at (+-0.5,
// +-0.4) m, fixed middle wheels at (0, +-0.45) m, wheel radius 0.1 m, the CC8's axis signs)
// as kinematics and as YAML parameters, and a mechanism with its ten joints.

#include <memory>
#include <string>

#include "controllers/drive/rover_drive_kinematics.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control::testing {

// Steering order FL, FR, RL, RR; wheel order FL, FR, ML, MR, RL, RR (as the CC8 YAML lists
// them). `offset` (m) puts each steered tyre that far outboard of its steering axis.
RoverKinematics make_test_rover(double offset = 0.0);

// The controller's parameters for the same rover, as YAML under "rover:" (a controller map),
// with `extra` appended inside the controller (indented by four spaces, one key per line).
std::string test_rover_yaml(const std::string& extra = "", double offset = 0.0);

// The ten continuous joints steering_FL..RR, wheel_joint_FL..RR (velocity limits 3 and 20).
std::unique_ptr<TestRobot> make_rover_robot();

}  // namespace mechsim::control::testing
