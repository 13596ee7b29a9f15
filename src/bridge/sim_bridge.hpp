#pragma once
// SimBridge: one robot of a simulated world as the ROS bindings see it (ros/ for ROS 1, ros2/ for
// ROS 2): its controller manager, the controllers' ports, its model plugins and sensors, and
// Gazebo's model API over it. ROS 1 headers do not compile as C++20 and the sim/control headers
// do not compile as C++17 (std::span, defaulted comparisons), so this header is C++17-clean: the
// bindings reach Simulation, ControllerManager and the ports only through it; its implementation
// (bridge/*.cpp, library mechsim_bridge) is C++20.
//
// Threads: run_for() and the tick observers belong to the loop thread. pause(), unpause(),
// request_reset() and the controller-manager calls may come from any thread (the simulation and
// the manager serialise them). A PortRef is valid while its controller is loaded: a binding drops
// every PortRef of a controller before unloading it.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "control/ros2_params.hpp"
#include "controllers/trajectory/trajectory_msgs.hpp"
#include "description/robot_model.hpp"
#include "description/ros2_control_plugin.hpp"
#include "description/sensor_spec.hpp"
#include "sensors/sensor_output.hpp"

namespace mechsim::sim {
class Simulation;
}

namespace mechsim::bridge {

struct BridgeOptions {
  description::RobotModel robot;       // parsed robot_description
  control::Params controller_params;  // the namespace holding the controllers (e.g. /cc8)
  // The tree controller_params belongs to, where gazebo_ros_control's pid_gains are looked up
  // (sim::SimulationOptions::parameter_root); none: controller_params is the root.
  std::optional<control::Params> parameter_root;
  std::string world = "empty";        // empty | mars_yard_2024 | heightmap file path
  double x = 0.0, y = 0.0, z = 0.0;   // m, spawn position (z above the ground under x, y)
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // rad, spawn orientation
  bool paused = false;
  double real_time_factor = 0.0;  // 0: as fast as possible
  double period = 0.001;          // s
  double start_time = 0.0;        // s: the world's time when the robot is spawned into it
  std::map<std::string, double> initial_joints;  // rad or m by joint (spawn_model -J)
  // An SDF world's models with sensors or model plugins are left out of the world's objects: the
  // caller brings them in as robots of their own (describe_world's WorldSummary::robots; as
  // bridge::World does).
  bool world_models_apart = false;
  // ros2_control (docs/ros2_control.md). Set: the robot's controllers are a ros2_control
  // controller manager's, configured from these ROS 2 parameter files' contents (every node's
  // parameters: e.g. the files of the description's gazebo_ros2_control <parameters>, or those a
  // user gives the node); controller_params and parameter_root are then not used. The manager's
  // node is <ros2_namespace>/<controller_manager_name> (sim/ros2_control_config.hpp), its
  // update_rate and controllers those its parameters declare.
  std::optional<control::Ros2ParameterSet> ros2_parameters;
  std::string ros2_namespace;  // the manager's namespace; "": the plugin's <ros><namespace>
};

// A link's (or a model's root link's) state in the world frame: pose X_WL, and the twist of the
// link frame's origin (m/s, rad/s).
struct EntityState {
  description::Pose pose;
  description::Vec3 linear, angular;
};

// gazebo_msgs/GetJointProperties' content; type as its constants (REVOLUTE 0, CONTINUOUS 1,
// PRISMATIC 2, FIXED 3).
struct JointPropertiesData {
  int type = 3;
  double damping = 0.0;             // N m s/rad or N s/m
  double position = 0.0, rate = 0.0;  // rad or m, rad/s or m/s
};

// gazebo_msgs/SetJointProperties' content mechsim honours (ODEJointProperties' first entries):
// damping (N m s/rad or N s/m), hiStop and loStop (rad or m). Unset: unchanged.
struct JointPropertyChange {
  std::optional<double> damping, lower, upper;
};

// gazebo_msgs/GetLinkProperties' content: the URDF inertial (zero mass when it has none).
struct LinkPropertiesData {
  description::Pose com;  // X_L<centre of mass frame>
  bool gravity_mode = true;
  double mass = 0.0;  // kg
  double ixx = 0.0, ixy = 0.0, ixz = 0.0, iyy = 0.0, iyz = 0.0, izz = 0.0;  // kg m^2, at the com frame
};

// An SDF world's model that is a robot of its own (BridgeOptions::world_models_apart): its sensors
// and model plugins run. A static one is welded to the world (its root link is `world`).
struct WorldRobot {
  std::string name;
  description::RobotModel robot;
  description::Pose X_WR;  // the root link frame in the world: its spawn pose
  bool is_static = false;
};

// What a world (BridgeOptions::world) holds, for the Gazebo world (world.hpp).
struct WorldSummary {
  bool has_ground = true;
  description::Vec3 gravity{0.0, 0.0, -9.81};  // m/s^2
  std::vector<std::string> sdf_models;         // an SDF world's models that are simulated
  std::vector<description::Pose> sdf_model_poses;  // each one's pose in the SDF (X_WM)
  std::vector<std::string> not_simulated;      // one line each
  std::vector<std::string> warnings;           // what Gazebo tolerates, taken as it does; one line each
  double max_step_size = 0.0;                  // s; 0: unset
  double real_time_factor = 0.0;               // 0: unset
  std::vector<WorldRobot> robots;              // with models_apart: the models that are robots
  struct Light {
    std::string name, type;
    bool cast_shadows = true;
    double diffuse[4] = {1, 1, 1, 1}, specular[4] = {0.1, 0.1, 0.1, 1};
    double attenuation_constant = 1.0, attenuation_linear = 0.0, attenuation_quadratic = 0.0;
    description::Vec3 direction{0.0, 0.0, -1.0};
    description::Pose pose;
  };
  std::vector<Light> lights;  // an SDF world's <light>s
};
// Builds the world once; throws std::runtime_error naming the world or file. models_apart: as
// BridgeOptions::world_models_apart.
WorldSummary describe_world(const std::string& world, bool models_apart = false);

// What a controller port is, as far as ROS binding goes.
enum class PortType : std::uint8_t {
  ScalarCommand,   // std_msgs/Float64
  ArrayCommand,    // std_msgs/Float64MultiArray (size values)
  TwistCommand,    // geometry_msgs/Twist
  JointControllerState,  // control_msgs/JointControllerState
  JointStates,     // sensor_msgs/JointState
  Odometry,        // nav_msgs/Odometry
  TrajectoryCommand,  // trajectory_msgs/JointTrajectory ("command")
  TrajectoryGoal,     // control_msgs/FollowJointTrajectoryAction ("follow_joint_trajectory")
  TrajectoryState,    // control_msgs/JointTrajectoryControllerState ("state")
  GripperCommand,     // pr2_controllers_msgs/Pr2GripperCommand ("command" of the PR2 gripper)
  GripperGoal,        // pr2_controllers_msgs/Pr2GripperCommandAction ("gripper_action")
  TrajectoryQuery,    // control_msgs/QueryTrajectoryState service ("query_state")
  ScanCommand,        // pr2_msgs/PeriodicCmd and LaserTrajCmd (the PR2 laser tilt controller's "command")
  TwistState,         // geometry_msgs/TwistStamped (diff_drive_controller's "cmd_vel_out")
  ImuState,           // sensor_msgs/Imu (imu_sensor_controller: one port per IMU, named after it)
  WrenchState,        // geometry_msgs/WrenchStamped (force_torque_sensor_controller: one per sensor)
  Other,           // not bound to ROS (gains, mode, status, group state, trajectories)
};

// A handle on one port of one loaded controller (see the lifetime rule above).
struct PortRef {
  std::string controller;
  std::string controller_type;  // e.g. robot_mechanism_controllers/JointTrajectoryActionController
  std::string name;  // the port's name: "command", "state", "joint_states", "cmd_vel", "odom", ...
  PortType type = PortType::Other;
  std::size_t size = 0;  // ArrayCommand: values expected
  void* port = nullptr;  // control::Port*, opaque here
};

struct ClaimedResources {
  std::string hardware_interface;  // e.g. hardware_interface::EffortJointInterface
  std::vector<std::string> resources;  // joint names
};

struct ControllerSummary {
  std::string name, type;
  std::string state;  // "initialized", "running", "stopped", "waiting" (its start is pending)
  // ROS 1: hardware_interface is ros_control's class name ("hardware_interface::
  // EffortJointInterface"). ros2_control: the interface's name ("position", "velocity",
  // "effort"): ros2_control's claimed interface of joint J is "J/<name>".
  std::vector<ClaimedResources> claims;
};

// A ros2_control robot (BridgeOptions::ros2_parameters) as the wire layer needs it to name its
// topics as gazebo_ros2_control would (docs/ros2_control.md).
struct Ros2ControlSummary {
  // The description's gazebo_ros2_control / gz_ros2_control plugin element: <ros><namespace>,
  // <ros><remapping>s, <parameters> files (as written and resolved), <controller_manager_name>,
  // <hold_joints>, <robot_param>, <robot_param_node>; nullopt when the description has none.
  std::optional<description::Ros2ControlPlugin> plugin;
  std::string controller_manager;  // the manager's fully qualified node name ("/ns/controller_manager")
  std::string node_namespace;      // its (and its controllers') namespace: "/" or "/ns"
  double update_rate = 100.0;      // Hz
  std::vector<std::string> declared_controllers;  // what its parameters declare (NAME: {type: ...})
  std::vector<std::string> parameter_files;       // the files' names, in order
  std::vector<std::string> notes;                 // warnings from reading them
};

// A Gazebo model plugin of the robot (controllers/plugins/model_plugin.hpp) as ROS sees it: its
// ports under the topic names the plugin gives them. The ROS binding publishes each new snapshot
// of an output port (the plugin keeps its own rate) and writes each message of an input one.
struct PluginTopicRef {
  PortRef port;
  std::string topic;  // as the plugin resolves it, relative to robot_namespace unless it starts with '/'; "": none
  std::string message;  // "": the port's own; "geometry_msgs/Pose": Gazebo's vel_cmd pose (control::PluginTopic)
};

struct ModelPluginSummary {
  std::string name, filename;
  std::string origin;           // "file:line" of its <plugin> element
  std::string robot_namespace;  // <robotNamespace>, "" for the root
  std::vector<PluginTopicRef> topics;
  bool odom_tf = false;  // the "odom" port's pose also on /tf
  // publishWheelTF: these joints' parent -> child transforms on /tf with the "joint_states" port,
  // frames named as control::PluginRosInterface says (the links' names, or the joint's for the
  // child, with the TF prefix).
  std::vector<std::string> wheel_tf_joints;
  std::string tf_prefix;
  bool wheel_tf_child_is_joint = false;
};

struct BridgeResult {
  bool ok = true;
  std::string error;
};

// control_msgs/JointControllerState's content.
struct JointControllerStateData {
  double stamp = 0.0;
  double set_point = 0.0, process_value = 0.0, process_value_dot = 0.0, error = 0.0;
  double time_step = 0.0, command = 0.0;
  double p = 0.0, i = 0.0, d = 0.0, i_clamp = 0.0;
  bool antiwindup = false;
};

// sensor_msgs/JointState's content.
struct JointStatesData {
  double stamp = 0.0;
  std::vector<std::string> names;
  std::vector<double> position, velocity, effort;
};

// nav_msgs/Odometry's content (planar: z = 0).
struct OdometryData {
  double stamp = 0.0;
  std::string frame_id, child_frame_id;
  double x = 0.0, y = 0.0;                     // m
  double z = 0.0;                              // m (Gazebo plugins' world odometry)
  double qw = 1.0, qx = 0.0, qy = 0.0, qz = 0.0;  // orientation
  double vx = 0.0, vy = 0.0, wz = 0.0;         // m/s, rad/s in child_frame_id
  std::vector<double> pose_covariance, twist_covariance;  // 36 each, row-major
};

// pr2_controllers_msgs/Pr2GripperCommandResult and Feedback.
struct GripperStateData {
  double position = 0.0;  // m, the gap between the finger tips
  double effort = 0.0;    // N, the effort commanded on the gap joint
  bool stalled = false;
  bool reached_goal = false;
};

// pr2_mechanism_msgs/JointStatistics, over the window since the previous take (see
// SimBridge::take_mechanism_statistics).
struct JointStatisticsData {
  std::string name;
  double position = 0.0, velocity = 0.0;   // rad or m, rad/s or m/s, now
  double measured_effort = 0.0;            // N m or N, now
  double commanded_effort = 0.0;           // N m or N, now (after the safety limits)
  bool violated_limits = false;            // window: outside [lower, upper], or effort at its limit
  double odometer = 0.0;                   // rad or m travelled since the simulation started
  double min_position = 0.0, max_position = 0.0;  // window
  double max_abs_velocity = 0.0, max_abs_effort = 0.0;  // window (measured effort)
};

// pr2_mechanism_msgs/ActuatorStatistics: what a simulated actuator knows.
struct ActuatorStatisticsData {
  std::string name;
  int device_id = 0;              // index in the mechanism
  double position = 0.0;          // rad (motor side)
  double velocity = 0.0;          // rad/s
  double commanded_effort = 0.0;  // N m
  double measured_effort = 0.0;   // N m
};

// pr2_mechanism_msgs/ControllerStatistics.
struct ControllerStatisticsData {
  std::string name;
  bool running = false;
  double max_time = 0.0, mean_time = 0.0;  // s of wall time per update, since the load
  std::uint64_t overruns = 0;              // updates longer than the period
};

struct MechanismStatisticsData {
  double stamp = 0.0;  // s
  std::vector<ActuatorStatisticsData> actuators;
  std::vector<JointStatisticsData> joints;
  std::vector<ControllerStatisticsData> controllers;
};

class SimBridge {
 public:
  using Observer = std::function<void(double time)>;  // sim time (s) after a tick

