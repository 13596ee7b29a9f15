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
//   world:
//     name: empty                     # empty | mars_yard_2024 (seed) | slope (slope_deg: a plane
//                                     # rising along +x, 40 m x 12 m) | heightmap file (size_x ...)
//     # A heightmap file: a PNG or TIFF (physics/heightmap_io.hpp). size_x, size_y: its footprint (m;
//     # a GeoTIFF's own pixel scale when absent); z_min, z_max: the heights of an integer image's
//     # lowest and highest sample values, or, both given, a float DEM's relief rescaled onto them.
//     soil: dry_sand                  # optional: the wheels meet this soil, not rigid ground
//                                     # (sim/soil_config.hpp: named sets or your own values)
//     # Leaving the usable ground (a height field's footprint, or the Mars Yard's ground inside its
//     # 1.5 m flat border; `empty` has no edge) is an event, recorded in summary.json:
//     on_leaving: stop                # stop (default): the run ends there, not completed;
//                                     # continue: a warning, the run goes on (until the robot
//                                     # falls 10 m below the lowest ground: always a stop)
//     boxes:                          # optional objects (physics::WorldBox), any world
//       - {name: block, size: [0.03, 0.04, 0.03], x: 0.8, y: -0.2, z: 0.7,   # m (full edges; centre)
//          roll: 0, pitch: 0, yaw: 0, fixed: true, mass: 1.0}                 # rad; kg (free boxes)
//          # or an orientation quaternion instead of roll/pitch/yaw: quat: [w, x, y, z]
//       - {name: drum, shape: cylinder, radius: 0.2, length: 0.6, x: 2, z: 0.3}  # axis along z
//       - {name: ball, shape: sphere, radius: 0.1, x: 1, z: 0.5, fixed: false}
//       - {name: rock, shape: mesh, mesh: rock.stl, scale: [1, 1, 1], x: 3, z: 0.4, fixed: false, mass: 20}
//         # a mesh file (STL, OBJ, DAE, ...; relative to this file), its own frame at the pose;
//         # MuJoCo collides with its convex hull; a free one's mass fills its bounds
//   spawn:
//     x: 0, y: 0, z: 0.02, yaw: 0     # m, rad (roll, pitch, yaw) of the root link. On a height
//                                     # field (mars_yard_2024, a heightmap file) z is measured
//                                     # from the ground under (x, y), not from z = 0, and
//                                     # without roll or pitch the robot is stood on the ground
//                                     # plane fitted under its footprint (roll and pitch from
//                                     # its normal, z along it); give roll/pitch to fix them
//     joints: {r_gripper_l_finger_joint: 0.3}   # optional initial joint positions (rad, m), as
//                                               # Gazebo's spawn_model -J; physics joints only
//   controllers:                      # optional: a robot its Gazebo model plugins drive needs none
//     file: ../robots/cc8/config/controllers.yaml
//     namespace: cc8
//     start: [joint_state_controller, rover_drive_controller]
//     # A ros2_control robot (<ros2_control> tags, docs/ros2_control.md): ROS 2 parameter files
//     # (controller_manager: {ros__parameters: {update_rate: 100, NAME: {type: ...}}}, NAME:
//     # {ros__parameters: {...}}), recognised by their ros__parameters. `file` and/or `files`
//     # name them; with neither, the description's gazebo_ros2_control <parameters> are read.
//     # `namespace` is then the controller manager's ROS 2 namespace (default: the plugin's
//     # <ros><namespace>), `start` the controllers to load and activate, `params` values laid over
//     # its controllers (NAME: {param: value}).
//     # files: [../robots/cc8/config/ros2_controllers.yaml]
//     # Optional: values laid over the file's parameters (under `namespace`) before the controllers
//     # load, as a second `rosparam load` would. Each must name a parameter the file has (a
//     # misspelt gain must not pass silently); lists and scalars replace, maps merge.
//     params: {rover_drive_controller: {wheel_pid: {p: 5.0}}}
//   # The robot's Gazebo model plugins (diff drive, skid steer, planar move, joint state publisher,
//   # mimic joint) run from the start as controllers named after their <plugin name>: a timeline
//   # event's `controller` may name one (a twist to a drive plugin's cmd_vel), and the report
//   # records a drive plugin's odometry.
//   duration: 30        # s of simulation time
//   period: 0.001       # s
//   integrator: euler   # euler | implicit | rk4: MuJoCo's integrator; default physics::BuildOptions' (see there)
//   seed: 1             # for everything random (world generation when world.seed is absent)
//   record_rate: 50     # Hz of the CSV files
//   replay_rate: 30     # Hz of the link poses `mechsim view` replays (report's replay/); 0: none
//   timeline:
//     - {at: 0.0, controller: rover_drive_controller, twist: {vx: 0.5, vy: 0, wz: 0}}
//     - {at: 2.0, controller: steering_FL_position_controller, command: 0.5}
//     - {at: 0.0, controller: rover_drive_controller, route: {waypoints: [[5, 0], [10, 3]], speed: 0.5}}
//     # A FollowJointTrajectory goal to a trajectory controller (joint_trajectory_controller/
//     # JointTrajectoryController, robot_mechanism_controllers/JointTrajectoryActionController).
//     # joints: default the controller's joints in order. Per point: time (s from the goal's
//     # start, increasing), positions (rad, m; one per joint), optional velocities and
//     # accelerations (cubic / quintic segments). Tolerances as control_msgs/JointTolerance
//     # (> 0 a bound, 0 the controller's default, < 0 none), by joint name or `all`.
//     - at: 0.5
//       controller: r_arm_controller
//       trajectory:
//         joints: [r_shoulder_pan_joint, ...]
//         points:
//           - {time: 1.0, positions: [...], velocities: [...]}
//         goal_time_tolerance: 0.6                       # s; 0: the controller's default
//         goal_tolerance: {all: {position: 0.02, velocity: 0.5}}
//         path_tolerance: {r_elbow_flex_joint: {position: 0.1}}
//     # A control_msgs/GripperCommand goal to pr2_mechanism_controllers/Pr2GripperController:
//     # gap (m) between the finger tips, max_effort (N; < 0 or absent: no limit).
//     - {at: 0.0, controller: r_gripper_controller, gripper: {position: 0.08, max_effort: 50}}
//   checks:
//     - {reach: {x: 10, y: 0, within: 0.5, by: 40}}
//     - {final_pose: {x: 5, y: 0, within: 0.1, lateral_within: 0.05}}
//     - {final_heading: {yaw_deg: 90, within_deg: 5}}
//     - {direction: {deg: 45, within_deg: 5}}   # of the straight line from spawn to the end
//     - {upright: {max_tilt_deg: 30}}
//     - {odometry: {max_error_fraction: 0.03}}   # |odom - truth| / distance driven
//     - {odometry: {max_yaw_error_fraction: 0.03}}   # |odom yaw - true yaw| / |true yaw change|
//     # Trajectory goals: `goal` is the 1-based index among that controller's trajectory events
//     # (default: the last). RMS and max of desired - actual per joint, sampled from the
//     # controller's state (50 Hz by default) while the goal is ACTIVE; result is the
//     # FollowJointTrajectory result code (SUCCESSFUL, INVALID_GOAL, INVALID_JOINTS,
//     # OLD_HEADER_TIMESTAMP, PATH_TOLERANCE_VIOLATED, GOAL_TOLERANCE_VIOLATED).
//     - {trajectory: {controller: r_arm_controller, goal: 2, max_rms_error: 0.01, max_error: 0.05, result: SUCCESSFUL}}
//     # Gripper goals (same `goal` rule): reached / stalled as the action's result says, finished
//     # within `by` s of being sent, and the gap (m) where it finished within `within` m.
//     - {gripper: {controller: r_gripper_controller, goal: 1, reached: true, by: 1.0}}
//     - {gripper: {controller: r_gripper_controller, stalled: true, position: 0.04, within: 0.006}}
//     # ... and the effort the result reports (N or N m: the gripper's max_effort once it stalls).
//     - {gripper: {controller: gripper_action_controller, stalled: true, effort: 0.05, effort_within: 0.001}}
//     # A mechanism joint's position (rad, m) at time `at` (s; default: the end of the run).
//     - {joint: {name: r_gripper_joint, at: 1.2, position: 0.08, within: 0.002}}
//     # The largest |error| of a controller's state (control_msgs/JointControllerState: set point
//     # - process value), read every tick from `after` s on (default 0): a PID joint controller's
//     # tracking, a mimic joint plugin's follower against multiplier * leader + offset (rad, m).
//     - {tracking: {controller: right_finger_mimic, max_error: 0.001, after: 0.0}}
//     # Sensor readings (the sensor's latest sample at time `at`, default the end): a laser's range
//     # (m) along the ray nearest `angle_deg` (0: the middle), or `inf` for nothing in range; an
//     # IMU's tilt (deg: the angle between its z axis and the measured specific force, i.e. how
//     # far from level it reads).
//     - {laser_range: {sensor: front_laser, angle_deg: 0, range: 2.0, within: 0.01, at: 1.0}}
//     - {imu_tilt: {sensor: zed2_imu_sensor, tilt_deg: 0, within_deg: 1, at: 2.0}}
//     # With a soil (world.soil): the mean slip (physics::WheelSoilReading: > 0 spinning faster
//     # than travelling) over [from, to] s of a wheel (its link; default every wheel), sampled
//     # every tick while the wheel is in the soil.
//     - {slip: {wheel: wheel_FL_1, from: 2, to: 10, min_mean: 0.05, max_mean: 0.6}}
//   # With a soil: a test rig's steady states, one row per window of a wheel's means (slip,
//   # drawbar pull, DP/W, torque, sinkage, load) in steady_states.csv and steady_states.png (DP/W,
//   # torque / (W r) and sinkage against slip) and summary.json. wheel: default the first soil wheel.
//   steady_states: {wheel: wheel_link, windows: [[10, 20], [30, 40]]}
//   # More robots in the world (sim::OtherRobot), each with its own controller manager; they
//   # collide with the robot and each other. `robot` and `controllers` default to the first
//   # robot's (its description, args and packages; its controllers file, namespace and start).
//   # A timeline event or a final_pose, final_heading, distance or odometry check names one with
//   # `robot:`; summary.json gives each one's distance, final pose and odometry error.
//   others:
//     - name: cc8_2                   # unique, no "::"
//       spawn: {x: 0, y: 4, z: 0.02, yaw: 1.5708, joints: {steering_FL: 0.1}}
//       robot: {description: ..., args: {...}, packages: {...}, lenient: false}
//       controllers: {file: ..., namespace: cc8, start: [rover_drive_controller]}
//   # e.g. timeline: - {at: 0, robot: cc8_2, controller: rover_drive_controller, twist: {vx: 0.2}}
//   #      checks:   - {odometry: {robot: cc8_2, max_error_fraction: 0.03}}
//   # Other robots' sensors are not simulated, nor their trajectory and gripper goals. An other
//   # ros2_control robot's controller manager is in the namespace /<name> unless its
//   # controllers give `namespace` (as spawn_entity's -robot_namespace puts it there).
//   # Sensors added to the robot, as Gazebo <gazebo reference="LINK"> blocks (the robot's own
//   # <sensor> tags are simulated too; mechsim check lists them). Each entry is XML text.
//   sensors:
//     - |
//       <gazebo reference="base_link">
//         <sensor type="ray" name="front_laser">
//           <update_rate>10</update_rate><pose>0.4 0 0.3 0 0 0</pose>
//           <ray><scan><horizontal><samples>181</samples><min_angle>-1.57</min_angle>
//             <max_angle>1.57</max_angle></horizontal></scan><range><min>0.1</min><max>10</max></range></ray>
//         </sensor>
//       </gazebo>
//   # The report: a CSV per sensor (sensors/<name>.csv), a plot per IMU (sensors/<name>.png), and
//   # the laser scans over the world seen from above at these times (laser_scans.png; default: the
//   # start, the middle and the end). Sensor noise is seeded from `seed`.
//   laser_picture_times: [0, 5, 10]
//   # Every camera of the robot renders once at these times (none by default: cameras render
//   # only when asked); frames in cameras/, side by side in camera_sheet.png.
//   camera_picture_times: [0.5, 10]
//   # A camera's rate (Hz) and image size (pixels; one of width/height keeps the aspect ratio) in
//   # place of the description's, by sensor name or for every camera ("all"), for faster runs;
//   # the field of view stays (description/camera_override.hpp).
//   camera_overrides: {all: {rate: 5, width: 640}, zed2_depth_camera: {rate: 2}}
//
// Unknown keys inside timeline events, world boxes and checks are errors (a misspelt bound
// must not pass silently). Every error names the file, the line and the parameter path.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "description/camera_override.hpp"
#include "control/params.hpp"
#include "control/ports.hpp"
#include "controllers/gripper/pr2_gripper_ports.hpp"
#include "controllers/trajectory/trajectory_msgs.hpp"
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
  std::string robot;  // "": the first robot; else an `others:` entry's name
  std::string controller;
  enum class Kind { Scalar, Array, Twist, Route, Mode, Trajectory, Gripper } kind = Kind::Scalar;
  double scalar = 0.0;
  std::vector<double> array;
  control::Twist twist;
  RouteCommand route;
  std::string mode;  // ackermann | crab | point_turn | auto
  // Trajectory: joint names empty = the controller's joints (filled when the run binds it).
  // Tolerances named `all` apply to every joint of the controller.
  control::FollowJointTrajectoryGoal trajectory;
  control::GripperCommand gripper;  // Gripper
  std::string location;  // file:line of the event, for errors found when the run binds it
};

