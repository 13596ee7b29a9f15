#pragma once
// Which of a robot's controllers to run when nobody says: `mechsim bench` without --start.

#include <string>
#include <vector>

#include "control/controller_manager.hpp"

namespace mechsim::sim {

// A conflict-free set from the loaded controllers `loaded` (in their YAML order), widest first:
// the controllers claiming the most joints (a drive, an arm's trajectory controller) are taken
// first, then each that claims no joint already taken (YAML order among equals); controllers
// that claim nothing (joint_state_controller, odometry) are always in. The result keeps
// `loaded`'s order. For mechsim's CC8 this is joint_state_controller and rover_drive_controller
// (what its scenarios and launch files start; not the ten per-joint controllers), for its PR2
// the nine of pr2_gazebo's default set (not the per-joint position controllers).
std::vector<std::string> widest_conflict_free(const std::vector<control::ControllerInfo>& loaded);

}  // namespace mechsim::sim