  // Builds world, physics, mechanism and controller manager. Throws std::runtime_error with
  // what failed (world name, description, mechanism).
  explicit SimBridge(BridgeOptions options);
  // Another robot in `host`'s world (Gazebo's second spawned model; sim::Simulation::add_other):
  // taken into the running world between two ticks, every robot there going on undisturbed. Its
  // controller manager, plugins, sensors and model API are its own; time, pause, stepping and the
  // real-time factor are the world's (the host's). No run_for():
  // the host's loop ticks it and runs its observers. options.robot.name is its name in the world;
  // the world, period, start time and paused flag are the host's. Throws std::runtime_error
  // (changing nothing) when it cannot be built or the loop does not take it within 60 s.
  SimBridge(SimBridge& host, BridgeOptions options);
  // An other robot leaves the world with its bridge (remove_from_world()).
  ~SimBridge();
  bool is_other_robot() const;
  // An other robot: out of the world (its controllers stopped and unloaded first, the physics
  // rebuilt without it, in the loop between ticks); the bridge must not be used after. Refused
  // for the world's first robot, whose simulation ticks the world.
  BridgeResult remove_from_world();
  // An other robot, once the host's loop has stopped for good (the world shutting down): forgets
  // its simulation, which goes with the host's; the bridge must not be used after.
  void detach_from_world();
  // Returns once the loop has started a new tick (or, paused, run its requests): an observer
  // that was running when it was called has returned. At most 5 s; at once after detach.
  void wait_for_loop();
  SimBridge(const SimBridge&) = delete;
  SimBridge& operator=(const SimBridge&) = delete;