struct Check {
  enum class Kind { Reach, FinalPose, FinalHeading, Direction, Upright, Odometry, Distance, Trajectory, Gripper, Joint,
                    Tracking, LaserRange, ImuTilt, Slip } kind = Kind::Reach;
  std::string text;  // as written, for the report
  std::string robot;  // FinalPose, FinalHeading, Distance, Odometry: "" the first robot, else an other's name
  double x = 0.0, y = 0.0, within = 0.0, by = 0.0;  // Reach / FinalPose (m, s)
  std::optional<double> lateral_within;            // FinalPose: |y error| (m)
  double yaw = 0.0, within_angle = 0.0;            // FinalHeading, Direction (rad)
  double max_tilt = 0.0;                           // Upright (rad)
  std::optional<double> max_error_fraction;        // Odometry: position error / distance
  std::optional<double> max_yaw_error_fraction;    // Odometry: yaw error / |yaw change|
  double min_distance = 0.0, max_distance = 0.0;   // Distance (m)
  // Trajectory and Gripper: which goal (1-based among the controller's events of that kind;
  // 0 = the last).
  std::string controller;
  std::size_t goal = 0;
  std::optional<double> max_rms_error, max_abs_error;   // Trajectory, per joint (rad, m); Tracking
  std::optional<control::TrajectoryResultCode> result;  // Trajectory
  std::optional<bool> reached, stalled;                 // Gripper
  std::optional<double> finished_by;                    // Gripper: s after the goal was sent
  std::optional<double> position;                       // Gripper: final gap (m), +- `within`; Joint
  std::optional<double> effort;                         // Gripper: the result's effort, +- effort_within
  double effort_within = 0.0;
  std::string joint;                                    // Joint: mechanism joint name
  std::optional<double> at;                             // Joint, LaserRange, ImuTilt: s (absent: the end); Tracking: from
  std::string sensor;                                   // LaserRange, ImuTilt: sensor name
  double angle = 0.0;                                   // LaserRange: ray direction (rad)
  double range = 0.0;                                   // LaserRange: m (+inf: nothing in range)
  double tilt = 0.0;                                    // ImuTilt: rad (+- within_angle)
  std::string wheel;                                    // Slip: a wheel's link ("": every wheel)
  double from = 0.0, to = 1e300;                        // Slip: window (s)
  std::optional<double> min_mean, max_mean;             // Slip: bounds on the mean slip
};

