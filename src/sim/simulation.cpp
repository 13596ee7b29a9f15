#include "sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "controllers/builtin_controllers.hpp"
#include "controllers/ros2_control/ros2_controllers.hpp"
#include "description/ros2_control.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "controllers/drive/diff_drive_params.hpp"
#include "controllers/drive/pr2_base_params.hpp"
#include "controllers/drive/rover_drive_params.hpp"
#include "description/ros_control_plugin.hpp"
#include "description/sensor_spec.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/direct_joints.hpp"
#include "mechanism/pr2_gripper_transmission.hpp"
#include "mechanism/propagation.hpp"
#include "physics/heightmap_sample.hpp"
#include "physics/transform.hpp"
#include "sim/ground_plane.hpp"
#include "sim/ros2_control_config.hpp"

namespace mechsim::sim {

namespace {

using mechanism::HardwareInterface;

physics::BuildOptions build_options(const World& world, const SimulationOptions& options,
                                    const std::vector<OtherRobot>& others) {
  physics::BuildOptions b;
  b.timestep = options.period;
  b.integrator = options.integrator;
  b.differential = options.differential;
  b.world = world.spec;
  b.spawn = options.spawn;
  b.arena = options.arena;
  b.arena_overflow = options.arena_overflow;
  b.step_cost = options.step_cost;
  if (world.spec.terrain) b.spawn.z += physics::height_at(*world.spec.terrain, b.spawn.x, b.spawn.y);
  for (const OtherRobot& o : others) {
    if (o.name.empty() || o.name.find("::") != std::string::npos)
      throw std::invalid_argument("other robot '" + o.name + "': a robot's name must be non-empty, without '::'");
    physics::WorldModel m;
    m.name = o.name;
    m.robot = std::make_shared<const description::RobotModel>(o.robot);
    const physics::SpawnPose& at = o.spawn;
    const double ground = world.spec.terrain ? physics::height_at(*world.spec.terrain, at.x, at.y) : 0.0;
    m.pose = {{at.x, at.y, at.z + ground}, physics::quat_from_rpy(at.roll, at.pitch, at.yaw)};
    m.actuated = true;
    b.world.models.push_back(std::move(m));
  }
  return b;
}

// Cameras draw a height field from render tiles at the detail each view needs (physics/renderer.hpp),
// in a model of their own (sensors/render_hub.hpp says why).
bool has_cameras(const description::RobotModel& robot) {
  return std::any_of(robot.sensors.begin(), robot.sensors.end(),
                     [](const description::SensorSpec& s) { return std::holds_alternative<description::CameraSpec>(s.details); });
}

}  // namespace

void fill_description_params(const control::Params& controllers, const description::RobotModel& robot, bool ros2_control) {
  control::fill_rover_drive_geometry_all(controllers, robot);
  control::fill_pr2_base_geometry_all(controllers, robot);
  // ros2_controllers' diff drive reads no robot description.
  if (!ros2_control) control::fill_diff_drive_geometry_all(controllers, robot);
}

control::ControlResult Simulation::load_controller(const std::string& name) {
  try {
    if (std::optional<control::Params> p = manager_->params().find(name); p && p->is_map()) {
      const std::string type = p->get<std::string>("type", "");
      if (type == control::kRoverDriveControllerType) control::fill_rover_drive_geometry(*p, robot_);
      // ros2_controllers' diff drive reads no robot description.
      if (type == control::kDiffDriveControllerType && !options_.ros2_control) control::fill_diff_drive_geometry(*p, robot_);
      if (type == control::kPr2BaseController2Type || type == control::kPr2BaseControllerType ||
          type == control::kPr2OdometryType) {
        control::fill_pr2_base_geometry(*p, robot_);
      }
    }
  } catch (const std::exception& e) {
    return control::ControlResult::failure(e.what());
  }
  return manager_->load_controller(name);
}

Simulation::Simulation(description::RobotModel robot, const World& world, control::Params controller_params,
                       SimulationOptions options, std::vector<OtherRobot> others)
    : robot_(std::move(robot)), world_(world), options_(std::move(options)) {
  if (!(options_.period > 0.0) || options_.period > 0.1) {
    throw std::invalid_argument("simulation period must be in (0, 0.1] s, got " + std::to_string(options_.period));
  }
  if (!(options_.start_time >= 0.0) || !std::isfinite(options_.start_time)) {
    throw std::invalid_argument("simulation start time must be finite and >= 0 s");
  }
  ticks_ = static_cast<std::uint64_t>(std::llround(options_.start_time / options_.period));
  // ros2_control's initial_value: where Gazebo's systems put the joints at load (a scenario's or
  // spawn_model's -J wins).
  for (const auto& [joint, position] : description::ros2_control_initial_positions(robot_)) {
    options_.initial_joints.emplace(joint, position);
  }
  if (!(options_.real_time_factor >= 0.0)) {
    throw std::invalid_argument("real-time factor must be >= 0 (0: as fast as possible)");
  }
  const physics::BuildOptions build = build_options(world_, options_, others);
  physics_model_ = physics::PhysicsModel::build(robot_, build);
  startup_times_.mjcf = physics_model_->build_times().mjcf;
  startup_times_.compile = physics_model_->build_times().compile;
  physics::StageTimer timer;
  physics_ = std::make_shared<physics::Physics>(physics_model_);
  physics_->set_soil(world_.soil, world_.wheels);
  startup_times_.data = timer.lap();
  if (options_.settle_on_ground && world_.spec.terrain && !physics_model_->fixed_to_world()) settle_on_ground();
  if (options_.settle_on_ground)
    for (const OtherRobot& o : others) fit_to_ground(*physics_model_, *physics_, o);
  floating_ = !physics_model_->fixed_to_world();
  spawn_pose_ = physics_->base_pose();
  startup_times_.mechanism = timer.lap();
  build_ = build;
  build_robot(std::move(controller_params));
  for (OtherRobot& o : others) others_.push_back(std::unique_ptr<Simulation>(new Simulation(*this, std::move(o))));
}

description::Pose Simulation::base_pose() const {
  return root_link_ ? physics_->link_pose(*root_link_) : physics_->base_pose();
}

void Simulation::bind_physics() {
  physics_model_ = host_ != nullptr ? host_->physics_model_ : physics_model_;
  physics_ = host_ != nullptr ? host_->physics_ : physics_;
  if (host_ != nullptr) {
    root_link_ = physics_model_->link_index(prefix_ + robot_.root_link);
    if (!root_link_) throw std::logic_error("other robot '" + name_ + "': its root link is not in the physics");
  }
  for (std::size_t j = 0; j < physics_joint_.size(); ++j) {
    const auto p = physics_model_->joint_index(prefix_ + mechanism_->joints[j].name);
    physics_joint_[j] = p && physics_model_->joints()[*p].actuated ? static_cast<int>(*p) : -1;
  }
  sensors_.set_model(physics_model_, render_factory());
}

void Simulation::rebuild_physics(const std::vector<OtherRobot>& others, const OtherRobot* arriving) {
  const physics::BuildOptions build = build_options(world_, options_, others);
  auto model = physics::PhysicsModel::build(robot_, build);
  auto physics = std::make_shared<physics::Physics>(model);
  if (arriving != nullptr) fit_to_ground(*model, *physics, *arriving);
  physics->take_state_from(*physics_);
  // Nothing below throws: the world changes as a whole or not at all.
  for (const std::string& w : physics_warnings_of_physics()) earlier_notices_.push_back(w);
  notice_ticks_.clear();
  physics_model_ = std::move(model);
  physics_ = std::move(physics);
  build_ = build;
  ++generation_;
  bind_physics();
  for (const auto& o : others_) o->bind_physics();
}

sensors::RenderModelFactory Simulation::render_factory() const {
  if (!has_cameras(robot_) || !world_.spec.terrain) return {};
  // The world's model (the first robot's, which holds the others): what every camera sees.
  const Simulation& world = world_host();
  return [robot = world.robot_, b = world.build_]() mutable {
    b.render_terrain = true;
    return physics::PhysicsModel::build(robot, b);
  };
}

void Simulation::build_robot(control::Params controller_params) {
  physics::StageTimer timer;
  mechanism_ = std::make_unique<mechanism::MechanismModel>(mechanism::build_mechanism(robot_));
  // The model plugins' controllers; the joints they drive or read join the mechanism.
  std::vector<control::ModelPluginBuild> plugins =
      control::build_model_plugins(robot_, control::PluginContext{robot_.name, controller_params});
  for (const control::ModelPluginBuild& b : plugins) mechanism::add_direct_joints(*mechanism_, robot_, b.joints);
  for (const control::ModelPluginStatus& status : control::model_plugin_status(robot_)) {
    if (!status.simulated()) plugin_notes_.push_back(control::describe(status));
  }
  mechanism_state_ = std::make_unique<mechanism::MechanismState>(mechanism::make_state(*mechanism_));
  mechanism_state_->base.floating = floating_;
  fill_description_params(controller_params, robot_, options_.ros2_control);
  // gazebo_ros_control's plugin element: its pid_gains (read now, as DefaultRobotHWSim reads them
  // at load) and a RobotHWSim mechsim cannot load.
  const std::optional<description::RosControlPlugin> ros_control = description::find_ros_control_plugin(robot_);
  if (ros_control && !ros_control->default_hw()) {
    plugin_notes_.push_back(ros_control->origin + ": gazebo_ros_control robotSimType '" + ros_control->robot_sim_type +
                            "' is not simulated (mechsim cannot load a RobotHWSim plugin): the transmissions' joints get " +
                            description::kDefaultRobotHWSim + "'s behaviour instead");
  }
  pid_drive_ = PidGainsDrive(*mechanism_, ros_control, options_.parameter_root.value_or(controller_params));
  if (ros_control) e_stop_topic_ = ros_control->e_stop_topic;
  if (ros_control && ros_control->control_period) {
    const double wanted = *ros_control->control_period;
    const long long n = std::llround(wanted / options_.period);
    control_every_ = static_cast<std::uint64_t>(std::max(1LL, n));
    char note[1024];
    if (wanted < options_.period) {
      std::snprintf(note, sizeof note, "%s: gazebo_ros_control controlPeriod %g s is shorter than the period %g s: "
                    "the controllers update every tick", ros_control->origin.c_str(), wanted, options_.period);
      plugin_notes_.emplace_back(note);
    } else if (std::abs(control_period() - wanted) > 1e-9 * wanted) {
      std::snprintf(note, sizeof note, "%s: gazebo_ros_control controlPeriod %g s is not a whole number of periods "
                    "(%g s): the controllers update every %g s", ros_control->origin.c_str(), wanted, options_.period,
                    control_period());
      plugin_notes_.emplace_back(note);
    }
  }
  if (options_.controller_update_rate > 0.0) {
    std::string note;
    control_every_ = ros2_control_ticks(options_.controller_update_rate, options_.period, &note);
    if (!note.empty()) plugin_notes_.push_back(std::move(note));
  }
  manager_ = std::make_unique<control::ControllerManager>(
      *mechanism_, *mechanism_state_, std::move(controller_params),
      options_.ros2_control ? control::ros2_controller_registry() : control::controller_registry_with_plugins());
  if (options_.ros2_control) manager_->set_update_rate(options_.controller_update_rate > 0.0 ? 1.0 / control_period() : 1.0 / options_.period);

  const std::size_t n = mechanism_->joints.size();
  physics_joint_.assign(n, -1);
  physics_mode_.assign(n, HardwareInterface::Effort);
  e_stop_position_.assign(n, 0.0);
  physics_effort_limit_.assign(n, 0.0);
  servo_gains_.assign(n, physics::ServoGains{});
  commanded_.assign(n, false);
  effort_scale_.assign(n, 1.0);
  for (std::size_t j = 0; j < n; ++j) {
    const std::string& name = mechanism_->joints[j].name;
    if (auto p = physics_model_->joint_index(prefix_ + name); p && physics_model_->joints()[*p].actuated) {
      physics_joint_[j] = static_cast<int>(*p);
      commanded_[j] = mechanism::physics_applies_command(mechanism_->joints[j]);
    }
    if (auto it = options_.servo_gains.find(name); it != options_.servo_gains.end()) servo_gains_[j] = it->second;
  }
  // PR2 grippers without a gap joint in the physics are driven through their fingers.
  for (const auto& t : mechanism_->transmissions) {
    const auto* gripper = dynamic_cast<const mechanism::Pr2GripperTransmission*>(t.get());
    if (gripper == nullptr || physics_joint_[static_cast<std::size_t>(gripper->joints()[0])] >= 0) continue;
    GapFromFingers g;
    g.gap = gripper->joints()[0];
    g.t0 = gripper->geometry().t0;
    g.r = gripper->geometry().r;
    g.theta0 = gripper->geometry().theta0;
    for (const int f : gripper->joints()) {
      const auto fi = static_cast<std::size_t>(f);
      if (mechanism_->joints[fi].role != mechanism::JointRole::Passive || physics_joint_[fi] < 0) continue;
      g.fingers.push_back(f);
    }
    if (g.fingers.empty()) continue;  // nothing moves: the gap stays at rest, as before
    // The drive goes to the fingers hinged on the gripper itself (the PR2's l/r_finger_joint),
    // carrying every finger's share; the finger tips, hinged on the fingers, follow through the
    // mimic constraints (a torque on a tip would twist it against them when the pads meet an
    // object). Fingers and tips move together, so the drive's power is the same.
    std::vector<int> driven;
    const auto parent_of = [&](int f) -> const description::Joint* {
      return robot_.joint(mechanism_->joints[static_cast<std::size_t>(f)].name);
    };
    for (const int f : g.fingers) {
      const description::Joint* jf = parent_of(f);
      bool on_a_finger = false;
      for (const int other : g.fingers) {
        const description::Joint* jo = parent_of(other);
        if (jf != nullptr && jo != nullptr && jo->child_link == jf->parent_link) on_a_finger = true;
      }
      if (!on_a_finger) driven.push_back(f);
    }
    if (driven.empty()) driven = g.fingers;
    g.measured = driven;  // collocated with the drive
    const double share = static_cast<double>(g.fingers.size()) / static_cast<double>(driven.size());
    for (const int f : driven) {
      commanded_[static_cast<std::size_t>(f)] = true;
      effort_scale_[static_cast<std::size_t>(f)] = share;
    }
    // The gripper motor's reflected inertia, which dominates the real gripper's dynamics, is not
    // in the description (Gazebo has the gap joint's own damping instead); without it the
    // fingers weigh ~0.07 kg at the gap and the PR2's gap gains (PID d = 1000 N s/m, safety
    // k_velocity = 5000 N s/m, applied explicitly once per tick) make them chatter. We give the
    // gap a mass of 2 k_velocity * period (10 kg for the PR2 at 1 kHz: explicit damping ratio
    // k dt / m = 0.5), as armature of the driven fingers at the closed linkage.
    const mechanism::JointInfo& gap_info = mechanism_->joints[static_cast<std::size_t>(g.gap)];
    if (gap_info.safety && gap_info.safety->k_velocity > 0.0) {
      const double gap_mass = 2.0 * gap_info.safety->k_velocity * options_.period;  // kg
      const double dx_dq = 2.0 * g.r * std::cos(g.theta0);                            // m/rad
      const double armature = gap_mass * dx_dq * dx_dq / static_cast<double>(driven.size());
      for (const int f : driven)
        physics_->set_armature(static_cast<std::size_t>(physics_joint_[static_cast<std::size_t>(f)]), armature);
    }
    gap_from_fingers_.push_back(std::move(g));
  }
  add_reflected_inertia_for_safety_limits();
  // After the armatures: they are computed at the zero configuration, as before spawn joints existed.
  apply_initial_joints();
  paused_.store(options_.start_paused);
  read_physics();
  add_model_plugins(plugins);
  make_velocity_motors();
  if (host_ == nullptr) notice_ticks_.assign(physics_->notices().size(), 0);  // raised by the spawn state: tick 0
  startup_times_.mechanism += timer.lap();
  if (options_.sensors) {
    sensors_ = sensors::SensorSet(robot_.sensors, physics_model_, options_.sensor_seed, render_factory(), prefix_);
    sensors_.sample_all(*physics_, time());
    sensor_handles_ = SensorHandles(sensors_);
    sensor_handles_.fill(sensors_);
  }
  manager_->set_sensor_hardware(&sensor_handles_.hardware());
  startup_times_.sensors = timer.lap();
}

Simulation::~Simulation() = default;

void Simulation::add_reflected_inertia_for_safety_limits() {
  // The safety controller's velocity law tau = -k_velocity (v - v_bound) is applied once per
  // tick from the measured velocity, i.e. explicitly: the discrete loop v' = v - k dt (v - v_b)
  // / (I + c dt) (c: the joint damping, which MuJoCo integrates implicitly) overshoots the bound
  // when k dt > I + c dt and oscillates with period 2 when k dt > 2 (I + c dt). The PR2's
  // torso (k_velocity 2e6 N s/m for ~100 kg: k dt / I = 20) chattered at its +-10 kN effort
  // limit and shook the whole robot on its casters. The real joints do not, because their
  // motors' rotor inertia, reflected through reductions like the torso's 47641, is large; the
  // description does not carry it. So, like the gripper gap above, each such joint gets the
  // armature that makes k dt / (I + armature + c dt) = 0.5 (a one-step decay to the bound's
  // half way, no overshoot), where I is the inertia the joint sees with everything else free.
  // Joints whose own inertia already satisfies this (the PR2's arm joints, mostly) are unchanged.
  for (std::size_t j = 0; j < mechanism_->joints.size(); ++j) {
    const mechanism::JointInfo& info = mechanism_->joints[j];
    const int p = physics_joint_[j];
    if (p < 0 || !info.safety || info.safety->k_velocity <= 0.0) continue;
    const auto pj = static_cast<std::size_t>(p);
    const double k_dt = info.safety->k_velocity * options_.period;
    const double have = physics_->effective_inertia(pj) + physics_->joint_damping(pj) * options_.period;
    if (2.0 * k_dt <= have) continue;
    physics_->set_armature(pj, physics_->armature(pj) + 2.0 * k_dt - have);
    reflected_inertia_.push_back({info.name, physics_->armature(pj)});
  }
}

void Simulation::add_model_plugins(std::vector<control::ModelPluginBuild>& plugins) {
  for (control::ModelPluginBuild& b : plugins) {
    const control::ControlResult r =
        manager_->add_model_plugin(b.name, b.filename, std::move(b.controller), b.params, b.origin, time());
    if (!r) throw std::runtime_error(r.error);
  }
}

void Simulation::make_velocity_motors() {
  // Gazebo drives a velocity joint with the joint's motor (gazebo_ros_control: "vel" with "fmax" =
  // the URDF effort limit; the drive plugins: "vel" with their wheelTorque), which reaches the
  // commanded speed within the step unless the torque bound stops it: so do mechsim's velocity
  // joints (physics::ServoGains::motor). A joint given servo gains keeps the servo.
  for (std::size_t j = 0; j < physics_joint_.size(); ++j) {
    const mechanism::JointInfo& info = mechanism_->joints[j];
    const bool velocity = info.role == mechanism::JointRole::Direct || info.has_interface(HardwareInterface::Velocity);
    if (velocity && options_.servo_gains.count(info.name) == 0) servo_gains_[j].motor = true;
  }
}

void Simulation::apply_requests() {
  bool reset_asked = reset_requested_.exchange(false);
  for (const auto& o : others_) reset_asked = o->reset_requested_.exchange(false) || reset_asked;
  if (reset_asked) reset();
  if (have_commands_.load(std::memory_order_acquire)) run_commands();
  for (const auto& o : others_)
    if (o->have_commands_.load(std::memory_order_acquire)) o->run_commands();
}

void Simulation::post(Command command) {
  {
    std::lock_guard<std::mutex> lock(commands_mutex_);
    commands_.push_back(std::move(command));
    ++commands_posted_;
  }
  have_commands_.store(true, std::memory_order_release);
}

void Simulation::run_commands() {
  std::vector<Command> batch;
  {
    std::lock_guard<std::mutex> lock(commands_mutex_);
    batch.swap(commands_);
    have_commands_.store(false, std::memory_order_relaxed);
  }
  for (Command& command : batch) {
    try {
      command(*this);
    } catch (const std::exception&) {
      // Commands report through what they capture (see post()).
    }
  }
  {
    std::lock_guard<std::mutex> lock(commands_mutex_);
    commands_run_ += batch.size();
  }
  commands_done_.notify_all();
}

bool Simulation::wait_for_commands(double timeout) {
  std::unique_lock<std::mutex> lock(commands_mutex_);
  const std::uint64_t target = commands_posted_;
  return commands_done_.wait_for(lock, std::chrono::duration<double>(timeout), [&] { return commands_run_ >= target; });
}

void Simulation::state_changed() {
  read_physics();
  sensors_.sample_all(*physics_, time());
  sensor_handles_.fill(sensors_);
}

void Simulation::control_phase() {
  read_physics();
  const bool e_stop = e_stop_requested_.load(std::memory_order_acquire);
  if (e_stop && !e_stop_) {
    for (std::size_t j = 0; j < e_stop_position_.size(); ++j) e_stop_position_[j] = mechanism_state_->joints[j].position;
  }
  if (!e_stop && e_stop_) restart_controllers_ = true;
  e_stop_ = e_stop;
  if (ticks_ % control_every_ == 0) {
    manager_->update(time(), control_period(), restart_controllers_);
    restart_controllers_ = false;
  }
  write_physics();
}

void Simulation::sense_phase() {
  // The mechanism state describes the new time() for observers and callers between ticks (the
  // read at the start of the next tick repeats it, for writes to the physics in between).
  read_physics();
  sensors_.sample_due(*physics_, time());
  sensor_handles_.fill(sensors_);
}

TickResult Simulation::step() {
  if (host_ != nullptr) throw std::logic_error("robot '" + name_ + "' ticks with the simulation that holds it");
  apply_requests();
  control_phase();
  for (const auto& o : others_) o->control_phase();
  if (external_.active()) external_.apply(*physics_, time());
  for (const Observer& observer : control_observers_) observer(*this);
  for (const auto& o : others_)
    for (const Observer& observer : o->control_observers_) observer(*o);
  const physics::StepStatus status = physics_->step();
  ++ticks_;
  for (const auto& o : others_) o->ticks_ = ticks_;
  while (notice_ticks_.size() < physics_->notices().size()) notice_ticks_.push_back(ticks_);
  if (!status.ok()) {
    ++divergences_;
    const char* what = status.code == physics::StepCode::ArenaFull ? "physics failed" : "physics diverged";
    TickResult result{false, std::string(what) + " at tick " + std::to_string(ticks_) + " (t=" + std::to_string(time()) +
                                 " s): " + status.message()};
    if (options_.on_divergence == DivergencePolicy::Reset) {
      reset();
      result.error += " (simulation reset to the spawn state)";
    } else {
      pause();
      result.error += " (simulation stopped)";
    }
    return result;
  }
  sense_phase();
  for (const auto& o : others_) o->sense_phase();
  for (const Observer& observer : observers_) observer(*this);
  for (const auto& o : others_)
    for (const Observer& observer : o->observers_) observer(*o);
  return {};
}

TickResult Simulation::run_for(double duration) {
  if (host_ != nullptr) throw std::logic_error("robot '" + name_ + "' ticks with the simulation that holds it");
  using Clock = std::chrono::steady_clock;
  const std::uint64_t target = ticks_ + static_cast<std::uint64_t>(duration / options_.period + 0.5);
  const auto wall_start = Clock::now();
  const double sim_start = time();
  TickResult result;
  while (ticks_ < target) {
    if (paused()) {
      pace_anchored_ = false;  // time stood still: the pace starts afresh on unpause
      apply_requests();
      if (pending_steps_.load() > 0) {  // single steps asked for while paused
        result = step();
        pending_steps_.fetch_sub(1);
        if (!result.ok && options_.on_divergence == DivergencePolicy::Stop) {
          pending_steps_.store(0);
          break;
        }
        continue;
      }
      // Nobody can unpause a paused single-threaded run: return instead of waiting forever.
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      if (paused()) break;
      continue;
    }
    if (options_.real_time_factor > 0.0 && !pace_anchored_) {
      pace_wall_ = Clock::now();
      pace_sim_ = time();
      pace_anchored_ = true;
    }
    result = step();
    if (!result.ok && options_.on_divergence == DivergencePolicy::Stop) break;
    if (options_.real_time_factor > 0.0) pace();
  }
  const double wall = std::chrono::duration<double>(Clock::now() - wall_start).count();
  if (wall > 0.0) measured_rtf_ = (time() - sim_start) / wall;
  return result;
}

void Simulation::pace() {
  using Clock = std::chrono::steady_clock;
  const auto due = pace_wall_ + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>((time() - pace_sim_) / options_.real_time_factor));
  const auto now = Clock::now();
  if (now - due > std::chrono::duration<double>(kMaxPaceLag)) {
    pace_wall_ = now;
    pace_sim_ = time();
    return;
  }
  std::this_thread::sleep_until(due);
}