  // ---- loop thread
  // Runs `duration` seconds of simulation time (paced to the real-time factor); returns at once
  // while paused (after applying a pending reset). False with `error` when the physics diverged.
  bool run_for(double duration, std::string* error);
  void add_observer(Observer observer);
  // Live view (~foxglove_port; src/live/): serves the simulation over the Foxglove WebSocket
  // protocol on address:port (port 0: any free one) with `urdf` as /robot_description and /tf,
  // /joint_states, /odom at `rate` Hz (sim time); returns its ws:// address. Call before the loop
  // starts. Throws std::runtime_error naming the address and port when it cannot listen.
  std::string start_live_view(const std::string& address, int port, const std::string& urdf, double rate);
  // What the live view sent ("" without one): clients, messages sent and dropped.
  std::string live_view_summary() const;
  // Joint positions (rad or m) per description joint (robot().joints order); 0 for joints the
  // physics does not have (fixed). Base pose X_WB of the root link.
  void joint_positions(std::vector<double>& out) const;
  description::Pose base_pose() const;
  // The PR2 controller manager's own outputs (pr2_controller_manager: joint_states,
  // mechanism_statistics). enable_mechanism_statistics() makes every following tick update the
  // joint statistics window (call it before the loop thread starts). Joints: every non-fixed
  // description joint, the mechanism's state where the mechanism has the joint (the PR2 gripper
  // gap included), else the physics'. Both reads are for the loop thread (an observer).
  void enable_mechanism_statistics();
  void mechanism_joint_states(JointStatesData& out) const;
  // Fills `out` and starts a new window (min/max, violated_limits, max_abs_*).
  void take_mechanism_statistics(MechanismStatisticsData& out);
  // The simulated sensors (the simulation's sensors::SensorSet, in its order): spec and latest
  // reading (its count changes with each new sample). A disabled sensor is not sampled (nobody
  // consumes it); the change takes effect at the next tick. Loop thread (an observer).
  std::size_t sensor_count() const;
  const description::SensorSpec& sensor_spec(std::size_t i) const;
  const sensors::SensorReading& sensor_reading(std::size_t i) const;
  void set_sensor_enabled(std::size_t i, bool enabled);
  // Samples sensor i at the next tick, enabled or not, due or not (a triggered camera's frame).
  void request_sensor_sample(std::size_t i);
  // A camera sensor's CameraInfo per lens, known without rendering (empty for other sensors).
  std::vector<sensors::CameraInfo> camera_infos(std::size_t i) const;
  // Declared sensors mechsim does not simulate: "SOURCE:LINE: sensor 'NAME': reason", one line
  // each (the ones left out for this physics model are in physics_warnings()).
  std::vector<std::string> skipped_sensors() const;

