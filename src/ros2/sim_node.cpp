// SimNode: construction, the loop thread and /clock (sim_node.hpp).
#include "ros2/sim_node.hpp"

#include <algorithm>

#include "ros2/conversions.hpp"

namespace mechsim::ros2 {

SimNode::SimNode(bridge::BridgeOptions bridge, NodeOptions options) : options_(std::move(options)) {
  options_.robot_namespace = normalize_namespace(options_.robot_namespace);
  participant_ = std::make_unique<Participant>(options_.participant);
  bridge_ = std::make_unique<bridge::SimBridge>(std::move(bridge));
  for (const std::string& note : bridge_->joint_drive_notes()) participant_->log(note);
  // gzserver's ROS node: gazebo_ros_init's /clock.
  gazebo_node_ = std::make_unique<Node>(*participant_, "/", "gazebo");
  clock_pub_ = gazebo_node_->create_publisher<rosgraph_msgs::msg::Clock>("/clock", Qos::clock());
  outbox_ = std::make_unique<Outbox>([this](double time) {
    rosgraph_msgs::msg::Clock clock;
    clock.clock = to_time(time);
    clock_pub_->publish(clock);
  });
  // gazebo_ros_init's world services (both resets put the robot back at its spawn pose and
  // restart its controllers; time goes on: sim/simulation.hpp says why).
  using Empty = std_srvs::srv::Empty;
  auto serve = [this](const char* name, std::function<void()> action) {
    world_services_.push_back(std::make_unique<ServiceServer<Empty>>(
        *gazebo_node_, name, [action](const Empty::Request&, Empty::Response&) {
          action();
          return true;
        }));
  };
  serve("/pause_physics", [this] { bridge_->pause(); });
  serve("/unpause_physics", [this] { bridge_->unpause(); });
  serve("/reset_simulation", [this] { bridge_->request_reset(); });
  serve("/reset_world", [this] { bridge_->request_reset(); });
  // gazebo_ros2_control's controller manager (its services are issue 37's).
  manager_node_ = std::make_unique<Node>(*participant_, options_.robot_namespace, "controller_manager");
  if (options_.publish_tf) {
    state_ = std::make_unique<StatePublisher>(*participant_, *outbox_, "/", bridge_->robot(), options_.robot_description, "");
    state_->publish_static(bridge_->time());
  }
  sensors_ = std::make_unique<SensorTopics>(*participant_, *bridge_, *outbox_);
  bridge_->add_observer([this](double time) { on_tick(time); });
  topic_lines_.push_back("/clock (rosgraph_msgs/msg/Clock, " +
                         (options_.clock_rate > 0.0 ? std::to_string(options_.clock_rate) + " Hz" : std::string("every tick")) +
                         " of sim time)");
  if (state_) {
    topic_lines_.push_back("/tf, /tf_static, /robot_description (robot_state_publisher)");
  }
  topic_lines_.push_back("/pause_physics, /unpause_physics, /reset_simulation, /reset_world (std_srvs/srv/Empty services, "
                         "rmw_fastrtps and rmw_cyclonedds clients)");
  for (const std::string& t : sensors_->topics()) topic_lines_.push_back(t);
}

SimNode::~SimNode() {
  stop();
  {
    std::lock_guard<std::mutex> lock(manager_mutex_);
    std::vector<std::string> names;
    {
      std::lock_guard<std::mutex> b(bindings_mutex_);
      for (const auto& n : controller_nodes_) names.push_back(n->name());
    }
    for (const std::string& n : names) unbind(n);
  }
  // What is queued goes out, then the endpoints go, before the participant.
  world_services_.clear();
  outbox_.reset();
  sensors_.reset();
  state_.reset();
  clock_pub_.reset();
  manager_node_.reset();
  gazebo_node_.reset();
  bridge_.reset();
  participant_.reset();
}

void SimNode::start() {
  stop_.store(false);
  loop_thread_ = std::thread([this] { loop(); });
}

void SimNode::stop() {
  stop_.store(true);
  if (loop_thread_.joinable()) loop_thread_.join();
}

void SimNode::loop() {
  // Chunks of 10 ms of simulation time keep stop() and pause() responsive at any pace.
  while (!stop_.load()) {
    if (bridge_->paused()) {
      bridge_->run_for(bridge_->period(), nullptr);  // applies a pending reset, sleeps 1 ms
      // Time stands still but /clock keeps coming (10 Hz of wall time), as gazebo_ros' throttle
      // runs on real time; transient local keeps the last one for late subscribers anyway.
      const auto now = std::chrono::steady_clock::now();
      if (now - last_clock_ > std::chrono::milliseconds(100)) publish_clock(bridge_->time());
      outbox_->end_of_tick();
      if (state_ && last_tf_ != bridge_->time()) {
        bridge_->joint_positions(joint_positions_);
        state_->publish(bridge_->time(), joint_positions_, bridge_->base_pose());
        last_tf_ = bridge_->time();
        outbox_->end_of_tick();
      }
      continue;
    }
    std::string error;
    if (!bridge_->run_for(0.01, &error)) {
      if (error != divergence_) participant_->log(error);
      divergence_ = error;
    }
  }
}

void SimNode::publish_clock(double time) {
  outbox_->set_clock(time);
  last_clock_ = std::chrono::steady_clock::now();
}

void SimNode::on_tick(double time) {
  if (!publishing_.load(std::memory_order_relaxed)) {
    sensors_->disable_all();
    return;
  }
  if (time + 1e-9 >= next_clock_ || time < next_clock_ - 1.0) {
    publish_clock(time);
    next_clock_ = next_due_after(time, options_.clock_rate > 0.0 ? 1.0 / options_.clock_rate : 0.0);
  }
  sensors_->publish();
  publish_controller_states(time);
  if (state_ && (time + 1e-9 >= next_tf_ || time < next_tf_ - 1.0)) {
    bridge_->joint_positions(joint_positions_);
    state_->publish(time, joint_positions_, bridge_->base_pose());
    tf_messages_.fetch_add(1, std::memory_order_relaxed);
    last_tf_ = time;
    next_tf_ = next_due_after(time, options_.tf_rate > 0.0 ? 1.0 / options_.tf_rate : 0.0);
  }
  outbox_->end_of_tick();
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

void SimNode::unload_all_controllers() {
  stop();
  std::lock_guard<std::mutex> lock(manager_mutex_);
  outbox_->flush();
  const std::vector<std::string> names = bridge_->stop_all_controllers_now();
  for (auto it = names.rbegin(); it != names.rend(); ++it) {
    unbind(*it);
    const bridge::BridgeResult r = bridge_->unload_controller(*it);
    if (!r.ok) participant_->log("could not unload controller '" + *it + "': " + r.error);
  }
}

std::vector<std::string> SimNode::topic_lines() const {
  std::lock_guard<std::mutex> lock(bindings_mutex_);
  return topic_lines_;
}

NodeStats SimNode::stats() const {
  NodeStats s;
  const OutboxStats o = outbox_->stats();
  s.clock_messages = o.clocks;
  s.clock_coalesced = o.coalesced;
  s.dropped = o.dropped;
  s.tf_messages = tf_messages_.load();
  s.commands = commands_.load();
  s.commands_rejected = commands_rejected_.load();
  return s;
}

}  // namespace mechsim::ros2
