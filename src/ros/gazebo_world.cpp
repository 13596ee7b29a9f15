// GazeboWorld: the ROS 1 binding's lifecycle: the world's loop and /clock, each model's node, and
// the world services (spawn, delete, pause, reset, step) (gazebo_world.hpp).
#include "ros/gazebo_world.hpp"

#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/SpawnModel.h>
#include <mechsim_msgs/StepSimulation.h>
#include <rosgraph_msgs/Clock.h>
#include <std_srvs/Empty.h>

#include "ros/gazebo_reconfigure.hpp"
#include "ros/gazebo_topics.hpp"

namespace mechsim::ros {

GazeboWorld::GazeboWorld(::ros::NodeHandle private_nh, GazeboWorldOptions options)
    : private_nh_(std::move(private_nh)), root_nh_("/"), options_(std::move(options)), world_(options_.world) {
  clock_pub_ = root_nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  // gazebo_ros sets /use_sim_time when nobody has.
  if (!root_nh_.hasParam("/use_sim_time")) root_nh_.setParam("/use_sim_time", true);
  // The topics now (the loop publishes them from its first tick); the services once the world
  // runs (start()), so that a client that sees them can call them.
  if (options_.enable_ros_network) advertise_topics();
  else ROS_INFO_STREAM("mechsim: ~enable_ros_network is false: no /gazebo topics or services (only /clock)");
}

GazeboWorld::~GazeboWorld() { stop(); }

void GazeboWorld::start() {
  world_.start(this);
  if (!options_.enable_ros_network) return;
  advertise_world_services();
  advertise_model_services();
  advertise_light_services();
  start_reconfigure();
  if (options_.step_service) {
    using Step = mechsim_msgs::StepSimulation;
    services_.push_back(root_nh_.advertiseService<Step::Request, Step::Response>(
        "/mechsim/step_simulation", [this](Step::Request& req, Step::Response& res) {
          const BridgeResult r = world_.step(req.steps);
          res.success = r.ok;
          res.status_message = r.error;
          res.sim_time = world_.time();
          return true;
        }));
  }
}

void GazeboWorld::stop() {
  reconfigure_.reset();
  world_.stop();
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  nodes_.clear();
}

void GazeboWorld::prepare_model(const bridge::ModelInfo& info, BridgeOptions& options) {
  SimNode::load_parameters(info.robot_namespace, options);
}

void GazeboWorld::model_added(const bridge::ModelInfo& info, SimBridge& model) {
  NodeOptions node = options_.node;
  node.robot_namespace = info.robot_namespace;
  node.pr2 = node.pr2 || info.pr2;
  node.controller_manager = info.controller_manager;
  auto added = std::make_unique<SimNode>(private_nh_, model, node);
  added->start();
  ROS_INFO_STREAM("mechsim: model '" << info.name << "': controller manager at " << info.robot_namespace
                                     << (info.robot_namespace.back() == '/' ? "" : "/") << "controller_manager");
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  nodes_[info.name] = std::move(added);
}

void GazeboWorld::model_removing(const bridge::ModelInfo& info, SimBridge&) {
  SimNode* node = nullptr;
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    const auto it = nodes_.find(info.name);
    if (it == nodes_.end()) return;
    node = it->second.get();
  }
  // Its outputs off, then its controllers stopped and unloaded (topics first).
  node->stop();
  const std::size_t unloaded = node->unload_all_controllers().size();
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  unloaded_[info.name] = unloaded;
}

void GazeboWorld::model_removed(const bridge::ModelInfo& info) {
  std::unique_ptr<SimNode> gone;
  std::size_t unloaded = 0;
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    const auto it = nodes_.find(info.name);
    if (it == nodes_.end()) return;
    gone = std::move(it->second);
    nodes_.erase(it);
    if (const auto u = unloaded_.find(info.name); u != unloaded_.end()) {
      unloaded = u->second;
      unloaded_.erase(u);
    }
  }
  ROS_INFO_STREAM("mechsim: deleted '" << info.name << "' (" << unloaded << " controllers stopped and unloaded)");
}

void GazeboWorld::warn(const std::string& message) { ROS_WARN_STREAM("mechsim: " << message); }
void GazeboWorld::info(const std::string& message) { ROS_INFO_STREAM("mechsim: " << message); }

void GazeboWorld::publish_clock(double time) {
  rosgraph_msgs::Clock clock;
  clock.clock = ::ros::Time(time);
  clock_pub_.publish(clock);
  last_clock_ = std::chrono::steady_clock::now();
}

void GazeboWorld::ticked(double time) {
  if (time + 1e-9 >= next_clock_) {
    publish_clock(time);
    const double rate = options_.node.clock_publish_rate;
    next_clock_ = time + (rate > 0.0 ? 1.0 / rate : 0.0);
  }
  if (topics_) publish_states(time);
}

void GazeboWorld::idle(double time) {
  // Time stands still but /clock keeps coming (10 Hz of wall time), as gazebo does while paused.
  const auto now = std::chrono::steady_clock::now();
  if (now - last_clock_ > std::chrono::milliseconds(100) || time != last_idle_clock_) {
    publish_clock(time);
    last_idle_clock_ = time;
  }
}

void GazeboWorld::advertise_world_services() {
  using Empty = std_srvs::Empty;
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>(
      "/gazebo/pause_physics", [this](Empty::Request&, Empty::Response&) {
        world_.set_paused(true);
        return true;
      }));
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>(
      "/gazebo/unpause_physics", [this](Empty::Request&, Empty::Response&) {
        world_.set_paused(false);
        return true;
      }));
  auto reset = [this](Empty::Request&, Empty::Response&) {
    world_.reset();
    return true;
  };
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>("/gazebo/reset_simulation", reset));
  services_.push_back(root_nh_.advertiseService<Empty::Request, Empty::Response>("/gazebo/reset_world", reset));

  using Spawn = gazebo_msgs::SpawnModel;
  auto spawn_service = [this](Spawn::Request& req, Spawn::Response& res) {
    const auto& p = req.initial_pose;
    bridge::SpawnRequest spawn;
    spawn.name = req.model_name;
    spawn.xml = req.model_xml;
    spawn.robot_namespace = req.robot_namespace;
    spawn.reference_frame = req.reference_frame;
    spawn.pose = {{p.position.x, p.position.y, p.position.z},
                  {p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}};
    const BridgeResult r = world_.spawn(spawn, &res.status_message);
    res.success = r.ok;
    if (!r.ok) res.status_message = r.error;
    return true;
  };
  services_.push_back(root_nh_.advertiseService<Spawn::Request, Spawn::Response>("/gazebo/spawn_urdf_model", spawn_service));
  services_.push_back(root_nh_.advertiseService<Spawn::Request, Spawn::Response>("/gazebo/spawn_sdf_model", spawn_service));

  using Delete = gazebo_msgs::DeleteModel;
  services_.push_back(root_nh_.advertiseService<Delete::Request, Delete::Response>(
      "/gazebo/delete_model", [this](Delete::Request& req, Delete::Response& res) {
        const BridgeResult r = world_.remove(req.model_name, &res.status_message);
        res.success = r.ok;
        if (!r.ok) res.status_message = r.error;
        return true;
      }));
}

}  // namespace mechsim::ros