  // ---- any thread
  double time() const;  // s
  double period() const;
  std::uint64_t ticks() const;
  std::uint64_t resets() const;
  void pause();
  void unpause();
  bool paused() const;
  void request_reset();
  // gazebo_ros_control's e-stop (sim::Simulation::set_e_stop; any thread) and the topic the
  // description's plugin names for it ("" when none: no e-stop).
  void set_e_stop(bool active);
  bool e_stop_active() const;
  const std::string& e_stop_topic() const;
  const description::RobotModel& robot() const;
  // What the physics left out or changed and why (meshes it could not use, with the link and the
  // path tried; massless links; dropped joints), one line each.
  const std::vector<std::string>& physics_warnings() const;
  // Per joint with a position or velocity interface: gazebo_ros_control's PID or mechsim's servo.
  const std::vector<std::string>& joint_drive_notes() const;
  // The controllers' parameter namespace (a handle on the tree the manager reads at load time).
  // ros2_control: one map per declared controller, its type and its node's parameters
  // (controller_params().child(NAME): use_stamped_vel, enable_odom_tf, frame_id, ...).
  control::Params controller_params() const;
  // ros2_control: the robot's controller manager and plugin settings; null for a ROS 1 robot.
  const Ros2ControlSummary* ros2_control() const;
  // ros2_control: every node's parameters as the files give them (parameters_for(fqn)); null
  // for a ROS 1 robot.
  const control::Ros2ParameterSet* ros2_parameters() const;

