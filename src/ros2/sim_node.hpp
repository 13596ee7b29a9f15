#pragma once
// One model of the world (a robot: the one `mechsim ros2 ROBOT` spawns, or one spawned through
// /spawn_entity) on a ROS 2 domain, as gazebo_ros2_control and gazebo_ros' model plugins present
// it (README.md, "Nodes and topics"). The world, /clock and gazebo_ros' services are WorldNode's
// (world_node.hpp); a SimNode owns, for its model's bridge:
//   - node `<robot ns>/controller_manager` with ros2_control's services, and one node per loaded
//     controller with its topics (controller_topics.cpp), parameters and actions
//     (controller_manager.cpp, parameters.hpp, actions.hpp);
//   - for the robot given on the command line, robot_state_publisher (/tf, /tf_static,
//     /robot_description);
//   - the sensors' topics, one node per sensor plugin (sensor_topics.hpp).
//
// Threads: the world's loop thread ticks the model and runs on_tick (fills what is due; the
// outbox thread writes it). Command samples arrive on Fast DDS's threads and are written to the
// controllers' ports (thread-safe, bridge/README.md) under `bindings_mutex_`.

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
#include "ros2/action_server.hpp"
#include "ros2/dds_participant.hpp"
#include "ros2/node.hpp"
#include "ros2/outbox.hpp"
#include "ros2/sensor_topics.hpp"
#include "ros2/service.hpp"
#include "ros2/state_publisher.hpp"

namespace mechsim::ros2 {

struct NodeOptions {
  // The controller manager's namespace (gazebo_ros2_control's <ros><namespace>, or gazebo_ros_control's
  // <robotNamespace>): its node, the controllers' nodes and their topics live there.
  std::string robot_namespace = "/";
  // Remappings applied to the controllers' nodes (gazebo_ros2_control's <ros><remapping>).
  std::vector<Remap> controller_remaps;
  // robot_state_publisher for this model (the command line's robot; a spawned model's users run
  // their own).
  bool publish_tf = true;
  double tf_rate = 20.0;  // Hz of sim time (robot_state_publisher's publish_frequency default)
  std::string robot_description;  // the URDF published on robot_description
  // Humble's diff_drive_controller parameter: true (its default) takes geometry_msgs/msg/TwistStamped
  // on ~/cmd_vel, false geometry_msgs/msg/Twist on ~/cmd_vel_unstamped. Jazzy has TwistStamped only.
  bool use_stamped_vel = true;
};

// What the node publishes and counts, for logs and tests.
struct NodeStats {
  std::uint64_t tf_messages = 0;
  std::uint64_t commands = 0;           // command samples written to ports
  std::uint64_t commands_rejected = 0;  // refused by a port (wrong size, not finite)
};

class ControllerManagerNode;

class SimNode {
 public:
  // Throws std::runtime_error when its nodes cannot be made. `bridge` outlives the SimNode.
  SimNode(Participant& participant, Outbox& outbox, bridge::SimBridge& bridge, NodeOptions options);
  ~SimNode();
  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;

  // Its outputs on (the bridge's tick observer publishes) and off (the model is leaving).
  void start();
  void stop();
  bridge::SimBridge& bridge() { return *bridge_; }
  Participant& participant() { return *participant_; }
  const NodeOptions& options() const { return options_; }
  // Loop thread, while the world is paused: /tf once after a change (a reset, a set state).
  void on_idle(double time);

  // Loads a controller and makes its node and topics; refusals name why.
  bridge::BridgeResult load_controller(const std::string& name);
  // Loads (when not loaded) and starts these controllers, best effort; the result names what failed.
  bridge::BridgeResult start_controllers(const std::vector<std::string>& names);
  // Drops a controller's topics and unloads it (it must not be running).
  bridge::BridgeResult unload_controller(const std::string& name);
  // Stops every controller, drops their topics and unloads them (outputs stopped first); how
  // many were loaded.
  std::size_t unload_all_controllers();
  // ros2_control's controller manager services on `<ns>/controller_manager` (controller_manager.cpp).
  ControllerManagerNode* controller_manager() { return manager_.get(); }
  // Publishing on (the default) or off: off, a tick publishes nothing and samples no sensor, as
  // without the ROS 2 layer (`mechsim ros2 --bench-rtf` measures what publishing costs). Any thread.
  void set_publishing(bool on) { publishing_.store(on, std::memory_order_relaxed); }
  // "topic (type)" per topic the node publishes or subscribes, for the start-up log.
  std::vector<std::string> topic_lines() const;
  NodeStats stats() const;
  // Every action server of its controllers, summed.
  ActionStats action_stats() const;
  // Its action servers stop polling their ports and end their goals (CANCELED, `why` logged):
  // before the model's simulation goes (the world stopping). Idempotent.
  void stop_actions(const std::string& why);

 private:
  struct Binding;
  void on_tick(double time);
  void publish_controller_states(double time);  // controller_topics.cpp
  void bind(const std::string& controller);       // controller_topics.cpp
  void unbind(const std::string& controller);     // controller_topics.cpp

  NodeOptions options_;
  Participant* participant_;
  bridge::SimBridge* bridge_;
  Outbox* outbox_;  // writes what the loop thread fills (outbox.hpp)
  std::unique_ptr<StatePublisher> state_;
  std::unique_ptr<SensorTopics> sensors_;

  // Polls the controllers' action servers (20 Hz of wall time); before the bindings, which
  // remove their servers from it.
  std::unique_ptr<ActionPoller> poller_ = std::make_unique<ActionPoller>();
  mutable std::mutex bindings_mutex_;
  std::vector<std::shared_ptr<Binding>> bindings_;
  std::vector<std::unique_ptr<Node>> controller_nodes_;  // under bindings_mutex_
  std::mutex manager_mutex_;                             // one load/switch at a time

  std::unique_ptr<ControllerManagerNode> manager_;  // after the bindings' members: goes first
  // The tick observer's: false once stop() ran (the bridge keeps its observer while it lives).
  std::shared_ptr<std::atomic<bool>> running_ = std::make_shared<std::atomic<bool>>(false);
  bool observing_ = false;
  std::atomic<bool> publishing_{true};
  double next_tf_ = 0.0, last_tf_ = -1.0;
  std::vector<double> joint_positions_;
  std::atomic<std::uint64_t> tf_messages_{0}, commands_{0}, commands_rejected_{0};
  std::vector<std::string> topic_lines_;  // under bindings_mutex_
};

}  // namespace mechsim::ros2
