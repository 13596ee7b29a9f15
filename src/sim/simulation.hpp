#pragma once
// One simulated robot in one world: physics + mechanism + controller manager, advanced by the
// tick of DESIGN.md at a fixed period (1 kHz by default):
//
//   1. physics joint positions/velocities/efforts -> mechanism joint state -> transmissions
//      backwards -> actuator state (what the encoders report);
//   2. controller manager update (transmissions forward, controllers, safety limits,
//      transmissions forward for the efforts);
//   3. actuator commands -> transmissions backwards -> joint commands -> physics (effort, or the
//      set point of the joint's implicit position/velocity servo);
//   4. one physics step; simulation time advances by exactly one period;
//   5. the mechanism state is read from the physics again, so that it describes the new time();
//      sensors that are due sample the new state (sensors()); then observers (publishers,
//      recorders) run; each decides whether it is due.
//
// Between ticks every state the simulation exposes (physics, mechanism state) describes time().
// Control observers run inside the tick, after step 3 and before the physics step: there the
// physics, the mechanism state, the controllers' states and the commands they just sent all
// describe time() (what a recorder wants: one row, one instant).
//
// Time: simulation time is ticks * period and never goes backwards. reset() puts the world and
// the robot back in the spawn state and restarts the running controllers, but time goes on
// (ROS nodes with use_sim_time treat a backwards jump as an error, and Gazebo's reset_world keeps
// time too; we chose one behaviour for both resets).
//
// Threads: step()/run_for() belong to one loop thread. pause(), unpause(), request_reset(),
// request_steps() and post() may be called from any thread; the loop applies them between ticks
// (at the start of step(), and every millisecond while run_for() waits paused), so that the tick
// stays the only writer of the simulation's state.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "control/controller_manager.hpp"
#include "control/params.hpp"
#include "description/robot_model.hpp"
#include "mechanism/mechanism_model.hpp"
#include "physics/physics.hpp"
#include "physics/physics_model.hpp"
#include "sensors/sensor_set.hpp"
#include "sim/external_forces.hpp"
#include "sim/pid_gains_drive.hpp"
#include "sim/sensor_handles.hpp"
#include "sim/world.hpp"

namespace mechsim::control {
struct ModelPluginBuild;  // controllers/plugins/model_plugins.hpp
}  // namespace mechsim::control

