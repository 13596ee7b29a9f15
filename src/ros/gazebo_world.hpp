#pragma once
// GazeboWorld: mechsim_node as gazebo_ros' gzserver (`~gazebo:=true`, what gazebo_ros'
// empty_world.launch starts): the ROS 1 binding of bridge::World (src/bridge/world.hpp, where the
// world's semantics live). It offers gazebo_ros' /gazebo/* API with gazebo_msgs' wire format
// (gazebo_services.cpp) and topics (gazebo_topics.cpp), /clock from the world's loop, and gives
// every model of the world its ROS outputs: a SimNode over the model's bridge (its controller
// manager under its robot namespace, topics, model plugins and sensors).
//
// Threads: the world's loop thread ticks and calls ticked()/idle() (/clock, model_states); the
// services run on the node's spinner threads and call the world, which serialises them.

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "bridge/world.hpp"
#include "ros/sim_node.hpp"

namespace mechsim::ros {

struct GazeboWorldOptions {
  bridge::WorldOptions world;
  NodeOptions node;  // each model's node options (its namespace comes from the spawn)
  // Hz (sim time) of /gazebo/model_states and link_states while subscribed; 0: every tick
  // (gazebo_ros publishes them at every world update).
  double model_states_rate = 0.0;
  // gazebo_ros' ~enable_ros_network: false leaves /clock only (no /gazebo services or topics, no
  // physics dynamic_reconfigure); the models' own controller managers, plugins and sensors stay.
  bool enable_ros_network = true;
  // mechsim's own /mechsim/step_simulation (stepping while paused), outside gazebo_ros' API.
  bool step_service = true;
};

class GazeboWorld : public bridge::WorldBinding {
 public:
  // Throws std::runtime_error when the world cannot be built (names the file or world).
  GazeboWorld(::ros::NodeHandle private_nh, GazeboWorldOptions options);
  ~GazeboWorld() override;
  GazeboWorld(const GazeboWorld&) = delete;
  GazeboWorld& operator=(const GazeboWorld&) = delete;

  void start();  // the world's loop
  void stop();   // stops it; every model goes with it

  // ---- bridge::WorldBinding
  void prepare_model(const bridge::ModelInfo& info, BridgeOptions& options) override;
  void model_added(const bridge::ModelInfo& info, SimBridge& model) override;
  void model_removing(const bridge::ModelInfo& info, SimBridge& model) override;
  void model_removed(const bridge::ModelInfo& info) override;
  void ticked(double time) override;
  void idle(double time) override;
  void warn(const std::string& message) override;
  void info(const std::string& message) override;

 private:
  struct Topics;  // model_states, link_states, performance_metrics (gazebo_topics.cpp)

  struct Reconfigure;  // the physics dynamic_reconfigure server (gazebo_reconfigure.cpp)

  void advertise_world_services();  // gazebo_world.cpp
  void advertise_model_services();  // gazebo_services.cpp
  void advertise_light_services();  // gazebo_services.cpp
  void start_reconfigure();         // gazebo_reconfigure.cpp
  void advertise_topics();          // gazebo_topics.cpp
  void publish_states(double time);  // the world's loop thread
  void publish_performance();        // 1 Hz wall
  void publish_clock(double time);

  ::ros::NodeHandle private_nh_, root_nh_;
  GazeboWorldOptions options_;
  bridge::World world_;

  std::mutex nodes_mutex_;
  std::map<std::string, std::unique_ptr<SimNode>> nodes_;  // by model name
  std::map<std::string, std::size_t> unloaded_;  // controllers unloaded by model_removing, for its log line

  ::ros::Publisher clock_pub_;
  double next_clock_ = 0.0;  // s, sim time of the next /clock (loop thread)
  std::chrono::steady_clock::time_point last_clock_{};  // wall time of the last /clock
  double last_idle_clock_ = -1.0;  // s: the time /clock last went out while paused

  std::vector<::ros::ServiceServer> services_;
  // /gazebo/set_model_state, set_link_state, set_model_states (gazebo_ros' topic forms)
  std::vector<::ros::Subscriber> subscribers_;
  std::unique_ptr<Topics> topics_;
  std::unique_ptr<Reconfigure> reconfigure_;
};

}  // namespace mechsim::ros
