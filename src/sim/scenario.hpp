#pragma once
// A scenario: one headless simulation run described in YAML — robot, world, spawn pose,
// controllers, duration, a timeline of commands and the checks that decide pass or fail.
//
//   name: cc8_straight
//   robot:
//     description: ../robots/cc8/urdf/cc8.urdf.xacro   # relative to the scenario file
//     args: {wheel_mu: 0.8}                            # xacro name:=value
//     packages: {mechsim_cc8: ../robots/cc8}           # optional; --package NAME=DIR
//     lenient: false
//   world: {name: empty}              # empty | mars_yard_2024 (seed) | heightmap file (size_x ...)
//   spawn: {x: 0, y: 0, z: 0.02, yaw: 0}   # m, rad (roll, pitch, yaw)
//   controllers:
//     file: ../robots/cc8/config/controllers.yaml
//     namespace: cc8
//     start: [joint_state_controller, rover_drive_controller]
//   duration: 30        # s of simulation time
//   period: 0.001       # s
//   integrator: implicit  # implicit (default) | euler | rk4: MuJoCo's integrator (see BuildOptions)
//   seed: 1             # for everything random (world generation when world.seed is absent)
//   record_rate: 50     # Hz of the CSV files
//   timeline:
//     - {at: 0.0, controller: rover_drive_controller, twist: {vx: 0.5, vy: 0, wz: 0}}
//     - {at: 2.0, controller: steering_FL_position_controller, command: 0.5}
//     - {at: 0.0, controller: rover_drive_controller, route: {waypoints: [[5, 0], [10, 3]], speed: 0.5}}
//   checks:
//     - {reach: {x: 10, y: 0, within: 0.5, by: 40}}
//     - {final_pose: {x: 5, y: 0, within: 0.1, lateral_within: 0.05}}
//     - {final_heading: {yaw_deg: 90, within_deg: 5}}
//     - {direction: {deg: 45, within_deg: 5}}   # of the straight line from spawn to the end
//     - {upright: {max_tilt_deg: 30}}
//     - {odometry: {max_error_fraction: 0.03}}

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "control/ports.hpp"
#include "physics/physics_options.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {

struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RouteCommand {
  std::vector<std::array<double, 2>> waypoints;  // (x, y) in the world frame (m)
  double speed = 0.4;          // m/s along the route
  double tolerance = 0.3;      // m: a waypoint counts as reached inside this radius
  double lookahead = 1.0;      // m: pure-pursuit look-ahead distance
  double max_yaw_rate = 0.6;   // rad/s
};

struct TimelineEvent {
  double at = 0.0;  // s
  std::string controller;
  enum class Kind { Scalar, Array, Twist, Route, Mode } kind = Kind::Scalar;
  double scalar = 0.0;
  std::vector<double> array;
  control::Twist twist;
  RouteCommand route;
  std::string mode;  // ackermann | crab | point_turn | auto
};

struct Check {
  enum class Kind { Reach, FinalPose, FinalHeading, Direction, Upright, Odometry, Distance } kind = Kind::Reach;
  std::string text;  // as written, for the report
  double x = 0.0, y = 0.0, within = 0.0, by = 0.0;  // Reach / FinalPose (m, s)
  std::optional<double> lateral_within;            // FinalPose: |y error| (m)
  double yaw = 0.0, within_angle = 0.0;            // FinalHeading, Direction (rad)
  double max_tilt = 0.0;                           // Upright (rad)
  double max_error_fraction = 0.0;                 // Odometry
  double min_distance = 0.0, max_distance = 0.0;   // Distance (m)
};

struct Scenario {
  std::string name;
  std::string file;  // where it was read from
  std::string description;  // robot description file (absolute)
  std::map<std::string, std::string> xacro_args;
  std::map<std::string, std::string> packages;
  bool lenient = false;
  WorldConfig world;
  physics::SpawnPose spawn;
  physics::DifferentialMode differential = physics::DifferentialMode::MimicConstraint;
  std::string controllers_file;  // absolute
  std::string controllers_namespace;
  std::vector<std::string> start;
  double duration = 10.0;
  double period = 0.001;
  physics::Integrator integrator = physics::Integrator::Implicit;
  std::uint64_t seed = 1;
  double record_rate = 50.0;
  std::vector<TimelineEvent> timeline;  // sorted by time
  std::vector<Check> checks;
};

// Reads and validates a scenario file. Errors name the file and the parameter path.
Scenario load_scenario(const std::string& path);

}  // namespace mechsim::sim