// One `sensors:` entry: Gazebo sensor blocks as a URDF holds them, and where they start.
struct SensorBlock {
  std::string xml;
  std::string file;
  int line = 0;  // of the block's first line
};

// One controllers.params value: `key` is its path under the controllers namespace
// ("rover_drive_controller/wheel_pid/p"), `value` a scalar or a list.
struct ControllerParam {
  std::string key;
  control::Params value;
};

// One `others:` entry: another robot in the world.
struct OtherRobotConfig {
  std::string name;
  std::string location;  // file:line of the entry
  std::string description;  // absolute
  std::map<std::string, std::string> xacro_args;
  std::map<std::string, std::string> packages;
  bool lenient = false;
  physics::SpawnPose spawn;
  std::map<std::string, double> initial_joints;
  std::string controllers_file;  // absolute; empty: no controllers YAML
  std::string controllers_namespace;
  std::vector<std::string> start;
  std::vector<std::string> controllers_files;  // ros2_control: more parameter files
  bool ros2_control = false;
};

// A scenario's steady_states: the windows (s) over which a wheel's soil readings are averaged.
struct SteadyStateSpec {
  std::string wheel;  // a soil wheel's link; "": the first
  std::vector<std::array<double, 2>> windows;
};

// What a run does when the robot leaves the usable ground.
enum class LeavingTerrain { Stop, Continue };

