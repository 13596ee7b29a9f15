// World: its lifecycle (the world's simulation and loop), spawn and delete, pause, step and reset
// (world.hpp).
#include "bridge/world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "bridge/robot_plugins.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "description/robot_namespace.hpp"
#include "description/sdf/sdf_model.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "physics/transform.hpp"

namespace mechsim::bridge {

namespace {

using Clock = std::chrono::steady_clock;

// URDF rpy (fixed axes x, y, z) of a unit quaternion.
void rpy_of(const description::Quat& q, double& roll, double& pitch, double& yaw) {
  roll = std::atan2(2.0 * (q.w * q.x + q.y * q.z), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
  const double s = 2.0 * (q.w * q.y - q.z * q.x);
  pitch = std::asin(s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s));
  yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

bool finite(const description::Pose& p) {
  const auto& v = p.position;
  const auto& q = p.orientation;
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(q.w) && std::isfinite(q.x) &&
         std::isfinite(q.y) && std::isfinite(q.z);
}

// Gazebo's worlds/empty.world (its install's resource path) is mechsim's `empty`.
std::string mechsim_world_name(const std::string& gazebo_name) {
  if (gazebo_name.empty() || gazebo_name == "worlds/empty.world") return "empty";
  return gazebo_name;
}

BridgeResult refused(std::string why) { return {false, std::move(why)}; }

}  // namespace

World::World(WorldOptions options) : options_(std::move(options)) {
  world_name_ = mechsim_world_name(options_.world);
  const WorldSummary world = describe_world(world_name_, true);
  world_robots_ = world.robots;
  gravity_ = world.gravity;
  world_models_ = world.sdf_models;
  world_model_poses_ = world.sdf_model_poses;
  sdf_model_count_ = world_models_.size();
  if (!description::is_sdf_world_file(world_name_) && world.has_ground) {
    world_models_.push_back("ground_plane");
    world_model_poses_.emplace_back();
  }
  for (const WorldSummary::Light& l : world.lights) {
    LightProperties light;
    light.name = l.name;
    light.type = l.type;
    light.cast_shadows = l.cast_shadows;
    for (std::size_t i = 0; i < 4; ++i) light.diffuse[i] = l.diffuse[i], light.specular[i] = l.specular[i];
    light.attenuation_constant = l.attenuation_constant;
    light.attenuation_linear = l.attenuation_linear;
    light.attenuation_quadratic = l.attenuation_quadratic;
    light.direction = l.direction;
    light.pose = l.pose;
    lights_.push_back(std::move(light));
  }
  if (!description::is_sdf_world_file(world_name_)) {
    // Gazebo's empty.world includes model://sun: mechsim's own worlds have it too.
    LightProperties sun;
    sun.name = "sun";
    sun.pose.position = {0.0, 0.0, 10.0};
    lights_.push_back(sun);
  }
  not_simulated_ = world.not_simulated;
  world_warnings_ = world.warnings;
  if (world.real_time_factor > 0.0 && options_.real_time_factor == 1.0) options_.real_time_factor = world.real_time_factor;
  if (world.max_step_size > 0.0 && std::abs(world.max_step_size - options_.period) > 1e-12) {
    not_simulated_.push_back("max_step_size " + std::to_string(world.max_step_size) + " s: mechsim steps at " +
                             std::to_string(options_.period) + " s (its controllers' 1 kHz tick)");
  }
}

World::~World() { stop(); }

void World::start(WorldBinding* binding) {
  std::lock_guard<std::mutex> lock(mutex_);
  binding_ = binding;
  if (binding_ != nullptr)
    for (const std::string& n : not_simulated_) binding_->warn(world_name_ + ": not simulated: " + n);
  if (binding_ != nullptr)
    for (const std::string& w : world_warnings_) binding_->warn(world_name_ + ": " + w);
  // A world with no robot of its own: the models come in as its other robots.
  BridgeOptions bridge;
  bridge.robot = description::parse_urdf_string("<robot name=\"world\"><link name=\"world\"/></robot>", "the world",
                                                description::UrdfOptions{});
  bridge.world = world_name_;
  bridge.real_time_factor = options_.real_time_factor;
  bridge.period = options_.period;
  bridge.paused = options_.paused;
  bridge.world_models_apart = true;
  world_ = std::make_unique<SimBridge>(std::move(bridge));
  if (binding_ != nullptr)
    for (const std::string& w : world_->physics_warnings()) binding_->warn("physics: " + w);
  world_->add_observer([this](double t) {
    if (binding_ != nullptr) binding_->ticked(t);
  });
  stop_.store(false);
  loop_thread_ = std::thread([this] { loop(); });
  // The world's models with sensors or plugins: robots of their own, as spawned ones (their
  // plugins name their own namespaces; gazebo_ros gives a world's models none).
  for (const WorldRobot& r : world_robots_) {
    BridgeOptions model;
    model.robot = r.robot;
    model.robot.name = r.name;
    control::add_model_name_namespaces(model.robot);  // gazebo_plugins' default for an unspawned model
    const std::string why = admit(model, r.X_WR, "");
    if (!why.empty() && binding_ != nullptr) binding_->warn("model '" + r.name + "' of the world: " + why);
  }
}

void World::stop() {
  stop_.store(true);
  if (loop_thread_.joinable()) loop_thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  // The models' simulations go with the world's: they are forgotten, not deleted one by one.
  std::vector<Model> models;
  {
    std::lock_guard<std::mutex> guard(models_mutex_);
    models.swap(models_);
  }
  for (Model& m : models) {
    m.bridge->detach_from_world();
    if (binding_ != nullptr) binding_->model_removed(m.info);
  }
  models.clear();
  // world_ stays until the World goes: calls that come in late (a binding's service threads while
  // it shuts down) read a stopped world.
}

void World::loop() {
  // Chunks of 10 ms of simulation time keep stop() and pause() responsive at any pace.
  while (!stop_.load()) {
    if (world_->paused()) {
      world_->run_for(world_->period(), nullptr);  // applies a pending reset and steps, sleeps 1 ms
      if (binding_ != nullptr) binding_->idle(world_->time());
      continue;
    }
    std::string error;
    if (!world_->run_for(0.01, &error)) {
      if (error != divergence_ && binding_ != nullptr) binding_->warn(error);
      divergence_ = error;
    }
  }
}

const World::Model* World::find(const std::string& name) const {
  for (const Model& m : models_)
    if (m.info.name == name) return &m;
  return nullptr;
}

std::vector<std::string> World::model_names() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> names = world_models_;
  for (const Model& m : models_) names.push_back(m.info.name);
  return names;
}

std::vector<ModelInfo> World::spawned_models() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ModelInfo> out;
  for (const Model& m : models_) out.push_back(m.info);
  return out;
}

