// SimNode: one model's nodes over its bridge (sim_node.hpp).
#include "ros2/sim_node.hpp"

#include <algorithm>

#include "ros2/controller_manager.hpp"
#include "ros2/conversions.hpp"

namespace mechsim::ros2 {

SimNode::SimNode(Participant& participant, Outbox& outbox, bridge::SimBridge& bridge, NodeOptions options)
    : options_(std::move(options)), participant_(&participant), bridge_(&bridge), outbox_(&outbox) {
  options_.robot_namespace = normalize_namespace(options_.robot_namespace);
  for (const std::string& note : bridge_->joint_drive_notes()) participant_->log(note);
  if (options_.publish_tf) {
    state_ = std::make_unique<StatePublisher>(*participant_, *outbox_, "/", bridge_->robot(), options_.robot_description, "");
    state_->publish_static(bridge_->time());
    topic_lines_.push_back("/tf, /tf_static, /robot_description (robot_state_publisher)");
  }
  sensors_ = std::make_unique<SensorTopics>(*participant_, *bridge_, *outbox_);
  for (const std::string& t : sensors_->topics()) topic_lines_.push_back(t);
  // gazebo_ros2_control's controller manager: its node, services and parameters.
  manager_ = std::make_unique<ControllerManagerNode>(*this);
  for (const std::string& t : manager_->service_lines()) topic_lines_.push_back(t);
}

SimNode::~SimNode() {
  stop_actions("the model is leaving the world");
  stop();
  manager_.reset();  // its services and actions first: they call into the bindings below
  std::vector<std::string> names;
  {
    std::lock_guard<std::mutex> b(bindings_mutex_);
    for (const auto& n : controller_nodes_) names.push_back(n->name());
  }
  for (const std::string& n : names) unbind(n);
  sensors_.reset();
  state_.reset();
}

void SimNode::start() {
  running_->store(true);
  if (observing_) return;
  observing_ = true;
  std::shared_ptr<std::atomic<bool>> running = running_;
  bridge_->add_observer([this, running](double time) {
    if (running->load()) on_tick(time);
  });
}

void SimNode::stop() {
  running_->store(false);
  // An observer that was running when the flag turned has returned once the loop starts a tick.
  if (observing_) bridge_->wait_for_loop();
}

void SimNode::on_idle(double time) {
  if (!running_->load() || !state_ || last_tf_ == time) return;
  bridge_->joint_positions(joint_positions_);
  state_->publish(time, joint_positions_, bridge_->base_pose());
  last_tf_ = time;
}

void SimNode::on_tick(double time) {
  if (!publishing_.load(std::memory_order_relaxed)) {
    sensors_->disable_all();
    return;
  }
  sensors_->publish();
  publish_controller_states(time);
  if (manager_) manager_->on_tick(time);
  if (state_ && (time + 1e-9 >= next_tf_ || time < next_tf_ - 1.0)) {
    bridge_->joint_positions(joint_positions_);
    state_->publish(time, joint_positions_, bridge_->base_pose());
    tf_messages_.fetch_add(1, std::memory_order_relaxed);
    last_tf_ = time;
    next_tf_ = next_due_after(time, options_.tf_rate > 0.0 ? 1.0 / options_.tf_rate : 0.0);
  }
}

bridge::BridgeResult SimNode::load_controller(const std::string& name) {
  try {
    check_node_name(name);
  } catch (const NameError& e) {
    return {false, "'" + name + "' cannot be a controller's node name: " + e.what()};
  }
  std::lock_guard<std::mutex> lock(manager_mutex_);
  bridge::BridgeResult r = bridge_->load_controller(name);
  if (!r.ok) return r;
  try {
    bind(name);
  } catch (const std::exception& e) {
    unbind(name);
    bridge_->unload_controller(name);
    return {false, "controller '" + name + "': its ROS 2 topics could not be made: " + e.what()};
  }
  return r;
}

bridge::BridgeResult SimNode::unload_controller(const std::string& name) {
  std::lock_guard<std::mutex> lock(manager_mutex_);
  if (!bridge_->is_loaded(name)) return {false, "controller '" + name + "' is not loaded"};
  unbind(name);
  return bridge_->unload_controller(name);
}

bridge::BridgeResult SimNode::start_controllers(const std::vector<std::string>& names) {
  std::string errors;
  std::vector<std::string> start;
  for (const std::string& n : names) {
    if (!bridge_->is_loaded(n)) {
      const bridge::BridgeResult r = load_controller(n);
      if (!r.ok) {
        errors += (errors.empty() ? "" : "; ") + r.error;
        continue;
      }
    }
    start.push_back(n);
  }
  if (!start.empty()) {
    const bridge::BridgeResult r = bridge_->switch_controllers(start, {}, false, 5.0);
    if (!r.ok) errors += (errors.empty() ? "" : "; ") + r.error;
  }
  return {errors.empty(), errors};
}

std::size_t SimNode::unload_all_controllers() {
  stop();
  if (manager_) manager_->forget_all();
  std::lock_guard<std::mutex> lock(manager_mutex_);
  outbox_->flush();
  const std::vector<std::string> names = bridge_->stop_all_controllers_now();
  for (auto it = names.rbegin(); it != names.rend(); ++it) {
    unbind(*it);
    const bridge::BridgeResult r = bridge_->unload_controller(*it);
    if (!r.ok) participant_->log("could not unload controller '" + *it + "': " + r.error);
  }
  return names.size();
}

std::vector<std::string> SimNode::topic_lines() const {
  std::lock_guard<std::mutex> lock(bindings_mutex_);
  return topic_lines_;
}

NodeStats SimNode::stats() const {
  NodeStats s;
  s.tf_messages = tf_messages_.load();
  s.commands = commands_.load();
  s.commands_rejected = commands_rejected_.load();
  return s;
}

}  // namespace mechsim::ros2