struct Scenario {
  std::string name;
  std::string file;  // where it was read from
  std::string description;  // robot description file (absolute)
  std::map<std::string, std::string> xacro_args;
  std::map<std::string, std::string> packages;
  bool lenient = false;
  WorldConfig world;
  LeavingTerrain on_leaving = LeavingTerrain::Stop;  // world.on_leaving
  physics::SpawnPose spawn;
  bool settle_on_ground = true;  // spawn has neither roll nor pitch (SimulationOptions::settle_on_ground)
  std::map<std::string, double> initial_joints;  // spawn.joints: physics joint -> rad or m
  std::vector<physics::WorldBox> boxes;          // world.boxes, added to the world's own
  physics::DifferentialMode differential = physics::DifferentialMode::MimicConstraint;
  std::string controllers_file;  // absolute; empty: no controllers YAML
  std::string controllers_namespace;
  std::vector<std::string> start;
  std::vector<ControllerParam> controller_params;  // controllers.params, in document order
  // ros2_control: controllers.files (absolute; after `file`), and whether the controllers are a
  // ROS 2 controller manager's (the files hold ros__parameters, or `controllers` names no file:
  // the description's gazebo_ros2_control <parameters>).
  std::vector<std::string> controllers_files;
  bool ros2_control = false;
  std::vector<OtherRobotConfig> others;
  double duration = 10.0;
  double period = 0.001;
  physics::Integrator integrator = physics::BuildOptions{}.integrator;  // the project default
  std::uint64_t seed = 1;
  double record_rate = 50.0;
  double replay_rate = 30.0;  // Hz of the replay's link poses (sim/replay_recorder.hpp); 0: no replay
  std::vector<TimelineEvent> timeline;  // sorted by time
  std::vector<Check> checks;
  std::vector<SensorBlock> sensor_blocks;    // sensors: added to the robot
  std::vector<double> laser_picture_times;   // s; empty: start, middle and end
  std::vector<double> camera_picture_times;  // s; empty: no camera pictures
  // camera_overrides: per camera sensor (or "all") a lower rate or resolution for a fast run.
  std::map<std::string, description::CameraOverride> camera_overrides;
  std::optional<SteadyStateSpec> steady_states;
};

// Reads and validates a scenario file. Errors name the file and the parameter path.
Scenario load_scenario(const std::string& path);
// A `world:` map (name, slope_deg, soil, seed, size_x/size_y/z_min/z_max of a heightmap file),
// relative file names resolved against `base` (what a scenario's world and `mechsim tune`'s
// conditions share). Throws ScenarioError naming the file, line and key.
WorldConfig read_world_config(const control::Params& world, const std::filesystem::path& base);
// The same from a tree already read (and perhaps changed: mechsim sweep's overrides); `path` is
// the file it came from (relative paths in it are resolved against its folder).
Scenario load_scenario(const control::Params& root, const std::string& path);

}  // namespace mechsim::sim
