// GazeboWorld: the world's lifecycle: its clock before a robot comes, spawn and delete, pause,
// reset and stepping (gazebo_world.hpp).
#include "ros/gazebo_world.hpp"

#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/SpawnModel.h>
#include <mechsim_msgs/StepSimulation.h>
#include <rosgraph_msgs/Clock.h>
#include <std_srvs/Empty.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "description/sdf/sdf_model.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "physics/transform.hpp"
#include "ros/gazebo_topics.hpp"
#include "ros/robot_plugins.hpp"

namespace mechsim::ros {

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

}  // namespace

GazeboWorld::GazeboWorld(::ros::NodeHandle private_nh, GazeboWorldOptions options)
    : private_nh_(std::move(private_nh)), root_nh_("/"), options_(std::move(options)) {
  world_name_ = mechsim_world_name(options_.world);
  // The world is built once here, for its checks and what it lists; each robot's simulation
  // builds it again with the robot (one physics per robot while a world holds one).
  const WorldSummary world = describe_world(world_name_);
  has_ground_ = world.has_ground;
  gravity_ = world.gravity;
  world_models_ = world.sdf_models;
  world_model_poses_ = world.sdf_model_poses;
  sdf_model_count_ = world_models_.size();
  if (!description::is_sdf_world_file(world_name_) && has_ground_) {
    world_models_.push_back("ground_plane");
    world_model_poses_.emplace_back();
  }
  for (const std::string& n : world.not_simulated) ROS_WARN_STREAM("mechsim: " << world_name_ << ": not simulated: " << n);
  if (world.real_time_factor > 0.0 && options_.real_time_factor == 1.0) options_.real_time_factor = world.real_time_factor;
  if (world.max_step_size > 0.0 && std::abs(world.max_step_size - options_.period) > 1e-12) {
    ROS_WARN_STREAM("mechsim: " << world_name_ << ": max_step_size " << world.max_step_size << " s: mechsim steps at "
                                << options_.period << " s (its controllers' 1 kHz tick)");
  }
  paused_.store(options_.paused);
  real_time_factor_.store(options_.real_time_factor);
  clock_pub_ = root_nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  advertise_world_services();
  advertise_model_services();
  advertise_topics();
}

GazeboWorld::~GazeboWorld() { stop(); }

void GazeboWorld::start() {
  stop_.store(false);
  clock_thread_ = std::thread([this] { clock_loop(); });
}

void GazeboWorld::stop() {
  stop_.store(true);
  if (clock_thread_.joinable()) clock_thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  if (!world_) return;
  world_->stop();  // the world's loop: every robot stops with it
  // The robots' simulations go with the world's: they are forgotten, not deleted.
  std::vector<Robot> robots;
  {
    std::lock_guard<std::mutex> clock(clock_mutex_);
    std::lock_guard<std::mutex> guard(robots_mutex_);
    for (Robot& r : robots_) {
      r.node->bridge().detach_from_world();
      robots.push_back(std::move(r));
    }
    robots_.clear();
  }
  robots.clear();
  std::lock_guard<std::mutex> clock(clock_mutex_);
  world_.reset();
}

const GazeboWorld::Robot* GazeboWorld::find_robot(const std::string& name) const {
  for (const Robot& r : robots_)
    if (r.name == name) return &r;
  return nullptr;
}

double GazeboWorld::time() const {
  std::lock_guard<std::mutex> lock(clock_mutex_);
  return host() != nullptr ? host()->bridge().time() : static_cast<double>(ticks_) * options_.period;
}

bool GazeboWorld::paused() const {
  std::lock_guard<std::mutex> lock(clock_mutex_);
  return host() != nullptr ? host()->bridge().paused() : paused_.load();
}

void GazeboWorld::set_paused(bool paused) {
  std::lock_guard<std::mutex> lock(clock_mutex_);
  paused_.store(paused);
  if (host() == nullptr) return;
  if (paused) host()->bridge().pause();
  else host()->bridge().unpause();
}