  // Loop thread (an observer), or any thread once the loop has stopped: the state of every link
  // the physics has, in link_names() order, world frame.
  const std::vector<std::string>& link_names() const;
  void link_states_now(std::vector<EntityState>& out) const;
  // The model's state (its root link's; a model fixed to the world: where its spawn put it, as
  // Gazebo reports a static model), world frame. Loop thread, like link_states_now.
  void model_state_now(EntityState& out) const;
  // Another robot welded to the world (its root link is `world`): its model frame is its spawn pose.
  bool fixed_in_world() const;
  description::Pose spawn_pose() const;  // X_W<root> as spawned
  // The world's SDF models now (WorldSummary::sdf_models order): a moving one where the physics
  // has it, a static one where the SDF put it. Loop thread only (an observer), like
  // link_states_now.
  void world_model_states_now(std::vector<EntityState>& out) const;
  // Only once the loop thread has stopped (a model being deleted): stops every running
  // controller at once (their stopping() runs) and returns the names of all loaded ones.
  std::vector<std::string> stop_all_controllers_now();

  // ---- Gazebo's model API (any thread). Each call runs in the loop thread between ticks and
  // waits for it (at most 5 s of wall time: an error when the loop does not answer). Links and
  // joints by their URDF names. Refusals (unknown link, non-finite value, a fixed robot's pose)
  // answer ok = false with why, and change nothing.
  BridgeResult link_state(const std::string& link, EntityState& out) const;
  // The world's SDF model `index` (WorldSummary::sdf_models order), as world_model_states_now.
  BridgeResult world_model_state(std::size_t index, EntityState& out) const;
  // Moves a moving SDF model (a free object, or a passive model not jointed to the world) to a
  // state (its model frame, world frame); static ones are refused.
  BridgeResult set_world_model_state(std::size_t index, const EntityState& state);
  // The root link's pose and twist (the model's state); a robot fixed to the world is refused.
  BridgeResult set_root_state(const EntityState& state);
  // Positions (rad or m), velocities set to zero (gazebo's set_model_configuration).
  BridgeResult set_joint_positions(const std::vector<std::string>& joints, const std::vector<double>& positions);
  BridgeResult joint_properties(const std::string& joint, JointPropertiesData& out) const;
  BridgeResult link_properties(const std::string& link, LinkPropertiesData& out) const;
  // Gazebo's set_joint_properties / set_link_properties: kept for the life of the model (over
  // spawns and deletes of others, which build the physics again). A link's mass, centre of mass
  // and inertia; gravity_mode cannot change while the model runs (refused when it would).
  BridgeResult set_joint_properties(const std::string& joint, const JointPropertyChange& change);
  BridgeResult set_link_properties(const std::string& link, const LinkPropertiesData& properties);
  // Forces from outside, from `start` (s, sim time; past: now) for `duration` s (< 0: no end; 0:
  // nothing; shorter than a tick: one tick). Wrench in the world frame: force (N) acting at the
  // link's centre of mass moved by offset_W (m), torque (N m).
  BridgeResult apply_link_wrench(const std::string& link, const description::Vec3& force_W,
                                 const description::Vec3& torque_W, const description::Vec3& offset_W, double start,
                                 double duration);
  BridgeResult apply_joint_effort(const std::string& joint, double effort, double start, double duration);
  BridgeResult clear_link_wrenches(const std::string& link);
  BridgeResult clear_joint_efforts(const std::string& joint);
  description::Vec3 gravity() const;  // m/s^2, world frame
  BridgeResult set_gravity(const description::Vec3& g_W);
  bool fixed_to_world() const;
  // The real-time factor the loop paces to (0: as fast as possible), and the one it measured.
  double real_time_factor() const;
  void set_real_time_factor(double factor);
  double measured_real_time_factor() const;
  // Stepping while paused: `count` more ticks; pending_steps() counts them down.
  void request_steps(std::uint64_t count);
  std::uint64_t pending_steps() const;
  void cancel_steps();

