#pragma once
// What the live stream shows of a running simulation, in two parts:
//   StreamLayout  built once when the stream is attached (names, frames, which physics link or
//                 joint each entry reads, the expanded URDF, scenario markers): immutable;
//   Snapshot      the state at one instant, copied by the tick into presized buffers
//                 (capture_snapshot: no allocation, no lock), handed to the streaming thread
//                 through a TripleBuffer.
// Units: m, rad, s, N, N m. Poses are X_WL (link L in the world frame W).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::sim {
class Simulation;
}  // namespace mechsim::sim

namespace mechsim::control {
template <class T>
class StatePort;
struct OdometrySnapshot;
}  // namespace mechsim::control

namespace mechsim::live {

// One laser of the robot, streamed as a foxglove.LaserScan in its link's frame.
struct LaserLayout {
  std::string name;       // the sensor's name
  std::string topic;      // channel topic: /scan/<name>
  std::string link;       // frame_id: the link the sensor is attached to
  description::Pose X_LS; // the sensor in that link's frame
  std::size_t sensor = 0; // index into the simulation's SensorSet
  double angle_min = 0.0, angle_max = 0.0;  // rad, about the sensor's z
  std::size_t rays = 0;   // horizontal rays of one scan (the first row of a multi-row scan)
};

struct StreamLayout {
  std::string world_frame = "world";
  // Links with a pose in the physics; links[0] is the root. parent[i] is the index of link i's
  // parent link in `links` (npos for the root: its parent frame is world_frame).
  std::vector<std::string> links;
  std::vector<std::size_t> physics_link;
  std::vector<std::size_t> parent;
  // Joint states: the mechanism's joints, then the physics joints no transmission drives (the
  // CC8's rocker and bogies). Effort is measured effort for mechanism joints, 0 for the others.
  std::vector<std::string> joints;
  std::size_t mechanism_joints = 0;
  std::vector<std::size_t> physics_joint;  // for joints[mechanism_joints + k]
  // The robot's odometry (a drive controller's port), when it has one; read in the tick.
  const control::StatePort<control::OdometrySnapshot>* odometry = nullptr;
  std::string odom_frame = "odom", odom_child_frame = "base_link";
  std::vector<LaserLayout> lasers;
  std::string robot_description;  // the expanded URDF (empty: no /robot_description channel)
  std::vector<std::array<double, 2>> waypoints;  // (x, y) in the world (m), scenario markers
};

struct LaserFrame {
  std::uint64_t count = 0;  // the sensor's sample count when copied (a new scan changes it)
  double stamp = 0.0;       // s
  std::vector<float> ranges;  // m, StreamLayout::lasers[i].rays of them
};

struct Snapshot {
  double time = 0.0;  // s of simulation time
  std::uint64_t tick = 0;
  std::vector<description::Pose> X_WL;         // per StreamLayout::links
  std::vector<double> position, velocity, effort;  // per StreamLayout::joints
  bool has_odometry = false;
  double odom_x = 0.0, odom_y = 0.0, odom_z = 0.0;  // m, child frame in the odometry frame
  description::Quat odom_orientation;
  std::vector<LaserFrame> lasers;  // per StreamLayout::lasers
};

// Builds the layout of `sim`'s robot. `urdf`: the expanded description for /robot_description.
StreamLayout make_stream_layout(sim::Simulation& sim, std::string urdf, std::vector<std::array<double, 2>> waypoints);

// A snapshot whose buffers have the sizes `layout` needs (the prototype of the triple buffer).
Snapshot make_snapshot(const StreamLayout& layout);

// Copies the state of `sim` into `out` (made by make_snapshot for `layout`). Real-time safe:
// assigns into the presized buffers only.
void capture_snapshot(const StreamLayout& layout, const sim::Simulation& sim, Snapshot& out) noexcept;

}  // namespace mechsim::live
