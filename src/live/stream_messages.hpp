#pragma once
// The JSON payloads of the live channels and their JSON Schemas. Field names follow the
// schemas Foxglove Studio and Lichtblick visualise by name:
//   /tf                 foxglove.FrameTransforms: world -> root link, then parent -> child link
//                       for every streamed link, from the physics' link poses (what the
//                       simulation really did, passive joints and a floating base included)
//   /joint_states       sensor_msgs/JointState (header, name, position, velocity, effort)
//   /odom               nav_msgs/Odometry (pose only; covariances zero)
//   /scan/<name>        foxglove.LaserScan in the laser's link frame (non-finite ranges: null)
//   /robot_description  std_msgs/String: the expanded URDF
//   /markers            foxglove.SceneUpdate: the scenario's waypoints as spheres joined by a line
// Every payload carries simulation time; `out` is cleared and reused by the caller.

#include <string>

#include "live/snapshot.hpp"

namespace mechsim::live {

void encode_frame_transforms(const StreamLayout& layout, const Snapshot& s, std::string& out);
void encode_joint_states(const StreamLayout& layout, const Snapshot& s, std::string& out);
void encode_odometry(const StreamLayout& layout, const Snapshot& s, std::string& out);
void encode_laser_scan(const StreamLayout& layout, std::size_t laser, const Snapshot& s, std::string& out);
std::string encode_robot_description(const std::string& urdf);
std::string encode_waypoint_markers(const StreamLayout& layout, double time);

// JSON Schemas of the channels.
const std::string& frame_transforms_schema();
const std::string& joint_state_schema();
const std::string& odometry_schema();
const std::string& laser_scan_schema();
const std::string& string_schema();
const std::string& scene_update_schema();

}  // namespace mechsim::live