  BridgeResult load_controller(const std::string& name);
  BridgeResult unload_controller(const std::string& name);
  // strict: ros_control STRICT, else BEST_EFFORT. Waits for the tick to apply the switch: at
  // most `timeout` seconds of wall time (5 s when not positive and finite, 30 s at most), after
  // which the switch is taken back and refused; not while paused (then it stays pending and
  // applies at the first tick after the unpause).
  BridgeResult switch_controllers(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                                  bool strict, double timeout);
  std::vector<ControllerSummary> list_controllers() const;
  std::vector<std::string> list_controller_types() const;
  bool is_loaded(const std::string& name) const;
  std::vector<PortRef> ports(const std::string& controller) const;  // empty when not loaded
  // The robot's simulated Gazebo model plugins; they run from construction on and are not in
  // list_controllers() (gazebo_ros_control's controller manager does not list them either).
  std::vector<ModelPluginSummary> model_plugins() const;
  // The model plugins mechsim does not simulate, one line each ("gazebo plugin 'x' (lib...so) at
  // file:line: NOT SIMULATED: ...").
  std::vector<std::string> plugin_notes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  static std::vector<std::string> stop_controllers(sim::Simulation& s);  // loop thread
};

// Port access (non-real-time, any thread). Writes return false with `error` when rejected (wrong
// type, non-finite, wrong size). Reads return false when the port has nothing new since
// `*sequence` (updated on success) or is of another type.
bool write_scalar(const PortRef& port, double value, std::string* error);
bool write_array(const PortRef& port, const std::vector<double>& values, std::string* error);
bool write_twist(const PortRef& port, double vx, double vy, double vz, double wx, double wy, double wz,
                 std::string* error);
bool read_joint_controller_state(const PortRef& port, JointControllerStateData& out, std::uint64_t* sequence);
bool read_joint_states(const PortRef& port, JointStatesData& out, std::uint64_t* sequence);
bool read_odometry(const PortRef& port, OdometryData& out, std::uint64_t* sequence);
// geometry_msgs/TwistStamped's content.
struct TwistStampedData {
  double stamp = 0.0;
  std::string frame_id;
  double vx = 0.0, vy = 0.0, vz = 0.0, wx = 0.0, wy = 0.0, wz = 0.0;  // m/s, rad/s
};
bool read_twist_state(const PortRef& port, TwistStampedData& out, std::uint64_t* sequence);
// The sensor controllers' snapshots: header stamp (s, the controller's update) and frame_id, and
// the values (the sensor's last sample) in the sensor layer's plain form.
bool read_imu_state(const PortRef& port, double& stamp, std::string& frame_id, sensors::ImuReading& out,
                    std::uint64_t* sequence);
bool read_wrench_state(const PortRef& port, double& stamp, std::string& frame_id, sensors::WrenchReading& out,
                       std::uint64_t* sequence);

// Trajectory controllers (controllers/trajectory/trajectory_goal.hpp explains the goal life).
bool write_trajectory(const PortRef& port, const control::JointTrajectory& trajectory, std::string* error);
bool read_trajectory_state(const PortRef& port, control::JointTrajectoryControllerState& out,
                           std::uint64_t* sequence);
struct GoalTicket {
  std::uint64_t id = 0;
  bool accepted = false;
  control::TrajectoryResult result;  // why it was rejected
};
// False when the port is not a goal port.
bool submit_goal(const PortRef& port, const control::FollowJointTrajectoryGoal& goal, GoalTicket& ticket);
bool cancel_goal(const PortRef& port, std::uint64_t id);
std::optional<control::GoalStatus> goal_status(const PortRef& port, std::uint64_t id);
std::optional<control::TrajectoryResult> goal_result(const PortRef& port, std::uint64_t id);
bool read_goal_feedback(const PortRef& port, control::FollowJointTrajectoryFeedback& out, std::uint64_t* sequence);
// query_state: the desired state of the controller's joints at `time` (s, simulation time).
// False with `error` set when the controller is not running or the port is not a query port.
struct TrajectorySample {
  std::vector<std::string> names;
  std::vector<double> position, velocity, acceleration;
};
bool query_trajectory(const PortRef& port, double time, TrajectorySample& out, std::string* error);

// The PR2 gripper (controllers/gripper/pr2_gripper_controller.hpp explains the goal life: Succeeded when
// reached, Aborted with stalled = true when it stalls first, Preempted by a cancel, a newer
// goal or a plain command).
bool write_gripper_command(const PortRef& port, double position, double max_effort, std::string* error);
struct GripperTicket {
  std::uint64_t id = 0;
  bool accepted = false;
  std::string error;  // why it was rejected
};
bool submit_gripper_goal(const PortRef& port, double position, double max_effort, GripperTicket& ticket);
bool cancel_gripper_goal(const PortRef& port, std::uint64_t id);
std::optional<control::GoalStatus> gripper_goal_status(const PortRef& port, std::uint64_t id);
std::optional<GripperStateData> gripper_goal_result(const PortRef& port, std::uint64_t id);
// The latest feedback (about goal `*goal_id`, 0: none yet) when newer than `*sequence`.
bool read_gripper_feedback(const PortRef& port, GripperStateData& out, std::uint64_t* goal_id, std::uint64_t* sequence);

// The PR2 laser tilt controller's profile (pr2_msgs/PeriodicCmd, LaserTrajCmd): profile by name
// ("linear", "blended_linear"; "sine" for periodic ones), rad, s. False (and `error` set) when
// the port refuses it; the previous profile stays.
bool write_periodic_command(const PortRef& port, const std::string& profile, double period, double amplitude,
                            double offset, std::string* error);
bool write_laser_traj_command(const PortRef& port, const std::string& profile, const std::vector<double>& positions,
                              const std::vector<double>& times_from_start, double max_velocity,
                              double max_acceleration, std::string* error);

}  // namespace mechsim::bridge