void GazeboWorld::clock_loop() {
  // Time advances from an anchor (wall, ticks), so that the pace holds over the loop's sleeps.
  Clock::time_point anchor_wall = Clock::now();
  std::uint64_t anchor_ticks = 0;
  bool anchored = false;
  double next_clock = 0.0;
  Clock::time_point last_clock{};
  while (!stop_.load() && ::ros::ok()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::lock_guard<std::mutex> lock(clock_mutex_);
    if (host() != nullptr) {  // the world's loop runs the clock
      anchored = false;
      continue;
    }
    const auto now = Clock::now();
    bool publish = false;
    if (paused_.load()) {
      anchored = false;
      const std::uint64_t steps = pending_steps_.exchange(0);
      ticks_ += steps;
      publish = steps > 0 || now - last_clock > std::chrono::milliseconds(100);
    } else {
      if (!anchored) {
        anchor_wall = now;
        anchor_ticks = ticks_;
        anchored = true;
      }
      const double rtf = real_time_factor_.load() > 0.0 ? real_time_factor_.load() : 1.0;
      const double elapsed = std::chrono::duration<double>(now - anchor_wall).count();
      ticks_ = anchor_ticks + static_cast<std::uint64_t>(elapsed * rtf / options_.period);
      publish = static_cast<double>(ticks_) * options_.period + 1e-9 >= next_clock;
    }
    if (publish) {
      const double t = static_cast<double>(ticks_) * options_.period;
      rosgraph_msgs::Clock clock;
      clock.clock = ::ros::Time(t);
      clock_pub_.publish(clock);
      last_clock = now;
      const double rate = options_.node.clock_publish_rate;
      next_clock = t + (rate > 0.0 ? 1.0 / rate : 0.0);
    }
  }
}

