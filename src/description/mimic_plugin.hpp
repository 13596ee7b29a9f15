#pragma once
// The mimic joint plugins (roboticsgroup_gazebo_plugins' and roboticsgroup_upatras_gazebo_plugins'
// libroboticsgroup[_upatras]_gazebo_mimic_joint_plugin.so) as the physics needs to see them: which
// joint follows which, and whether the plugin sets the follower's position (a constraint for
// mechsim's physics, as a URDF <mimic>) or drives it with a PID (an effort the controller of
// controllers/plugins/mimic_joint_plugin.hpp computes). Lenient: the controller reports bad
// elements with their lines; this reader only needs to not misread good ones.

#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

bool is_mimic_joint_plugin(const std::string& filename);
bool is_upatras_mimic_joint_plugin(const std::string& filename);

struct MimicPluginSpec {
  std::string joint;        // the joint mimicked (the leader)
  std::string mimic_joint;  // the follower
  double multiplier = 1.0;
  double offset = 0.0;  // follower = multiplier * leader + offset (rad or m)
  bool has_pid = false;
};

// Null for another plugin, or one whose joint, mimicJoint, multiplier or offset cannot be read.
std::optional<MimicPluginSpec> read_mimic_plugin(const GazeboPlugin& plugin);

// Every readable mimic plugin of `robot` (document order).
std::vector<MimicPluginSpec> mimic_plugins(const RobotModel& robot);

}  // namespace mechsim::description