double World::time() const { return world_ ? world_->time() : 0.0; }
bool World::paused() const { return world_ ? world_->paused() : options_.paused; }

void World::set_paused(bool paused) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!world_) return;
  if (paused) world_->pause();
  else world_->unpause();
}

void World::reset() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (world_) world_->request_reset();
}

double World::measured_real_time_factor() const { return world_ ? world_->measured_real_time_factor() : 0.0; }

BridgeResult World::step(std::uint64_t steps) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!world_->paused()) return refused("the simulation is running: pause it first (/gazebo/pause_physics)");
  if (steps == 0) return {};
  // The call holds every world call until its steps ran: a count of 2^64 - 1 used to hold them
  // (pause and unpause included) for ever.
  if (steps > kMaxSteps) {
    return refused("steps " + std::to_string(steps) + " is more than " + std::to_string(kMaxSteps) +
                   " per call (the world's calls wait for the steps to run); step in smaller parts");
  }
  world_->request_steps(steps);
  // A tick of a robot takes well under 10 ms of wall time; a minute is a stuck loop.
  const auto deadline = Clock::now() + std::chrono::duration<double>(60.0 + 0.01 * static_cast<double>(steps));
  while (world_->pending_steps() > 0) {
    if (Clock::now() > deadline || stop_.load()) {
      world_->cancel_steps();
      return refused("the steps did not run in time (the simulation loop is stuck?)");
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return {};
}

BridgeResult World::spawn(const SpawnRequest& request, std::string* status) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string name = request.name;
  auto refuse = [&](const std::string& why) {
    if (binding_ != nullptr) binding_->warn("spawn of '" + name + "' refused: " + why);
    return refused(why);
  };
  if (!world_ || stop_.load()) return refuse("the world is not running");
  if (name.empty() && request.model) name = request.model->name;
  if (name.empty() && request.name_from_description) {
    // The description's own name: parsed below, checked once known.
  } else if (name.empty()) {
    return refuse("model_name is empty");
  }
  if (name.find("::") != std::string::npos) return refuse("model_name '" + name + "' holds '::' (Gazebo's scope separator)");
  if (find(name) != nullptr || std::find(world_models_.begin(), world_models_.end(), name) != world_models_.end())
    return refuse("a model named '" + name + "' is in the world already");
  if (!finite(request.pose)) return refuse("initial_pose is not finite");
  const description::Quat& q = request.pose.orientation;
  const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (norm < 1e-9) return refuse("initial_pose's orientation is a zero quaternion");
  // The frame the pose is given in: the world, or one of the world's entities (its pose now).
  Entity frame;
  EntityState X_WR;
  std::string why;
  if (!resolve(request.reference_frame, frame, &why) || !entity_state(frame, X_WR, &why))
    return refuse("reference_frame '" + request.reference_frame + "': " + why);
  description::Pose X_RM = request.pose;
  X_RM.orientation = {q.w / norm, q.x / norm, q.y / norm, q.z / norm};
  description::Pose X_WM = physics::compose(X_WR.pose, X_RM);

  BridgeOptions bridge;
  const std::string source = "model '" + name + "'";
  if (request.model) {
    bridge.robot = *request.model;
  } else try {
    // gazebo_ros gives every plugin that names no namespace the spawn's.
    const std::string xml = description::with_robot_namespace(request.xml, request.robot_namespace);
    if (xml.find("<sdf") != std::string::npos) {
      description::SdfModel sdf = description::parse_sdf_model(xml, source);
      if (binding_ != nullptr) {
        for (const std::string& n : sdf.not_simulated) binding_->warn(source + ": not simulated: " + n);
        for (const std::string& w : sdf.warnings) binding_->warn(source + ": " + w);
      }
      bridge.robot = std::move(sdf.robot);
      X_WM = physics::compose(physics::compose(X_WM, sdf.pose), sdf.root_offset);
    } else {
      std::vector<std::string> warnings;
      description::UrdfOptions urdf;
      urdf.lenient = options_.lenient;
      bridge.robot = description::parse_urdf_string(xml, source, urdf, &warnings);
      if (binding_ != nullptr)
        for (const std::string& w : warnings) binding_->warn(source + ": " + w);
    }
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  if (name.empty()) {
    name = bridge.robot.name;
    if (name.empty()) return refuse("the description names no model and the request gives no name");
    if (name.find("::") != std::string::npos) return refuse("model name '" + name + "' holds '::' (Gazebo's scope separator)");
    if (find(name) != nullptr || std::find(world_models_.begin(), world_models_.end(), name) != world_models_.end())
      return refuse("a model named '" + name + "' is in the world already");
  }
  bridge.robot.name = name;
  // A spawn without a namespace leaves gazebo_plugins' GazeboRos plugins under the model's name.
  if (request.robot_namespace.empty()) control::add_model_name_namespaces(bridge.robot);
  if (const std::string refusal = admit(bridge, X_WM, request.robot_namespace); !refusal.empty()) return refuse(refusal);
  if (status != nullptr) *status = "SpawnModel: Successfully spawned entity";
  return {};
}

std::string World::admit(BridgeOptions& bridge, const description::Pose& X_WM, const std::string& robot_namespace) {
  const std::string name = bridge.robot.name;
  ModelInfo info;
  info.name = name;
  // gazebo_ros_control's <robotNamespace>, else the spawn's (gazebo_ros gives each plugin the
  // spawn's namespace when it names none), else the root.
  std::string ns = plugin_namespace(bridge.robot, &info.pr2);
  if (ns.empty()) ns = robot_namespace;
  if (ns.empty()) ns = "/";
  if (ns.front() != '/') ns = "/" + ns;
  info.robot_namespace = ns;
  info.controller_manager = has_controller_manager_plugin(bridge.robot);
  for (const Model& m : models_) {
    // Two controller managers cannot answer under one name.
    if (info.controller_manager && m.info.controller_manager && m.info.robot_namespace == ns) {
      return "robot namespace '" + ns + "' is model '" + m.info.name +
             "'s: give each robot its own (spawn_model -robot_namespace, or the gazebo_ros_control plugin's "
             "<robotNamespace>)";
    }
    if (m.info.pr2 && info.pr2) {
      return "model '" + m.info.name + "' has /pr2_controller_manager already: one PR2 controller manager per world";
    }
  }
  bridge.world = world_name_;
  bridge.x = X_WM.position.x;
  bridge.y = X_WM.position.y;
  bridge.z = X_WM.position.z;
  rpy_of(X_WM.orientation, bridge.roll, bridge.pitch, bridge.yaw);
  bridge.period = options_.period;
  const std::string key = ns.find_first_not_of('/') == std::string::npos ? "" : ns.substr(ns.find_first_not_of('/'));
  control::Params root;
  bridge.controller_params = key.empty() ? root : root.child_or_create(key);
  bridge.parameter_root = root;
  if (binding_ != nullptr) binding_->prepare_model(info, bridge);

  Model model;
  model.info = info;
  try {
    // Taken into the running world between two ticks of its loop.
    model.bridge = std::make_unique<SimBridge>(*world_, std::move(bridge));
  } catch (const std::exception& e) {
    return e.what();
  }
  if (binding_ != nullptr) {
    for (const std::string& w : model.bridge->physics_warnings()) binding_->warn("physics: " + w);
    try {
      binding_->model_added(info, *model.bridge);
    } catch (const std::exception& e) {
      model.bridge->remove_from_world();
      binding_->model_removed(info);
      return e.what();
    }
  }
  const double t = model.bridge->time();
  {
    std::lock_guard<std::mutex> guard(models_mutex_);
    models_.push_back(std::move(model));
  }
  if (binding_ != nullptr) {
    binding_->info("spawned '" + name + "' at t = " + std::to_string(t) + " s, namespace " + ns +
                   (world_->paused() ? " (paused)" : ""));
  }
  return "";
}

BridgeResult World::remove(const std::string& name, std::string* status) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = std::find_if(models_.begin(), models_.end(), [&](const Model& m) { return m.info.name == name; });
  if (it == models_.end()) {
    if (std::find(world_models_.begin(), world_models_.end(), name) != world_models_.end())
      return refused("DeleteModel: '" + name + "' is part of the world mechsim built (" + world_name_ + "): it stays");
    return refused("DeleteModel: model [" + name + "] does not exist");
  }
  Model gone;
  {
    std::lock_guard<std::mutex> guard(models_mutex_);
    gone = std::move(*it);
    models_.erase(it);
  }
  // The world goes on: the model's outputs off, its controllers stopped and unloaded (topics
  // first, by the binding), then out of the physics.
  if (binding_ != nullptr) binding_->model_removing(gone.info, *gone.bridge);
  const BridgeResult r = gone.bridge->remove_from_world();
  if (binding_ != nullptr) {
    if (!r.ok) binding_->warn("deleting '" + name + "': " + r.error);
    binding_->model_removed(gone.info);
  }
  gone.bridge.reset();
  if (status != nullptr) *status = "DeleteModel: successfully deleted model";
  return {};
}

}  // namespace mechsim::bridge