namespace mechsim::sim {

// What the loop does when the physics diverges (NaN/inf state, runaway acceleration).
enum class DivergencePolicy { Stop, Reset };

struct SimulationOptions {
  double period = 0.001;  // s: physics step = control period
  // MuJoCo's integrator (see physics::BuildOptions for the measured trade-off).
  physics::Integrator integrator = physics::BuildOptions{}.integrator;
  physics::DifferentialMode differential = physics::DifferentialMode::MimicConstraint;
  // Spawn pose of the root link. On terrain, z is measured from the ground under (x, y).
  physics::SpawnPose spawn;
  // On a height field, stand a floating robot on the ground plane fitted under its footprint:
  // roll and pitch from the plane's normal (spawn.roll and spawn.pitch are ignored, spawn.yaw
  // stays the heading) and spawn.z measured along the normal from the plane under (x, y). A robot
  // spawned level on a steep slope lands hard and tips. Nothing changes on level ground (a
  // fitted slope under 1e-4 rad, which float heights of a level pad can reach) or on `empty`.
  // Scenarios turn it on unless they give roll or pitch.
  bool settle_on_ground = false;
  // Initial joint positions (rad or m) by physics joint name, as Gazebo's spawn_model -J: set
  // before the first tick and again by reset(). An unknown joint is an error.
  std::map<std::string, double> initial_joints;
  bool start_paused = false;
  // s: simulation time at construction (rounded to a whole number of periods). A robot spawned
  // into a world that has been running goes on from the world's time: ROS nodes with
  // use_sim_time take a backwards jump as an error.
  double start_time = 0.0;
  // 0: as fast as possible (headless default); R > 0: paced so that simulation time runs R times
  // as fast as wall-clock time. The pace is kept across run_for() calls against one wall-clock
  // anchor (a caller that runs in short chunks, like the ROS node, loses nothing between them);
  // the anchor moves only on pause, on a new factor, and when the simulation falls more than
  // kMaxPaceLag behind (it then goes on from there instead of racing to catch up).
  double real_time_factor = 0.0;
  DivergencePolicy on_divergence = DivergencePolicy::Stop;
  // Gains of the implicit servo of joints commanded through position/velocity interfaces, by
  // joint name (a test's or a tuning run's). Missing: the physics default. Joints with
  // gazebo_ros_control pid_gains (see parameter_root) are driven by that PID instead.
  std::map<std::string, physics::ServoGains> servo_gains;
  // The root of the parameter tree the controller parameters belong to (standalone: the whole
  // controllers YAML; ROS: what the node fetched from the server), where gazebo_ros_control's
  // pid_gains are looked up at the path its plugin element gives (sim/pid_gains_drive.hpp). None:
  // the controller parameters are the root.
  std::optional<control::Params> parameter_root;
  // MuJoCo's contact and constraint arena (physics::BuildOptions): nullopt sizes it from the model;
  // a tick that needs more grows it (reported in physics_warnings()) or, with Fail, stops the run.
  std::optional<physics::ArenaSize> arena;
  physics::ArenaOverflow arena_overflow = physics::ArenaOverflow::Grow;
  // Cheaper ways to the same MuJoCo step (physics::StepCost; all on by default).
  physics::StepCost step_cost;
  // The robot's sensors (RobotModel::sensors) are simulated at their rates (sensors/sensor_set.hpp);
  // false leaves them out (a benchmark's "without sensors"). Their noise is seeded from
  // sensor_seed: the same seed gives bit-identical readings.
  bool sensors = true;
  std::uint64_t sensor_seed = 1;
  // ros2_control (sim/ros2_control_config.hpp): the controller parameters are a ROS 2 controller
  // manager's (control::Ros2ControlSetup::controllers) and its types ros2_controllers'
  // (controllers/ros2_control/ros2_controllers.hpp, over mechsim's built-in ones).
  bool ros2_control = false;
  // Hz: ros2_control's update_rate. The manager updates every round(1 / (rate * period)) ticks
  // (at least every tick) with that period, commands held and written every tick in between, as
  // gazebo_ros2_control updates it (read and update once the control period has passed, write
  // every step); a controller's own update_rate runs it slower (ControllerManager::
  // set_update_rate). 0: every tick (or gazebo_ros_control's controlPeriod).
  double controller_update_rate = 0.0;
};

// Another robot in the same world (Gazebo's second spawned model): the simulation that holds it
// ticks it with its own robot, around the one physics step (Simulation::other()). Its names in
// the physics are "<name>::<joint>", "<name>::<link>" (physics::WorldModel::actuated).
struct OtherRobot {
  std::string name;  // unique in the world, the robot's namespace; no "::" in it
  description::RobotModel robot;
  // Its controllers' parameters (the namespace holding them, as for the first robot) and the
  // tree gazebo_ros_control's pid_gains are looked up in (none: the controller parameters).
  control::Params controllers;
  std::optional<control::Params> parameter_root;
  physics::SpawnPose spawn;  // X_W<root>; on terrain, z from the ground under (x, y)
  // Initial joint positions by the robot's own joint names (spawn_model -J).
  std::map<std::string, double> initial_joints;
  // Its controllers are ros2_control's (SimulationOptions::ros2_control, controller_update_rate).
  bool ros2_control = false;
  double controller_update_rate = 0.0;
};

// Wall-clock seconds the paced simulation may fall behind its anchor before it gives up
// catching up (a stalled process, a debugger, a slower-than-real-time model).
inline constexpr double kMaxPaceLag = 0.25;

struct TickResult {
  bool ok = true;
  std::string error;  // set when the physics diverged or its arena was full: what, where, when
  explicit operator bool() const { return ok; }
};

// Fills, for every controller under `controllers`, the parameters its type takes from the robot
// description where they are absent (rover drive and PR2 base/odometry geometry; ros_controllers'
// diff drive geometry unless `ros2_control`: ros2_controllers' reads no description).
void fill_description_params(const control::Params& controllers, const description::RobotModel& robot,
                             bool ros2_control = false);

class Simulation {
 public:
  using Observer = std::function<void(const Simulation&)>;