void Simulation::reset() {
  if (host_ != nullptr) {
    host_->reset();
    return;
  }
  physics_->reset();
  external_.clear();
  reset_robot();
  for (const auto& o : others_) o->reset_robot();
}

void Simulation::reset_robot() {
  apply_initial_joints();
  for (std::size_t j = 0; j < physics_mode_.size(); ++j) physics_mode_[j] = HardwareInterface::Effort;
  pid_drive_.reset();
  // An e-stop still requested latches the spawn positions at the next tick; the restart below
  // stands for the one its release may owe.
  e_stop_ = false;
  restart_controllers_ = false;
  mechanism::MechanismState fresh = mechanism::make_state(*mechanism_);
  fresh.base.floating = floating_;
  *mechanism_state_ = fresh;
  // Every joint back to its own effort bound (the restarted plugins set theirs again).
  for (std::size_t j = 0; j < physics_joint_.size(); ++j) {
    if (physics_joint_[j] >= 0 && physics_effort_limit_[j] != 0.0) physics_->set_effort_limit(static_cast<std::size_t>(physics_joint_[j]), 0.0);
    physics_effort_limit_[j] = 0.0;
  }
  read_physics();
  // Every running controller and model plugin is stopped and started again at the next tick, so
  // that each starting() sees the spawn state. Not a switch: one pending (or asked for before
  // that tick) neither blocks the restart nor is refused because of it.
  manager_->request_restart();
  sensors_.sample_all(*physics_, time());
  sensor_handles_.fill(sensors_);
  ++resets_;
}

