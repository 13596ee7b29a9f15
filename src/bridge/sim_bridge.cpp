// SimBridge over sim::Simulation (C++20; see sim_bridge.hpp for why it exists).
#include "bridge/sim_bridge.hpp"
#include "description/sdf/sdf_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "controllers/drive/rover_drive_params.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "bridge/bridge_impl.hpp"
#include "bridge/mechanism_statistics.hpp"
#include "sensors/sensor_types.hpp"
#include "sim/ros2_control_config.hpp"
#include "sim/simulation.hpp"
#include "sim/world.hpp"

namespace mechsim::bridge {

namespace {

const char* lifecycle_string(control::ControllerLifecycle state) {
  switch (state) {
    case control::ControllerLifecycle::Initialized: return "initialized";
    case control::ControllerLifecycle::Running: return "running";
    case control::ControllerLifecycle::Stopped: return "stopped";
  }
  return "unknown";
}

const char* ros_control_interface(mechanism::HardwareInterface hw) {
  switch (hw) {
    case mechanism::HardwareInterface::Effort: return "hardware_interface::EffortJointInterface";
    case mechanism::HardwareInterface::Position: return "hardware_interface::PositionJointInterface";
    case mechanism::HardwareInterface::Velocity: return "hardware_interface::VelocityJointInterface";
  }
  return "hardware_interface::JointStateInterface";
}

PortType port_type(const control::Port& port) {
  switch (port.kind()) {
    case control::PortKind::ScalarCommand: return PortType::ScalarCommand;
    case control::PortKind::ArrayCommand: return PortType::ArrayCommand;
    case control::PortKind::TwistCommand: return PortType::TwistCommand;
    case control::PortKind::JointControllerState: return PortType::JointControllerState;
    case control::PortKind::JointStates: return PortType::JointStates;
    case control::PortKind::Odometry: return PortType::Odometry;
    case control::PortKind::TrajectoryCommand: return PortType::TrajectoryCommand;
    case control::PortKind::TrajectoryGoal: return PortType::TrajectoryGoal;
    case control::PortKind::JointTrajectoryState: return PortType::TrajectoryState;
    case control::PortKind::GripperCommand: return PortType::GripperCommand;
    case control::PortKind::GripperGoal: return PortType::GripperGoal;
    case control::PortKind::TrajectoryQuery: return PortType::TrajectoryQuery;
    case control::PortKind::PeriodicCommand: return PortType::ScanCommand;
    case control::PortKind::TwistState: return PortType::TwistState;
    case control::PortKind::ImuState: return PortType::ImuState;
    case control::PortKind::WrenchState: return PortType::WrenchState;
    default: return PortType::Other;
  }
}

}  // namespace

namespace {

sim::SimulationOptions simulation_options(const BridgeOptions& o) {
  sim::SimulationOptions sim_options;
  sim_options.period = o.period;
  sim_options.spawn = {o.x, o.y, o.z, o.roll, o.pitch, o.yaw};
  sim_options.start_paused = o.paused;
  sim_options.real_time_factor = o.real_time_factor;
  sim_options.start_time = o.start_time;
  sim_options.initial_joints = o.initial_joints;
  sim_options.parameter_root = o.parameter_root;
  return sim_options;
}

// ros2_control: the manager's configuration from the options' parameters; `options` get its
// rate and flag. Returns the controllers' parameter tree.
control::Params ros2_setup(const BridgeOptions& o, sim::SimulationOptions& options, std::optional<Ros2ControlSummary>& out) {
  const sim::Ros2ControlConfig config = sim::ros2_control_config(o.robot, *o.ros2_parameters, o.ros2_namespace);
  sim::apply_ros2_control(options, config);
  Ros2ControlSummary s;
  s.plugin = config.plugin;
  s.controller_manager = config.setup.controller_manager;
  s.node_namespace = config.setup.node_namespace;
  s.update_rate = config.setup.update_rate;
  s.declared_controllers = config.setup.controller_names;
  s.parameter_files = config.files;
  s.notes = config.notes;
  out = std::move(s);
  return config.setup.controllers;
}

// The description links the physics has (in the description's order).
std::vector<std::string> physics_links(const sim::Simulation& s) {
  std::vector<std::string> out;
  for (const description::Link& link : s.robot().links) {
    // A robot fixed to the world hangs from a `world` link: Gazebo's world, not a link of the model.
    if (link.name == "world" && s.robot().root_link == "world" && &s.world_host() != &s) continue;
    if (s.physics().model().link_index(s.physics_name(link.name))) out.push_back(link.name);
  }
  return out;
}

}  // namespace

void SimBridge::Impl::refresh() {
  const std::uint64_t g = simulation->physics_generation();
  if (resolved && g == generation) return;
  resolved = true;
  generation = g;
  const physics::PhysicsModel& model = simulation->physics().model();
  physics_joint.clear();
  for (const description::Joint& joint : simulation->robot().joints) {
    const auto index = model.joint_index(simulation->physics_name(joint.name));
    physics_joint.push_back(index ? static_cast<int>(*index) : -1);
  }
  link_index.clear();
  for (const std::string& link : link_names) link_index.push_back(model.link_index(simulation->physics_name(link)).value_or(0));
  world_model_body.clear();
  for (const sim::World::ModelFrame& f : simulation->world().sdf_model_frames)
    world_model_body.push_back(f.body.empty() ? -1 : model.body_index(f.body));
  reapply_overrides();
}

void SimBridge::Impl::reapply_overrides() {
  // A rebuilt physics starts from the description: what the model API changed goes in again.
  std::lock_guard<std::mutex> lock(overrides_mutex);
  physics::Physics& p = simulation->physics();
  const physics::PhysicsModel& model = p.model();
  for (const auto& [joint, change] : joint_overrides) {
    const auto j = model.joint_index(simulation->physics_name(joint));
    if (!j) continue;
    if (change.damping) p.set_joint_damping(*j, *change.damping);
    if (change.lower || change.upper) {
      auto [lower, upper] = p.joint_limits(*j);
      p.set_joint_limits(*j, change.lower.value_or(lower), change.upper.value_or(upper));
    }
  }
  for (const auto& [link, l] : link_overrides)
    if (const auto i = model.link_index(simulation->physics_name(link)))
      p.set_link_inertial(*i, l.mass, l.com, {l.ixx, l.ixy, l.ixz, l.iyy, l.iyz, l.izz});
}

SimBridge::SimBridge(BridgeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  Impl& m = *impl_;
  sim::WorldConfig world_config;
  world_config.name = m.options.world;
  world_config.sdf_active_models_apart = m.options.world_models_apart;
  const sim::World world = sim::make_world(world_config);
  sim::SimulationOptions sim_options = simulation_options(m.options);
  m.params = m.options.ros2_parameters ? ros2_setup(m.options, sim_options, m.ros2) : m.options.controller_params;
  m.owned = std::make_unique<sim::Simulation>(m.options.robot, world, m.params, sim_options);
  if (m.ros2) {
    for (const std::string& note : m.ros2->notes) m.owned->add_note(note);
  }
  m.simulation = m.owned.get();
  if (m.options.paused) m.simulation->pause();
  m.link_names = physics_links(*m.simulation);
  m.refresh();
}

SimBridge::SimBridge(SimBridge& host, BridgeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  Impl& m = *impl_;
  m.host = host.impl_->host != nullptr ? host.impl_->host : host.impl_.get();
  sim::SimulationOptions ros2_options;
  m.params = m.options.ros2_parameters ? ros2_setup(m.options, ros2_options, m.ros2) : m.options.controller_params;
  sim::OtherRobot other;
  other.ros2_control = ros2_options.ros2_control;
  other.controller_update_rate = ros2_options.controller_update_rate;
  other.name = m.options.robot.name;
  other.robot = m.options.robot;
  other.controllers = m.params;
  other.parameter_root = m.options.parameter_root;
  other.spawn = {m.options.x, m.options.y, m.options.z, m.options.roll, m.options.pitch, m.options.yaw};
  other.initial_joints = m.options.initial_joints;
  // The world's loop takes the robot in between two ticks. Should it not answer in time, the
  // command, when it runs later, does nothing (`abandoned`): no robot appears unseen.
  struct Taking {
    std::mutex mutex;
    bool done = false, abandoned = false;
    sim::Simulation* robot = nullptr;
    std::vector<std::string> links;
    std::string error;
  };
  auto taking = std::make_shared<Taking>();
  m.host->simulation->post([taking, other = std::move(other)](sim::Simulation& world) mutable {
    std::lock_guard<std::mutex> lock(taking->mutex);
    if (taking->abandoned) return;
    try {
      taking->robot = &world.add_other(std::move(other));
      taking->links = physics_links(*taking->robot);
    } catch (const std::exception& e) {
      taking->error = e.what();
    }
    taking->done = true;
  });
  constexpr double kSpawnTimeout = 60.0;  // s (wall): building a robot's physics takes ~1 s
  m.host->simulation->wait_for_commands(kSpawnTimeout);
  std::lock_guard<std::mutex> lock(taking->mutex);
  if (!taking->done) {
    taking->abandoned = true;
    throw std::runtime_error("the simulation loop did not take model '" + m.options.robot.name + "' in within 60 s");
  }
  if (!taking->error.empty()) throw std::runtime_error(taking->error);
  m.simulation = taking->robot;
  m.link_names = std::move(taking->links);
  // Its physics indices are looked up at their first use, in the loop (Impl::refresh).
}

SimBridge::~SimBridge() {
  // An other robot leaves the world with its bridge (a spawn that failed after the bridge was
  // made); remove_from_world() did it already when the model was deleted.
  if (impl_ && impl_->host != nullptr && impl_->simulation != nullptr) remove_from_world();
}

bool SimBridge::is_other_robot() const { return impl_->host != nullptr; }

void SimBridge::wait_for_loop() {
  if (impl_->simulation == nullptr) return;
  impl_->in_loop([](sim::Simulation&) { return BridgeResult{}; });
}

void SimBridge::detach_from_world() {
  if (impl_->host != nullptr) impl_->simulation = nullptr;
}

BridgeResult SimBridge::remove_from_world() {
  Impl& m = *impl_;
  if (m.host == nullptr) return {false, "the world's first robot holds its physics"};
  if (m.simulation == nullptr) return {};
  const std::string name = m.simulation->robot_name_in_world();
  // Through the host's queue: the robot's own queue goes with it.
  const BridgeResult r = m.host->in_loop([name](sim::Simulation& world) -> BridgeResult {
    if (!world.remove_other(name)) return {false, "no robot '" + name + "' in the world"};
    return {};
  });
  if (r.ok) m.simulation = nullptr;
  return r;
}



WorldSummary describe_world(const std::string& name, bool models_apart) {
  sim::WorldConfig config;
  config.name = name;
  config.sdf_active_models_apart = models_apart;
  const sim::World world = sim::make_world(config);
  WorldSummary out;
  out.has_ground = world.spec.ground_plane || world.spec.terrain.has_value();
  out.gravity = {0.0, 0.0, -world.spec.gravity};
  out.sdf_models = world.sdf_models;
  for (const sim::World::ModelFrame& f : world.sdf_model_frames) out.sdf_model_poses.push_back(f.pose);
  out.not_simulated = world.not_simulated;
  out.warnings = world.warnings;
  out.max_step_size = world.max_step_size.value_or(0.0);
  out.real_time_factor = world.real_time_factor.value_or(0.0);
  for (const sim::SdfRobot& r : world.sdf_robots) out.robots.push_back({r.name, r.robot, r.X_WR, r.is_static});
  for (const description::SdfLight& l : world.lights) {
    WorldSummary::Light light;
    light.name = l.name;
    light.type = l.type;
    light.cast_shadows = l.cast_shadows;
    for (int i = 0; i < 4; ++i) light.diffuse[i] = l.diffuse[static_cast<std::size_t>(i)], light.specular[i] = l.specular[static_cast<std::size_t>(i)];
    light.attenuation_constant = l.attenuation_constant;
    light.attenuation_linear = l.attenuation_linear;
    light.attenuation_quadratic = l.attenuation_quadratic;
    light.direction = l.direction;
    light.pose = l.pose;
    out.lights.push_back(std::move(light));
  }
  return out;
}

bool SimBridge::run_for(double duration, std::string* error) {
  if (impl_->host != nullptr) throw std::logic_error("run_for: an other robot ticks with the world's first robot");
  const sim::TickResult r = impl_->simulation->run_for(duration);
  if (!r.ok && error) *error = r.error;
  return r.ok;
}

void SimBridge::add_observer(Observer observer) {
  auto add = [obs = std::move(observer)](sim::Simulation& s) {
    s.add_observer([obs](const sim::Simulation& t) { obs(t.time()); });
    return BridgeResult{};
  };
  // An other robot's observers run in the world's loop, which is running: add it there.
  if (impl_->host != nullptr) impl_->in_loop(add);
  else add(*impl_->simulation);
}

void SimBridge::joint_positions(std::vector<double>& out) const {
  impl_->refresh();
  const physics::Physics& p = impl_->simulation->physics();
  out.resize(impl_->physics_joint.size());
  for (std::size_t j = 0; j < out.size(); ++j) {
    const int pj = impl_->physics_joint[j];
    out[j] = pj >= 0 ? p.position(static_cast<std::size_t>(pj)) : 0.0;
  }
}

description::Pose SimBridge::base_pose() const { return impl_->simulation->base_pose(); }

void SimBridge::enable_mechanism_statistics() {
  if (impl_->statistics) return;
  auto enable = [this](sim::Simulation& simulation) {
    impl_->statistics = std::make_shared<MechanismStatistics>(simulation);
    simulation.add_observer([stats = impl_->statistics](const sim::Simulation& s) { stats->update(s); });
    return BridgeResult{};
  };
  // Another robot's observers run in the world's loop, which is running: add it there.
  if (impl_->host != nullptr) impl_->in_loop(enable);
  else enable(*impl_->simulation);
}

void SimBridge::mechanism_joint_states(JointStatesData& out) const {
  if (!impl_->statistics) throw std::logic_error("mechanism_joint_states: enable_mechanism_statistics() first");
  impl_->statistics->joint_states(*impl_->simulation, out);
}

void SimBridge::take_mechanism_statistics(MechanismStatisticsData& out) {
  if (!impl_->statistics) throw std::logic_error("take_mechanism_statistics: enable_mechanism_statistics() first");
  impl_->statistics->take(*impl_->simulation, out);
}

double SimBridge::time() const { return impl_->simulation->time(); }
double SimBridge::period() const { return impl_->simulation->period(); }
std::uint64_t SimBridge::ticks() const { return impl_->simulation->ticks(); }
std::uint64_t SimBridge::resets() const { return impl_->simulation->resets(); }
// Time, pause and stepping are the world's: an other robot's are its host's.
void SimBridge::pause() { impl_->simulation->world_host().pause(); }
void SimBridge::unpause() { impl_->simulation->world_host().unpause(); }
bool SimBridge::paused() const { return impl_->simulation->world_host().paused(); }
void SimBridge::request_reset() { impl_->simulation->request_reset(); }
void SimBridge::set_e_stop(bool active) { impl_->simulation->set_e_stop(active); }
bool SimBridge::e_stop_active() const { return impl_->simulation->e_stop_active(); }
const std::string& SimBridge::e_stop_topic() const { return impl_->simulation->e_stop_topic(); }
const description::RobotModel& SimBridge::robot() const { return impl_->simulation->robot(); }
control::Params SimBridge::controller_params() const { return impl_->params; }
const Ros2ControlSummary* SimBridge::ros2_control() const { return impl_->ros2 ? &*impl_->ros2 : nullptr; }
const control::Ros2ParameterSet* SimBridge::ros2_parameters() const {
  return impl_->options.ros2_parameters ? &*impl_->options.ros2_parameters : nullptr;
}
const std::vector<std::string>& SimBridge::joint_drive_notes() const { return impl_->simulation->joint_drive_notes(); }
const std::vector<std::string>& SimBridge::physics_warnings() const {
  return impl_->simulation->physics().model().warnings();
}

BridgeResult SimBridge::load_controller(const std::string& name) {
  // The simulation fills the geometry the rover drive, the PR2 base and diff_drive_controller
  // take from the URDF where the parameters leave it out.
  const control::ControlResult r = impl_->simulation->load_controller(name);
  return {r.ok, r.error};
}

BridgeResult SimBridge::unload_controller(const std::string& name) {
  const control::ControlResult r = impl_->simulation->controllers().unload_controller(name);
  return {r.ok, r.error};
}

BridgeResult SimBridge::switch_controllers(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                                           bool strict, double timeout) {
  control::ControllerManager& cm = impl_->simulation->controllers();
  const control::SwitchResult r = cm.switch_controllers(
      start, stop, strict ? control::SwitchStrictness::Strict : control::SwitchStrictness::BestEffort);
  if (!r.ok) return {false, r.error};
  BridgeResult result;
  for (const std::string& s : r.skipped) result.error += (result.error.empty() ? "" : "; ") + s;
  // ros_control waits for the update loop to apply the switch; a paused world never does, and
  // one paused while we wait will not either: the switch stays pending (listed "waiting") and
  // the answer is ok, as for a switch made while paused. A switch not applied in time is taken
  // back, so that the refusal is true (it used to apply at the next tick after "not applied"),
  // and no timeout (NaN, infinite, 1e300) holds the caller, and the manager's lock, unbounded.
  constexpr double kMaxWait = 30.0;  // s (wall)
  const double wait = timeout > 0.0 && std::isfinite(timeout) ? std::min(timeout, kMaxWait) : 5.0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait);
  while (cm.switch_pending() && !paused()) {
    if (std::chrono::steady_clock::now() >= deadline) {
      if (cm.cancel_pending_switch()) {
        return {false, "the switch was not applied within the timeout (" + std::to_string(wait) +
                           " s of wall time); it was taken back: no controller changed"};
      }
      cm.wait_for_switch(1.0);  // a tick took it just now and applies it
      break;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  return result;
}

std::vector<ControllerSummary> SimBridge::list_controllers() const {
  std::vector<ControllerSummary> out;
  for (const control::ControllerInfo& info : impl_->simulation->controllers().list_controllers()) {
    if (info.model_plugin) continue;  // model_plugins()
    ControllerSummary s;
    s.name = info.name;
    s.type = info.type;
    s.state = lifecycle_string(info.state);
    // ros_control's "waiting": asked to start, not started yet (a switch made while paused
    // applies at the first tick after unpause).
    if (info.start_pending && info.state != control::ControllerLifecycle::Running) s.state = "waiting";
    for (const control::ResourceClaim& claim : info.claims) {
      s.claims.push_back({impl_->ros2 ? control::interface_short_name(claim.interface) : ros_control_interface(claim.interface),
                          claim.joints});
    }
    // Sensor interfaces: ros_control lists them with no resource (sensor handles claim nothing).
    for (const control::SensorUse& use : info.sensors) s.claims.push_back({use.interface, {}});
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> SimBridge::list_controller_types() const {
  return impl_->simulation->controllers().list_controller_types();
}

bool SimBridge::is_loaded(const std::string& name) const {
  return impl_->simulation->controllers().controller(name) != nullptr;
}

std::vector<PortRef> SimBridge::ports(const std::string& controller) const {
  std::vector<PortRef> out;
  control::Controller* c = impl_->simulation->controllers().controller(controller);
  if (!c) return out;
  const auto info = impl_->simulation->controllers().controller_info(controller);
  for (control::Port* p : c->ports()) {
    PortRef ref;
    ref.controller = controller;
    ref.controller_type = info ? info->type : std::string();
    ref.name = p->name();
    ref.type = port_type(*p);
    if (auto* array = dynamic_cast<control::ArrayCommandPort*>(p)) ref.size = array->size();
    ref.port = p;
    out.push_back(std::move(ref));
  }
  return out;
}

std::vector<ModelPluginSummary> SimBridge::model_plugins() const {
  std::vector<ModelPluginSummary> out;
  control::ControllerManager& cm = impl_->simulation->controllers();
  for (const control::ControllerInfo& info : cm.list_controllers()) {
    if (!info.model_plugin) continue;
    const auto* plugin = dynamic_cast<const control::ModelPlugin*>(cm.controller(info.name));
    if (plugin == nullptr) continue;
    const control::PluginRosInterface& ros = plugin->ros_interface();
    ModelPluginSummary m;
    m.name = info.name;
    m.filename = info.type;
    m.origin = info.origin;
    m.robot_namespace = ros.robot_namespace;
    m.odom_tf = ros.odom_tf;
    m.wheel_tf_joints = ros.wheel_tf_joints;
    m.tf_prefix = ros.tf_prefix;
    m.wheel_tf_child_is_joint = ros.wheel_tf_child_is_joint;
    const std::vector<PortRef> ports = this->ports(info.name);
    for (const control::PluginTopic& t : ros.topics) {
      for (const PortRef& p : ports) {
        if (p.name == t.port) m.topics.push_back({p, t.topic, t.message});
      }
    }
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<std::string> SimBridge::plugin_notes() const {
  std::vector<std::string> out;
  for (const control::ModelPluginStatus& s : control::model_plugin_status(impl_->simulation->robot())) {
    if (!s.simulated()) out.push_back(control::describe(s));
  }
  return out;
}

// ---- sensors

std::size_t SimBridge::sensor_count() const { return impl_->simulation->sensors().size(); }

const description::SensorSpec& SimBridge::sensor_spec(std::size_t i) const {
  return impl_->simulation->sensors().spec(i);
}

const sensors::SensorReading& SimBridge::sensor_reading(std::size_t i) const {
  return impl_->simulation->sensors().reading(i);
}

void SimBridge::set_sensor_enabled(std::size_t i, bool enabled) { impl_->simulation->sensors().set_enabled(i, enabled); }

void SimBridge::request_sensor_sample(std::size_t i) { impl_->simulation->sensors().request(i); }

std::vector<sensors::CameraInfo> SimBridge::camera_infos(std::size_t i) const {
  std::vector<sensors::CameraInfo> out;
  if (const auto* camera = dynamic_cast<const sensors::CameraSensor*>(&impl_->simulation->sensors().sensor(i)))
    for (const sensors::CameraSensor::Lens& lens : camera->lenses()) out.push_back(lens.info);
  return out;
}

std::vector<std::string> SimBridge::skipped_sensors() const {
  std::vector<std::string> out;
  for (const sensors::SkippedSensor& s : impl_->simulation->sensors().skipped())
    if (!s.left_out) out.push_back(s.spec.where() + ": " + s.reason);
  return out;
}

}  // namespace mechsim::bridge