  // Builds the physics of `robot` in `world`, its mechanism and its controller manager over
  // `controller_params` (the namespace holding the controllers, e.g. the `cc8` map of a YAML).
  // Throws on a description the physics, the mechanism or its model plugins cannot build (a model
  // plugin's error names its file, line and plugin).
  // `others`: more robots in the same world, each with its own mechanism, controller manager and
  // model plugins and sensors (other()); they collide with this robot and each other. With
  // options.settle_on_ground they stand on a terrain's slope as this robot does, here and when
  // add_other() spawns them.
  Simulation(description::RobotModel robot, const World& world, control::Params controller_params,
             SimulationOptions options = {}, std::vector<OtherRobot> others = {});
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // One tick, whether paused or not (single step). Applies pending requests first.
  TickResult step();
  // Ticks until `duration` seconds of simulation time have passed, pacing to the real-time
  // factor. While paused it waits (a paused run with no other thread to unpause returns at
  // once). Stops early and returns the error when the physics diverges under Stop.
  TickResult run_for(double duration);

  void pause() { paused_.store(true); }
  void unpause() { paused_.store(false); }
  bool paused() const { return paused_.load(); }
  void request_reset() { reset_requested_.store(true); }
  // gazebo_ros_control's e-stop (its <eStopTopic>; any thread). While active, the tick still runs
  // the controllers but writes no effort, zero velocity, and for position-commanded joints the
  // position each had when the e-stop came (pid_gains joints: their PID towards those); model
  // plugins are not affected. On release the running controllers are stopped and started again
  // at the next controller update (ros_control's reset_controllers), e.g. to hold where they are.
  void set_e_stop(bool active) { e_stop_requested_.store(active, std::memory_order_release); }
  bool e_stop_active() const { return e_stop_requested_.load(std::memory_order_acquire); }
  // The e-stop topic of the description's gazebo_ros_control plugin ("" when it names none).
  const std::string& e_stop_topic() const { return e_stop_topic_; }
  // Asks for `count` more ticks while paused (ROS 2's StepSimulation; run_for() ticks them while it
  // waits paused). pending_steps() counts down as they run.
  void request_steps(std::uint64_t count) { pending_steps_.fetch_add(count); }
  std::uint64_t pending_steps() const { return pending_steps_.load(); }
  void cancel_steps() { pending_steps_.store(0); }
  // A command to run in the loop thread between ticks (with the simulation to change or read).
  // Commands run in the order posted; one that throws is caught and its message dropped, so
  // commands report through what they capture.
  using Command = std::function<void(Simulation&)>;
  void post(Command command);
  // Waits (at most `timeout` s of wall time) until every command posted before the call has run.
  bool wait_for_commands(double timeout);
  // Back to the spawn state now (loop thread only).
  void reset();

  double time() const { return static_cast<double>(ticks_) * options_.period; }  // s
  double period() const { return options_.period; }
  std::uint64_t ticks() const { return ticks_; }
  std::uint64_t resets() const { return resets_; }
  std::uint64_t divergences() const { return divergences_; }
  // Simulation seconds per wall-clock second over the last run_for().
  double measured_real_time_factor() const { return measured_rtf_; }
  void set_real_time_factor(double factor) {
    options_.real_time_factor = factor;
    pace_anchored_ = false;
  }