std::vector<std::string> Simulation::physics_warnings() const {
  std::vector<std::string> out = earlier_notices_;
  const std::vector<std::string> now = physics_warnings_of_physics();
  out.insert(out.end(), now.begin(), now.end());
  for (const sensors::SkippedSensor& s : sensors_.skipped()) {
    if (s.left_out) out.push_back(s.reason);
  }
  out.insert(out.end(), plugin_notes_.begin(), plugin_notes_.end());
  return out;
}

std::vector<std::string> Simulation::physics_warnings_of_physics() const {
  std::vector<std::string> out;
  const std::vector<physics::PhysicsNotice>& notices = physics_->notices();
  for (std::size_t i = 0; i < notices.size() && i < notice_ticks_.size(); ++i) {
    const std::uint64_t tick = notice_ticks_[i];
    char when[64];
    if (tick == 0) std::snprintf(when, sizeof when, "spawn (t = 0 s): ");
    else std::snprintf(when, sizeof when, "tick %llu (t = %.3f s): ", static_cast<unsigned long long>(tick),
                       static_cast<double>(tick - 1) * options_.period);
    std::string text = when + notices[i].text;
    if (notices[i].count > 1) text += " (in " + std::to_string(notices[i].count) + " steps in all)";
    out.push_back(std::move(text));
  }
  return out;
}

void Simulation::load_and_start(const std::vector<std::string>& controllers) {
  for (const std::string& name : controllers) {
    // The manager's error names the controller already.
    if (control::ControlResult r = load_controller(name); !r) throw std::runtime_error(r.error);
  }
  control::SwitchResult s = manager_->switch_controllers(controllers, {}, control::SwitchStrictness::Strict);
  if (!s) throw std::runtime_error("could not start controllers: " + s.error);
  // Started now, from the state at time(), as the next tick would start them: a command written
  // before that tick (a scenario's timeline at t = 0) is then not reset by their starting().
  manager_->apply_pending_switch(time());
}

}  // namespace mechsim::sim
