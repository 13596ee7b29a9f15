#pragma once
// A simulated world and its robot on a ROS 2 domain, as gzserver with gazebo_ros and
// gazebo_ros2_control presents them (README.md, "Nodes and topics"). One SimNode owns:
//   - the DDS participant (dds_participant.hpp) and the SimBridge (world, robot, controllers);
//   - the loop thread that ticks the world and, after each tick, publishes what is due;
//   - node `gazebo` (/clock; the services /pause_physics, /unpause_physics, /reset_simulation,
//     /reset_world of gazebo_ros_init, std_srvs/srv/Empty), node `robot_state_publisher` (/tf, /tf_static,
//     /robot_description), node `<robot ns>/controller_manager`;
//   - one node per loaded controller in the robot namespace with its topics
//     (controller_topics.cpp);
//   - the sensors' topics, one node per sensor plugin (sensor_topics.hpp).
//
// Threads: the loop thread ticks and fills what is due; the outbox thread writes it (outbox.hpp).
// Command samples arrive on Fast DDS's threads and are written to the controllers' ports
// (thread-safe, bridge/README.md) under `bindings_mutex_`.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <mechsim_ros2_msgs/rosgraph_msgs.hpp>
#include <mechsim_ros2_msgs/std_srvs.hpp>

#include "bridge/sim_bridge.hpp"
#include "ros2/dds_participant.hpp"
#include "ros2/node.hpp"
#include "ros2/outbox.hpp"
#include "ros2/sensor_topics.hpp"
#include "ros2/service.hpp"
#include "ros2/state_publisher.hpp"

namespace mechsim::ros2 {

struct NodeOptions {
  ParticipantOptions participant;
  // The controller manager's namespace (gazebo_ros2_control's <ros><namespace>, or gazebo_ros_control's
  // <robotNamespace>): its node, the controllers' nodes and their topics live there.
  std::string robot_namespace = "/";
  // Remappings applied to the controllers' nodes (gazebo_ros2_control's <ros><remapping>).
  std::vector<Remap> controller_remaps;
  // Hz of simulated time of /clock; 0: every tick.
  double clock_rate = 0.0;
  bool publish_tf = true;
  double tf_rate = 20.0;  // Hz of sim time (robot_state_publisher's publish_frequency default)
  std::string robot_description;  // the URDF published on robot_description
  // Humble's diff_drive_controller parameter: true (its default) takes geometry_msgs/msg/TwistStamped
  // on ~/cmd_vel, false geometry_msgs/msg/Twist on ~/cmd_vel_unstamped. Jazzy has TwistStamped only.
  bool use_stamped_vel = true;
};

// What the node publishes and counts, for logs and tests.
struct NodeStats {
  std::uint64_t clock_messages = 0;     // written
  std::uint64_t clock_coalesced = 0;    // times replaced by a newer one before they went out
  std::uint64_t dropped = 0;            // samples the outbox had no room for
  std::uint64_t tf_messages = 0;
  std::uint64_t commands = 0;           // command samples written to ports
  std::uint64_t commands_rejected = 0;  // refused by a port (wrong size, not finite)
};

class SimNode {
 public:
  // Throws std::runtime_error when the robot, world or DDS participant cannot be made.
  SimNode(bridge::BridgeOptions bridge, NodeOptions options);
  ~SimNode();
  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;

  void start();  // the loop thread
  void stop();   // joins it
  bridge::SimBridge& bridge() { return *bridge_; }
  Participant& participant() { return *participant_; }

  // Loads a controller and makes its node and topics; refusals name why.
  bridge::BridgeResult load_controller(const std::string& name);
  // Loads (when not loaded) and starts these controllers, best effort; the result names what failed.
  bridge::BridgeResult start_controllers(const std::vector<std::string>& names);
  // Stops every controller, drops their topics and unloads them (the loop stopped first).
  void unload_all_controllers();
  // Publishing on (the default) or off: off, a tick publishes nothing and samples no sensor, as
  // without the ROS 2 layer (`mechsim ros2 --bench-rtf` measures what publishing costs). Any thread.
  void set_publishing(bool on) { publishing_.store(on, std::memory_order_relaxed); }
  // "topic (type)" per topic the node publishes or subscribes, for the start-up log.
  std::vector<std::string> topic_lines() const;
  NodeStats stats() const;

 private:
  struct Binding;
  void loop();
  void on_tick(double time);
  void publish_clock(double time);
  void publish_controller_states(double time);  // controller_topics.cpp
  void bind(const std::string& controller);       // controller_topics.cpp
  void unbind(const std::string& controller);     // controller_topics.cpp

  NodeOptions options_;
  std::unique_ptr<Participant> participant_;
  std::unique_ptr<bridge::SimBridge> bridge_;
  std::unique_ptr<Node> gazebo_node_;
  std::unique_ptr<Node> manager_node_;
  std::unique_ptr<Publisher<rosgraph_msgs::msg::Clock>> clock_pub_;
  std::unique_ptr<Outbox> outbox_;  // writes what the loop thread fills (outbox.hpp)
  std::vector<std::unique_ptr<ServiceServer<std_srvs::srv::Empty>>> world_services_;
  std::unique_ptr<StatePublisher> state_;
  std::unique_ptr<SensorTopics> sensors_;

  mutable std::mutex bindings_mutex_;
  std::vector<std::shared_ptr<Binding>> bindings_;
  std::vector<std::unique_ptr<Node>> controller_nodes_;  // under bindings_mutex_
  std::mutex manager_mutex_;                             // one load/switch at a time

  std::thread loop_thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> publishing_{true};
  double next_clock_ = 0.0, next_tf_ = 0.0, last_tf_ = -1.0;
  std::chrono::steady_clock::time_point last_clock_{};
  std::vector<double> joint_positions_;
  std::string divergence_;
  std::atomic<std::uint64_t> clock_messages_{0}, tf_messages_{0}, commands_{0}, commands_rejected_{0};
  std::vector<std::string> topic_lines_;  // under bindings_mutex_
};

}  // namespace mechsim::ros2
