// WorldNode: the world's loop and /clock, each model's node (world_node.hpp).
#include "ros2/world_node.hpp"

#include <mechsim_ros2_msgs/rosgraph_msgs.hpp>

#include "ros2/conversions.hpp"

namespace mechsim::ros2 {

WorldNode::WorldNode(WorldNodeOptions options)
    : options_(std::move(options)),
      participant_(std::make_unique<Participant>(options_.participant)),
      world_(options_.world) {
  // gzserver's ROS node: gazebo_ros_init's /clock.
  gazebo_node_ = std::make_unique<Node>(*participant_, "/", "gazebo");
  clock_pub_ = gazebo_node_->create_publisher<rosgraph_msgs::msg::Clock>("/clock", Qos::clock());
  outbox_ = std::make_unique<Outbox>([this](double time) {
    rosgraph_msgs::msg::Clock clock;
    clock.clock = to_time(time);
    clock_pub_->publish(clock);
  });
  worker_ = std::make_unique<Worker>();
}

WorldNode::~WorldNode() {
  stop();
  services_.reset();
  worker_.reset();  // runs what is queued (answers refusals: the world is stopped)
  outbox_.reset();
  clock_pub_.reset();
  gazebo_node_.reset();
  participant_.reset();
}

void WorldNode::start() {
  world_.start(this);
  advertise_services();
}

void WorldNode::stop() {
  {
    // The actions poll their controllers' ports on a thread of their own: they stop before the
    // world lets go of the models' simulations.
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    for (const auto& [name, node] : nodes_) node->stop_actions("the simulation is stopping");
  }
  world_.stop();
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  nodes_.clear();
}

bridge::BridgeResult WorldNode::spawn_robot(CommandLineRobot robot) {
  bridge::SpawnRequest request;
  request.name = robot.robot.name;
  request.robot_namespace = robot.robot_namespace;
  request.pose = robot.pose;
  request.model = robot.robot;
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    publish_tf_[request.name] = options_.node.publish_tf;
    pending_[request.name] = std::move(robot);
  }
  std::string status;
  const bridge::BridgeResult r = world_.spawn(request, &status);
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  pending_.erase(request.name);
  return r;
}

SimNode* WorldNode::model_node(const std::string& model) {
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  const auto it = nodes_.find(model);
  return it == nodes_.end() ? nullptr : it->second.get();
}

std::vector<std::string> WorldNode::node_lines() const {
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  std::vector<std::string> out;
  for (const auto& [name, node] : nodes_)
    for (const std::string& l : node->topic_lines()) out.push_back(l);
  return out;
}

void WorldNode::set_publishing(bool on) {
  publishing_.store(on);
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  for (const auto& [name, node] : nodes_) node->set_publishing(on);
}

std::uint64_t WorldNode::clock_messages() const { return outbox_->stats().clocks; }

ActionStats WorldNode::action_stats() const {
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  ActionStats sum;
  for (const auto& [name, node] : nodes_) sum += node->action_stats();
  return sum;
}

void WorldNode::prepare_model(const bridge::ModelInfo& info, bridge::BridgeOptions& options) {
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  const auto it = pending_.find(info.name);
  if (it == pending_.end()) return;
  // The command line's robot: its controllers' YAML.
  options.controller_params = it->second.controller_params;
  options.parameter_root = it->second.parameter_root;
}

void WorldNode::model_added(const bridge::ModelInfo& info, bridge::SimBridge& model) {
  NodeOptions node = options_.node;
  node.robot_namespace = info.robot_namespace;
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    const auto tf = publish_tf_.find(info.name);
    node.publish_tf = tf != publish_tf_.end() && tf->second;
    const auto p = pending_.find(info.name);
    node.robot_description = p != pending_.end() ? p->second.urdf : "";
  }
  auto added = std::make_unique<SimNode>(*participant_, *outbox_, model, node);
  added->set_publishing(publishing_.load());
  added->start();
  participant_->log("model '" + info.name + "': controller manager " + (info.robot_namespace == "/" ? "" : info.robot_namespace) +
                    "/controller_manager");
  std::lock_guard<std::mutex> lock(nodes_mutex_);
  nodes_[info.name] = std::move(added);
  last_added_ = info.name;
}

void WorldNode::model_removing(const bridge::ModelInfo& info, bridge::SimBridge&) {
  SimNode* node = model_node(info.name);
  if (node == nullptr) return;
  // Its actions end, its outputs off, then its controllers stopped and unloaded (topics first).
  node->stop_actions("the model is being deleted");
  node->stop();
  const std::size_t unloaded = node->unload_all_controllers();
  participant_->log("deleting '" + info.name + "': " + std::to_string(unloaded) + " controllers stopped and unloaded");
}

void WorldNode::model_removed(const bridge::ModelInfo& info) {
  std::unique_ptr<SimNode> gone;
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    const auto it = nodes_.find(info.name);
    if (it == nodes_.end()) return;
    gone = std::move(it->second);
    nodes_.erase(it);
    publish_tf_.erase(info.name);
  }
  outbox_->flush();  // nothing queued still refers to its publishers
  gone.reset();
}

void WorldNode::warn(const std::string& message) { participant_->log("warning: " + message); }
void WorldNode::info(const std::string& message) { participant_->log(message); }

void WorldNode::publish_clock(double time) {
  outbox_->set_clock(time);
  last_clock_ = std::chrono::steady_clock::now();
}

void WorldNode::ticked(double time) {
  if (publishing_.load(std::memory_order_relaxed) && (time + 1e-9 >= next_clock_ || time < next_clock_ - 1.0)) {
    publish_clock(time);
    next_clock_ = next_due_after(time, options_.clock_rate > 0.0 ? 1.0 / options_.clock_rate : 0.0);
  }
  if (tick_hook_) tick_hook_(time);
  outbox_->end_of_tick();
}

void WorldNode::idle(double time) {
  // Time stands still but /clock keeps coming (10 Hz of wall time), as gazebo_ros' throttle runs
  // on real time; transient local keeps the last one for late subscribers anyway.
  const auto now = std::chrono::steady_clock::now();
  if (now - last_clock_ > std::chrono::milliseconds(100) || time != last_idle_clock_) {
    publish_clock(time);
    last_idle_clock_ = time;
  }
  {
    std::lock_guard<std::mutex> lock(nodes_mutex_);
    for (const auto& [name, node] : nodes_) node->on_idle(time);
  }
  outbox_->end_of_tick();
}

}  // namespace mechsim::ros2
