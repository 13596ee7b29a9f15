#pragma once
// Helpers shared by the physics tests: inline URDF models and a parse shortcut.

#include <memory>
#include <string>

#include "description/robot_model.hpp"
#include "physics/physics.hpp"
#include "physics/physics_model.hpp"

namespace mechsim::physics::test {

// Parses an inline URDF (strict validation); packages map "cc8_description" and
// "pr2_description" into MECHSIM_SHARED_DIR/robots.
description::RobotModel parse(const std::string& urdf);
description::RobotModel parse_file(const std::string& path);

std::shared_ptr<const PhysicsModel> build(const std::string& urdf, const BuildOptions& options = {});

// A point-mass-like pendulum hanging from the world: a revolute joint "hinge" about y at
// height 2 m, a link whose mass `mass` sits `length` m below the joint with tiny inertia
// `inertia` about its centre of mass.
std::string pendulum_urdf(double length, double mass, double inertia, const std::string& joint_extra = "",
                          const std::string& joint_type = "continuous");

// A free-floating 1 kg box of edge 0.1 m.
std::string box_urdf();

// Two uniform rods (length 1 m, mass 1 kg), joints "j1", "j2" about y, fixed to the world.
std::string double_pendulum_urdf();

bool shared_dir_present();
std::string shared_dir();

}  // namespace mechsim::physics::test