  // The other robots of the world (OtherRobot), in the order given. Each is a Simulation of its
  // own robot over the shared physics: its mechanism, controllers, state_changed() and posted
  // commands are its own; time, pause, reset and stepping are this simulation's (its step() and
  // run_for() throw std::logic_error; its reset() and request_reset() reset the whole world).
  // Spawns another robot into the running world (loop thread: between ticks or in a posted
  // command): the physics is rebuilt with it, every robot and object going on from where it
  // was, at the same time, its controllers untouched (Physics::take_state_from). Throws, changing
  // nothing, on a robot that cannot be built or a name in use.
  Simulation& add_other(OtherRobot other);
  // Deletes an other robot (loop thread): its controllers are stopped and unloaded first, then
  // the physics is rebuilt without it, the rest going on as above. False when there is none.
  bool remove_other(const std::string& name);
  std::size_t other_count() const { return others_.size(); }
  Simulation& other(std::size_t i) { return *others_.at(i); }
  const Simulation& other(std::size_t i) const { return *others_.at(i); }
  Simulation* find_other(const std::string& name);
  // "" for the first robot; an other robot's name.
  const std::string& robot_name_in_world() const { return name_; }
  // The physics' name of this robot's joint or link `name` ("<name>::<name>" for an other robot).
  std::string physics_name(const std::string& name) const { return prefix_ + name; }
  // X_W<root link> now.
  description::Pose base_pose() const;
  // The root link floats (not fixed to the world).
  bool floating() const { return floating_; }
  // Counts the world's physics rebuilds (add_other, remove_other): indices into physics().model()
  // kept from before a change of it are stale. The same for every robot of the world.
  std::uint64_t physics_generation() const { return host_ != nullptr ? host_->generation_ : generation_; }
  // The simulation that ticks this robot: itself for the first robot, the host for an other one.
  Simulation& world_host() { return host_ != nullptr ? *host_ : *this; }
  const Simulation& world_host() const { return host_ != nullptr ? *host_ : *this; }

  const description::RobotModel& robot() const { return robot_; }
  const World& world() const { return world_; }
  const SimulationOptions& options() const { return options_; }
  // X_W<root> at spawn (and after reset()): options().spawn on the ground, settled on a slope.
  const description::Pose& spawn_pose() const { return spawn_pose_; }
  physics::Physics& physics() { return *physics_; }
  const physics::Physics& physics() const { return *physics_; }
  const mechanism::MechanismModel& mechanism() const { return *mechanism_; }
  const mechanism::MechanismState& mechanism_state() const { return *mechanism_state_; }
  control::ControllerManager& controllers() { return *manager_; }
  const control::ControllerManager& controllers() const { return *manager_; }
  // The simulated sensors and their latest readings (sampled in step 5 of each tick, before the
  // observers run; every one once at construction and after reset()).
  sensors::SensorSet& sensors() { return sensors_; }
  const sensors::SensorSet& sensors() const { return sensors_; }
  // Forces from outside (Gazebo's apply_body_wrench, apply_joint_effort), applied before each
  // physics step while any is queued; reset() clears them, and so does deleting an other robot
  // (they are held by physics index). Only the first robot's are applied: forces on an other
  // robot go into world_host().external_forces() under its physics names. Loop thread (a posted
  // command).
  ExternalForces& external_forces() { return external_; }
  // After a command wrote the physics state (a pose, joint positions): the mechanism state and
  // the sensors are brought to it, so that they describe time() again. Loop thread.
  void state_changed();

  // What the physics reported without failing a tick (physics::PhysicsNotice: its arena grew, a
  // MuJoCo warning), each as "tick N (t = T s): what" ("spawn (t = 0 s): " for the spawn state),
  // with how often it recurred; then the sensors left out, and the Gazebo model plugins mechsim
  // does not simulate (once each: controllers/plugins/model_plugins.hpp).
  std::vector<std::string> physics_warnings() const;
  // A configuration note physics_warnings() reports with the plugins' (a ros2_control parameter
  // file's: sim/ros2_control_config.hpp).
  void add_note(std::string note) { plugin_notes_.push_back(std::move(note)); }
  // Per joint with a position or velocity interface, how its commands reach the physics:
  // gazebo_ros_control's PID (pid_gains) or mechsim's servo, with the parameter path read.
  const std::vector<std::string>& joint_drive_notes() const { return pid_drive_.notes(); }
  // s between controller manager updates: gazebo_ros_control's <controlPeriod> rounded to whole
  // ticks (at least one), else period(). Commands are held in between and written to the
  // physics every tick (the pid_gains PIDs run every tick), as its writeSim does; the model
  // plugins, which the manager runs, update at this period too.
  double control_period() const { return static_cast<double>(control_every_) * options_.period; }