bool GazeboWorld::spawn(const std::string& name, const std::string& xml, const std::string& robot_namespace,
                        const description::Pose& X_RM, const std::string& reference_frame, std::string* status) {
  auto refuse = [&](const std::string& why) {
    *status = why;
    ROS_ERROR_STREAM("mechsim: spawn of '" << name << "' refused: " << why);
    return false;
  };
  if (name.empty()) return refuse("model_name is empty");
  if (name.find("::") != std::string::npos) return refuse("model_name '" + name + "' holds '::' (Gazebo's scope separator)");
  if (find_robot(name) != nullptr) return refuse("a model named '" + name + "' is in the world already");
  for (const std::string& m : world_models_)
    if (m == name) return refuse("a model named '" + name + "' is in the world already");
  if (!finite(X_RM)) return refuse("initial_pose is not finite");
  const description::Quat& q = X_RM.orientation;
  const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (norm < 1e-9) return refuse("initial_pose's orientation is a zero quaternion");
  // The frame the pose is given in: the world (gazebo_ros: "" or "world"), or one of the world's
  // static models, whose frames are the world's.
  if (!reference_frame.empty() && reference_frame != "world" && reference_frame != "map") {
    bool known = false;
    for (const std::string& m : world_models_) known = known || reference_frame == m || reference_frame.rfind(m + "::", 0) == 0;
    if (!known) return refuse("reference_frame '" + reference_frame + "' is no entity of this world");
  }
  description::Pose X_WM = X_RM;
  X_WM.orientation = {q.w / norm, q.x / norm, q.y / norm, q.z / norm};

  BridgeOptions bridge;
  const std::string source = "model '" + name + "'";
  try {
    if (xml.find("<sdf") != std::string::npos) {
      description::SdfModel sdf = description::parse_sdf_model(xml, source);
      for (const std::string& n : sdf.not_simulated) ROS_WARN_STREAM("mechsim: " << source << ": not simulated: " << n);
      for (const std::string& w : sdf.warnings) ROS_WARN_STREAM("mechsim: " << source << ": " << w);
      bridge.robot = std::move(sdf.robot);
      X_WM = physics::compose(physics::compose(X_WM, sdf.pose), sdf.root_offset);
    } else {
      std::vector<std::string> warnings;
      description::UrdfOptions urdf;
      urdf.lenient = options_.lenient;
      bridge.robot = description::parse_urdf_string(xml, source, urdf, &warnings);
      for (const std::string& w : warnings) ROS_WARN_STREAM("mechsim: " << source << ": " << w);
    }
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  bridge.robot.name = name;
  NodeOptions node = options_.node;
  node.gazebo_services = false;
  bool pr2 = false;
  // gazebo_ros_control's <robotNamespace>, else the spawn's (gazebo_ros gives each plugin the
  // spawn's namespace when it names none), else the root.
  std::string ns = plugin_namespace(bridge.robot, &pr2);
  if (ns.empty()) ns = robot_namespace;
  if (ns.empty()) ns = "/";
  if (ns.front() != '/') ns = "/" + ns;
  node.robot_namespace = ns;
  node.pr2 = node.pr2 || pr2;
  node.controller_manager = has_controller_manager_plugin(bridge.robot);
  for (const Robot& r : robots_) {
    // Two controller managers cannot answer under one name.
    if (node.controller_manager && r.controller_manager && r.ns == ns) {
      return refuse("robot namespace '" + ns + "' is model '" + r.name + "'s: give each robot its own (spawn_model " +
                    "-robot_namespace, or the gazebo_ros_control plugin's <robotNamespace>)");
    }
    if (r.pr2 && node.pr2) {
      return refuse("model '" + r.name + "' has /pr2_controller_manager already: one PR2 controller manager per world");
    }
  }
  bridge.world = world_name_;
  bridge.x = X_WM.position.x;
  bridge.y = X_WM.position.y;
  bridge.z = X_WM.position.z;
  rpy_of(X_WM.orientation, bridge.roll, bridge.pitch, bridge.yaw);
  bridge.real_time_factor = real_time_factor_.load();
  bridge.period = options_.period;
  const std::string key = ns.find_first_not_of('/') == std::string::npos ? "" : ns.substr(ns.find_first_not_of('/'));
  control::Params root;
  bridge.controller_params = key.empty() ? root : root.child_or_create(key);
  bridge.parameter_root = root;

  if (!world_) open_world(status);
  if (!world_) return refuse(*status);
  Robot robot;
  robot.name = name;
  robot.ns = ns;
  robot.pr2 = node.pr2;
  robot.controller_manager = node.controller_manager;
  try {
    // Taken into the running world between two ticks of its loop.
    robot.node = std::make_unique<SimNode>(private_nh_, std::move(bridge), node, world_.get());
  } catch (const std::exception& e) {
    close_world_if_empty();
    return refuse(e.what());
  }
  for (const std::string& w : robot.node->bridge().physics_warnings()) ROS_WARN_STREAM("mechsim: physics: " << w);
  robot.node->start();
  SimNode& added = *robot.node;
  {
    std::lock_guard<std::mutex> clock(clock_mutex_);
    std::lock_guard<std::mutex> robots(robots_mutex_);
    robots_.push_back(std::move(robot));
  }
  ROS_INFO_STREAM("mechsim: spawned '" << name << "' at t = " << added.bridge().time() << " s"
                                       << ", controller manager at " << ns << (ns.back() == '/' ? "" : "/")
                                       << "controller_manager" << (paused() ? " (paused)" : ""));
  *status = "SpawnModel: Successfully spawned entity";
  return true;
}

void GazeboWorld::open_world(std::string* status) {
  // A world with no robot of its own: the robots come in as its other robots.
  BridgeOptions bridge;
  try {
    bridge.robot = description::parse_urdf_string("<robot name=\"world\"><link name=\"world\"/></robot>", "the world",
                                                  description::UrdfOptions{});
  } catch (const std::exception& e) {
    *status = e.what();
    return;
  }
  bridge.world = world_name_;
  bridge.real_time_factor = real_time_factor_.load();
  bridge.period = options_.period;
  NodeOptions node = options_.node;
  node.gazebo_services = false;
  node.world_only = true;
  node.pr2 = false;
  node.publish_tf = false;
  std::lock_guard<std::mutex> lock(clock_mutex_);  // the clock stands still while the world's loop takes over
  bridge.start_time = static_cast<double>(ticks_) * options_.period;
  bridge.paused = paused_.load();
  try {
    auto world = std::make_unique<SimNode>(private_nh_, std::move(bridge), node);
    for (const std::string& w : world->bridge().physics_warnings()) ROS_WARN_STREAM("mechsim: physics: " << w);
    if (std::abs(gravity_.z + 9.81) > 1e-12 || gravity_.x != 0.0 || gravity_.y != 0.0) world->bridge().set_gravity(gravity_);
    world->bridge().add_observer([this](double t) { publish_states(t); });
    world_ = std::move(world);
  } catch (const std::exception& e) {
    *status = e.what();
    return;
  }
  world_->start();
}

void GazeboWorld::close_world_if_empty() {
  if (!world_ || !robots_.empty()) return;
  std::lock_guard<std::mutex> lock(clock_mutex_);
  world_->stop();
  const double t = world_->bridge().time();
  paused_.store(world_->bridge().paused());
  world_.reset();
  ticks_ = static_cast<std::uint64_t>(std::llround(t / options_.period));
}

bool GazeboWorld::remove(const std::string& name, std::string* status) {
  const auto it = std::find_if(robots_.begin(), robots_.end(), [&](const Robot& r) { return r.name == name; });
  if (it == robots_.end()) {
    for (const std::string& m : world_models_) {
      if (m == name) {
        *status = "DeleteModel: '" + name + "' is part of the world mechsim built (" + world_name_ + "): it stays";
        return false;
      }
    }
    *status = "DeleteModel: model [" + name + "] does not exist";
    return false;
  }
  Robot gone;
  {
    std::lock_guard<std::mutex> clock(clock_mutex_);
    std::lock_guard<std::mutex> robots(robots_mutex_);
    gone = std::move(*it);
    robots_.erase(it);
  }
  // The world goes on: the robot's outputs off, its controllers stopped and unloaded (topics
  // first), then out of the physics.
  gone.node->stop();
  const std::vector<std::string> controllers = gone.node->unload_all_controllers();
  const BridgeResult r = gone.node->bridge().remove_from_world();
  if (!r.ok) ROS_ERROR_STREAM("mechsim: deleting '" << name << "': " << r.error);
  gone.node.reset();
  close_world_if_empty();
  ROS_INFO_STREAM("mechsim: deleted '" << name << "' (" << controllers.size() << " controllers stopped and unloaded)");
  *status = "DeleteModel: successfully deleted model";
  return true;
}

bool GazeboWorld::step(std::uint64_t steps, std::string* status) {
  if (!paused()) {
    *status = "the simulation is running: pause it first (/gazebo/pause_physics)";
    return false;
  }
  if (steps == 0) return true;
  // The call holds every /gazebo service until its steps ran: a count of 2^64 - 1 used to hold
  // them (pause and unpause included) for ever.
  if (steps > kMaxSteps) {
    *status = "steps " + std::to_string(steps) + " is more than " + std::to_string(kMaxSteps) +
              " per call (the /gazebo services wait for the steps to run); step in smaller parts";
    return false;
  }
  if (host() != nullptr) {
    host()->bridge().request_steps(steps);
  } else {
    pending_steps_.fetch_add(steps);
  }
  // A tick of a robot takes well under 10 ms of wall time; a minute is a stuck loop.
  const auto deadline = Clock::now() + std::chrono::duration<double>(60.0 + 0.01 * static_cast<double>(steps));
  while (host() != nullptr ? host()->bridge().pending_steps() > 0 : pending_steps_.load() > 0) {
    if (Clock::now() > deadline || !::ros::ok()) {
      if (host() != nullptr) host()->bridge().cancel_steps();
      *status = "the steps did not run in time (the simulation loop is stuck?)";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

void GazeboWorld::advertise_world_services() {
  using Empty = std_srvs::Empty;
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>(
      "/gazebo/pause_physics", [this](Empty::Request&, Empty::Response&) {
        std::lock_guard<std::mutex> lock(mutex_);
        set_paused(true);
        return true;
      }));
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>(
      "/gazebo/unpause_physics", [this](Empty::Request&, Empty::Response&) {
        std::lock_guard<std::mutex> lock(mutex_);
        set_paused(false);
        return true;
      }));
  // Both resets put the robot back at its spawn pose and restart its running controllers; time
  // goes on (sim/simulation.hpp says why).
  auto reset = [this](Empty::Request&, Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (host() != nullptr) host()->bridge().request_reset();
    return true;
  };
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>("/gazebo/reset_simulation", reset));
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>("/gazebo/reset_world", reset));

  using Spawn = gazebo_msgs::SpawnModel;
  auto spawn_service = [this](Spawn::Request& req, Spawn::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto& p = req.initial_pose;
    const description::Pose pose{{p.position.x, p.position.y, p.position.z},
                                 {p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}};
    res.success = spawn(req.model_name, req.model_xml, req.robot_namespace, pose, req.reference_frame,
                        &res.status_message);
    return true;
  };
  services_.push_back(root_nh_.advertiseService<Spawn::Request, Spawn::Response>("/gazebo/spawn_urdf_model", spawn_service));
  services_.push_back(root_nh_.advertiseService<Spawn::Request, Spawn::Response>("/gazebo/spawn_sdf_model", spawn_service));

  using Delete = gazebo_msgs::DeleteModel;
  services_.push_back(root_nh_.advertiseService<Delete::Request, Delete::Response>(
      "/gazebo/delete_model", [this](Delete::Request& req, Delete::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        res.success = remove(req.model_name, &res.status_message);
        return true;
      }));

  using Step = mechsim_msgs::StepSimulation;
  services_.push_back(root_nh_.advertiseService<Step::Request, Step::Response>(
      "/gazebo/step_simulation", [this](Step::Request& req, Step::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        res.success = step(req.steps, &res.status_message);
        res.sim_time = time();
        return true;
      }));
}

}  // namespace mechsim::ros
