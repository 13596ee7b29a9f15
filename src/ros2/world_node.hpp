#pragma once
// WorldNode: gzserver with gazebo_ros (ROS 2) on a ROS 2 domain: the ROS 2 binding of
// bridge::World (src/bridge/world.hpp, where the world's semantics live). It owns the DDS
// participant, the world, node `/gazebo` with /clock and gazebo_ros' services, mapped onto World:
//
//   gazebo_ros_init     /pause_physics /unpause_physics /reset_simulation /reset_world (std_srvs/srv/Empty)
//   gazebo_ros_factory  /spawn_entity /delete_entity /get_model_list
//   gazebo_ros_state    /get_entity_state /set_entity_state (node `gazebo_ros_state`)
//
// and one SimNode per model (its controller manager, controllers, plugins and sensors). The
// robot given on `mechsim ros2`'s command line is spawned as spawn_entity.py would (its
// controllers from the command line's YAML); models spawned through /spawn_entity get their
// controllers' parameters from their description's gazebo_ros2_control <parameters> files.
//
// Threads: the world's loop thread ticks and calls ticked()/idle(); the services' slow work
// (spawn, delete, state changes) runs on one worker thread (worker.hpp), in request order.

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bridge/world.hpp"
#include "ros2/dds_participant.hpp"
#include "ros2/node.hpp"
#include "ros2/outbox.hpp"
#include "ros2/sim_node.hpp"
#include "ros2/worker.hpp"

namespace mechsim::ros2 {

struct WorldNodeOptions {
  bridge::WorldOptions world;
  ParticipantOptions participant;
  double clock_rate = 0.0;  // Hz of simulated time of /clock; 0: every tick
  NodeOptions node;         // each model's node options (namespace and robot_state_publisher per model)
};

// What the command line's robot brings that a spawn request does not: its parsed description,
// its controllers' parameters, robot_state_publisher.
struct CommandLineRobot {
  description::RobotModel robot;
  std::string urdf;
  std::string robot_namespace;
  control::Params controller_params;
  std::optional<control::Params> parameter_root;
  description::Pose pose;  // X_WM (z above the ground)
};

class WorldNode : public bridge::WorldBinding {
 public:
  // Throws std::runtime_error when the participant or the world cannot be made.
  explicit WorldNode(WorldNodeOptions options);
  ~WorldNode() override;
  WorldNode(const WorldNode&) = delete;
  WorldNode& operator=(const WorldNode&) = delete;

  void start();  // the world's loop, then the services
  void stop();   // every model goes with the world
  // Spawns the command line's robot; ok = false with why.
  bridge::BridgeResult spawn_robot(CommandLineRobot robot);

  bridge::World& world() { return world_; }
  Participant& participant() { return *participant_; }
  // The node of a model (nullptr when none); valid while the model is in the world.
  SimNode* model_node(const std::string& model);
  std::vector<std::string> node_lines() const;   // "topic (type)" of every model, for the start-up log
  void set_publishing(bool on);                   // every model's outputs (--bench-rtf)
  // Loop thread: called after each tick (--bench-rtf measures there).
  void set_tick_hook(std::function<void(double)> hook) { tick_hook_ = std::move(hook); }
  std::uint64_t clock_messages() const;
  // Every model's action servers, summed (the end-of-run line, tests).
  ActionStats action_stats() const;

  // ---- bridge::WorldBinding
  void prepare_model(const bridge::ModelInfo& info, bridge::BridgeOptions& options) override;
  void model_added(const bridge::ModelInfo& info, bridge::SimBridge& model) override;
  void model_removing(const bridge::ModelInfo& info, bridge::SimBridge& model) override;
  void model_removed(const bridge::ModelInfo& info) override;
  void ticked(double time) override;
  void idle(double time) override;
  void warn(const std::string& message) override;
  void info(const std::string& message) override;

 private:
  struct Services {  // gazebo_ros' services (gazebo_services.cpp)
    std::unique_ptr<Node> state_node;  // gazebo_ros_state's
    std::vector<std::shared_ptr<void>> servers;
  };
  void advertise_services();
  void publish_clock(double time);

  WorldNodeOptions options_;
  std::unique_ptr<Participant> participant_;
  std::unique_ptr<Node> gazebo_node_;
  std::unique_ptr<Publisher<rosgraph_msgs::msg::Clock>> clock_pub_;
  std::unique_ptr<Outbox> outbox_;
  bridge::World world_;
  std::unique_ptr<Worker> worker_;
  std::unique_ptr<Services> services_;

  mutable std::mutex nodes_mutex_;
  std::map<std::string, std::unique_ptr<SimNode>> nodes_;  // by model name
  std::map<std::string, CommandLineRobot> pending_;        // command-line robots being spawned
  std::map<std::string, bool> publish_tf_;                 // models with robot_state_publisher
  std::atomic<bool> publishing_{true};
  std::string last_added_;  // the last model added (set in the spawning thread: the worker's)

  std::function<void(double)> tick_hook_;
  double next_clock_ = 0.0;  // loop thread
  std::chrono::steady_clock::time_point last_clock_{};
  double last_idle_clock_ = -1.0;
};

}  // namespace mechsim::ros2