  // Time of the constructor's stages (wall-clock and CPU).
  struct StartupTimes {
    physics::StageTime mjcf;       // physics model: body plan, meshes, MJCF (physics::BuildTimes)
    physics::StageTime compile;    // physics model: MuJoCo's compiler, terrain, arena estimate
    physics::StageTime data;       // the physics instance: model copy and MuJoCo data (the arena)
    physics::StageTime mechanism;  // spawn pose, mechanism, controller manager, reflected inertia
    physics::StageTime sensors;    // the robot's sensors set up and sampled once (cameras' lens maps)
  };
  const StartupTimes& startup_times() const { return startup_times_; }

  // Rotor inertia the simulation added to joints whose safety controller would be unstable at
  // this period (see add_reflected_inertia_for_safety_limits): joint name and the joint's
  // armature now (kg m^2 or kg). Empty for most robots; the PR2's torso is the usual one.
  struct AddedInertia {
    std::string joint;
    double armature = 0.0;
  };
  const std::vector<AddedInertia>& reflected_inertia() const { return reflected_inertia_; }

  // Observers run after every tick, in the loop thread, in the order added.
  void add_observer(Observer observer) { observers_.push_back(std::move(observer)); }
  // Control observers run in every tick after the controllers' update and the commands' write,
  // before the physics step (see the top of this file), in the loop thread, in the order added.
  void add_control_observer(Observer observer) { control_observers_.push_back(std::move(observer)); }

  // Loads a controller from the controller parameters, first filling what its type takes from
  // the robot description where the parameters leave it out (the rover drive's and the PR2
  // base's geometry), so that parameters loaded after construction (a ROS spawner) get it too.
  control::ControlResult load_controller(const std::string& name);

  // Loads the named controllers and starts them with a STRICT switch applied at once (before
  // the next tick). Throws std::runtime_error naming the controller on failure.
  void load_and_start(const std::vector<std::string>& controllers);

 private:
  // An other robot of `host`'s world (`host`'s physics already holds it).
  Simulation(Simulation& host, OtherRobot other);
  // The robot's mechanism, controller manager, model plugins and sensors over the physics.
  void build_robot(control::Params controller_params);
  // The tick's steps 1-3 (state read, controllers, commands written) and step 5's state read and
  // sensors, for this robot.
  void control_phase();
  void sense_phase();
  // reset() for this robot, after the physics was reset.
  void reset_robot();
  // The world's physics rebuilt with `others` (Physics::take_state_from), and every robot bound to it.
  // `arriving`: a robot that comes in with this rebuild, fitted to the terrain's slope under it.
  void rebuild_physics(const std::vector<OtherRobot>& others, const OtherRobot* arriving = nullptr);
  // This robot's joints and root looked up in the (new) physics.
  void bind_physics();
  std::vector<OtherRobot> other_specs() const;  // what rebuilds the others' part of the physics
  std::vector<std::string> earlier_notices_;  // physics warnings of physics since rebuilt
  std::vector<std::string> physics_warnings_of_physics() const;  // the physics' notices, dated
  physics::BuildOptions build_;  // the physics' build options (the first robot's)
  // The cameras' render model: the physics model with the terrain's render tiles (none needed
  // without cameras or terrain).
  sensors::RenderModelFactory render_factory() const;
  void read_physics();
  void write_physics();
  void add_model_plugins(std::vector<control::ModelPluginBuild>& plugins);
  void make_velocity_motors();
  void apply_requests();
  void apply_initial_joints();
  void settle_on_ground();
  // The spawn pose on the ground plane fitted under `robot` (its collision bounds, spawned level)
  // at `spawn`; none on level ground or without a terrain.
  std::optional<description::Pose> fitted_spawn(const physics::Bounds& robot, const physics::SpawnPose& spawn) const;
  // An other robot in a just-built `physics` fitted so (settle_on_ground's rule for it).
  void fit_to_ground(const physics::PhysicsModel& model, physics::Physics& physics, const OtherRobot& other) const;

  description::RobotModel robot_;
  std::string name_, prefix_;       // an other robot's name and "<name>::"; "" for the first
  Simulation* host_ = nullptr;      // an other robot's: the simulation that ticks it
  std::optional<std::size_t> root_link_;  // an other robot's root link in the physics
  bool floating_ = false;           // the root floats (not fixed to the world)
  std::vector<std::unique_ptr<Simulation>> others_;
  World world_;
  SimulationOptions options_;
  description::Pose spawn_pose_;
  std::shared_ptr<const physics::PhysicsModel> physics_model_;
  std::shared_ptr<physics::Physics> physics_;  // shared with the other robots
  std::unique_ptr<mechanism::MechanismModel> mechanism_;
  std::unique_ptr<mechanism::MechanismState> mechanism_state_;
  std::unique_ptr<control::ControllerManager> manager_;
  sensors::SensorSet sensors_;
  SensorHandles sensor_handles_;  // the controllers' IMU and force-torque handles over sensors_

  // Per mechanism joint: the physics joint (-1 when the physics has none) and the mode the
  // physics servo is in, so modes switch only on change.
  std::vector<int> physics_joint_;
  std::vector<mechanism::HardwareInterface> physics_mode_;
  std::vector<double> physics_effort_limit_;  // JointState::effort_limit as the physics has it
  std::vector<physics::ServoGains> servo_gains_;
  std::vector<bool> commanded_;  // the physics applies this joint's command (actuated joints)
  PidGainsDrive pid_drive_;  // gazebo_ros_control's pid_gains, per mechanism joint
  std::vector<double> effort_scale_;  // applied effort = scale * commanded effort (1 but for fingers)

  // A PR2 gripper whose gap joint the physics dropped (URDF: a prismatic joint to a massless
  // frame; Gazebo closes it as a loop between the finger tips). The physics moves the passive
  // finger joints instead: the mimic leader takes the transmission's finger commands, and the gap state is
  // computed from the driven fingers' angle with the transmission's linkage.
  struct GapFromFingers {
    int gap = -1;              // mechanism joint
    std::vector<int> fingers;  // mechanism joints of every passive finger the physics has
    std::vector<int> measured;  // the driven ones, whose mean angle gives the gap
    double t0 = 0.0, r = 0.0, theta0 = 0.0;  // linkage: half gap offset (m), finger length (m), rad
  };
  std::vector<GapFromFingers> gap_from_fingers_;
  void read_gaps_from_fingers();

  std::vector<AddedInertia> reflected_inertia_;
  std::vector<std::string> plugin_notes_;  // model plugins mechsim does not simulate, one line each
  void add_reflected_inertia_for_safety_limits();

  // Sleeps until the wall-clock time at which the current simulation time is due (loop thread).
  void pace();

  std::vector<Observer> observers_, control_observers_;
  // Pacing anchor: simulation time `pace_sim_` was due at wall time `pace_wall_`.
  bool pace_anchored_ = false;
  std::chrono::steady_clock::time_point pace_wall_{};
  double pace_sim_ = 0.0;
  std::vector<std::uint64_t> notice_ticks_;  // the tick that raised each physics notice
  StartupTimes startup_times_;
  std::uint64_t ticks_ = 0, resets_ = 0, divergences_ = 0;
  std::uint64_t generation_ = 0;  // physics rebuilds (the first robot's)
  // The controller manager updates on ticks that are multiples of this (gazebo_ros_control's
  // <controlPeriod> in ticks; 1 without one).
  std::uint64_t control_every_ = 1;
  double measured_rtf_ = 0.0;
  std::atomic<bool> paused_{false};
  std::atomic<bool> reset_requested_{false};
  // E-stop: requested (any thread), in force in this tick, the positions latched when it came,
  // and a controller restart owed to its release (done at the next controller update).
  std::atomic<bool> e_stop_requested_{false};
  bool e_stop_ = false;
  bool restart_controllers_ = false;
  std::vector<double> e_stop_position_;  // per mechanism joint
  std::string e_stop_topic_;
  std::atomic<std::uint64_t> pending_steps_{0};
  ExternalForces external_;
  // Posted commands: the tick looks at the flag only; the lock is taken when there are some.
  std::mutex commands_mutex_;
  std::condition_variable commands_done_;
  std::vector<Command> commands_;
  std::uint64_t commands_posted_ = 0, commands_run_ = 0;  // under commands_mutex_
  std::atomic<bool> have_commands_{false};
  void run_commands();
};

}  // namespace mechsim::sim
