#pragma once
// mechsim_node: the simulation as a ROS 1 node, a drop-in for gazebo_ros + gazebo_ros_control +
// controller_manager (README.md, "The node"). One SimNode owns:
//   - the SimBridge (world, robot, controller manager) and the loop thread that ticks it;
//   - /clock, and gazebo's /gazebo/{pause_physics, unpause_physics, reset_simulation, reset_world};
//   - the controller manager services under <robot namespace>/controller_manager/ (cm_services.cpp);
//   - each loaded controller's topics (controller_bindings.cpp);
//   - the built-in robot state publisher (tf_publisher.cpp);
//   - the sensors' topics, as their Gazebo plugins name them (sensor_publishers.cpp);
//   - the model plugins' topics (diff drive, skid steer, planar move, ...: model_plugin_topics.cpp);
//   - for a PR2, pr2_controller_manager's own outputs: joint_states, mechanism_statistics and
//     the latched /calibrated (pr2_outputs.cpp).
//
// Threads: the loop thread ticks and runs the observers (clock, controller state topics, TF);
// ROS callbacks (services, command subscribers) run on the node's spinner threads. The binding
// table is shared by both under `bindings_mutex_`.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <ros/ros.h>

#include "ros/bridge_names.hpp"
#include "ros/model_plugin_topics.hpp"
#include "ros/sensor_publishers.hpp"
#include "ros/tf_publisher.hpp"

namespace mechsim::ros {

// SwitchController's strictness as the controller manager takes it (cm_services.cpp): STRICT (2)
// or BEST_EFFORT (1) as given, 0 as BEST_EFFORT with a warning (ros_control), anything else -1
// (refused, logged). The PR2's pr2_mechanism_msgs use the same values.
int switch_strictness(int strictness);

struct NodeOptions {
  std::string robot_namespace = "/";  // where the controllers' parameters and topics live
  double state_publish_rate = 50.0;   // Hz (sim time) of <controller>/state; 0: every tick
  double odom_publish_rate = 50.0;    // Hz (sim time) of <controller>/odom; 0: every tick
  // Hz (sim time) of /clock; 0: every tick, as gazebo_ros publishes it unless its
  // ~pub_clock_frequency is set (gazebo_ros_api_plugin.cpp: pub_clock_frequency_ starts at 0).
  double clock_publish_rate = 0.0;
  bool publish_tf = true;
  bool publish_odom_tf = false;
  double tf_rate = 50.0;          // Hz (sim time)
  std::string odom_frame = "odom";
  bool pr2 = false;               // also the pr2_mechanism_msgs services under /pr2_controller_manager
  // /gazebo/{pause_physics, unpause_physics, reset_simulation, reset_world}; false when a
  // GazeboWorld (gazebo_world.hpp) holds this node as one of its models and offers them itself.
  bool gazebo_services = true;
  // Live view over the Foxglove WebSocket protocol (~foxglove_port; < 0: off, 0: any free port).
  int foxglove_port = -1;
  std::string foxglove_address = "127.0.0.1";
  double foxglove_rate = 30.0;   // Hz (sim time) of its /tf, /joint_states, /odom
  std::string robot_description;  // its /robot_description (the URDF)
  // <ns>/controller_manager/* (GazeboWorld: only for a model with gazebo_ros_control's plugin, as
  // Gazebo; a model without one, a spawned SDF box, has none to clash with another's).
  bool controller_manager = true;
};

class SimNode {
 public:
  // `nh` is the node's private handle (~). The node's own simulation: its parameters from the
  // parameter server (load_parameters), its loop thread and /clock. Throws std::runtime_error when
  // the robot, world or parameters are unusable.
  SimNode(::ros::NodeHandle nh, BridgeOptions bridge, NodeOptions options);
  // A model of a Gazebo world (bridge::World, gazebo_world.hpp): the world owns `model` and its
  // loop ticks it; the node has its outputs (topics, controller manager services), no loop thread
  // or /clock. The model must outlive the node.
  SimNode(::ros::NodeHandle nh, SimBridge& model, NodeOptions options);
  ~SimNode();
  // The controllers' parameters under `robot_namespace` on the parameter server (and
  // gazebo_ros_control's absolute /gazebo_ros_control) into bridge.controller_params /
  // parameter_root, before the simulation is built.
  static void load_parameters(const std::string& robot_namespace, BridgeOptions& bridge);

  void start();  // loop thread (a world's model: its outputs start)
  void stop();   // joins it (a world's model: its outputs stop; returns once the last ran)
  // After stop(): stops every controller (their stopping() runs) and unloads them, topics first
  // (a model being deleted). Returns their names.
  std::vector<std::string> unload_all_controllers();
  SimBridge& bridge() { return *bridge_; }

 private:
  struct Binding;
  void loop();
  void on_tick(double time);
  void publish_controller_states(double time);
  void publish_tf(double time);  // loop thread  // loop thread (controller_bindings.cpp)
  void set_up();  // both constructors' common part
  void advertise_sim_services();
  void advertise_controller_manager();
  void advertise_pr2_controller_manager();
  void advertise_pr2_outputs();           // pr2_outputs.cpp
  void publish_pr2_outputs(double time);  // loop thread
  // Re-reads <ns>/<controller> from the parameter server into the manager's Params tree.
  void refresh_params(const std::string& controller);
  // Controller lifecycle with bindings (controller_bindings.cpp).
  BridgeResult load(const std::string& name);
  BridgeResult unload(const std::string& name);
  void bind(const std::string& controller);
  void unbind(const std::string& controller);
  std::string controller_ns(const std::string& controller) const;

  ::ros::NodeHandle private_nh_;
  ::ros::NodeHandle root_nh_;
  ::ros::NodeHandle robot_nh_;  // the robot namespace
  NodeOptions options_;
  std::unique_ptr<SimBridge> owned_bridge_;  // the node's own simulation; null for a world's model
  SimBridge* bridge_ = nullptr;
  std::unique_ptr<TfPublisher> tf_;
  std::unique_ptr<SensorPublishers> sensors_;  // the robot's simulated sensors (loop thread)
  std::unique_ptr<ModelPluginTopics> plugins_;  // the robot's Gazebo model plugins (model_plugin_topics.hpp)

  ::ros::Publisher clock_pub_;
  ::ros::Subscriber e_stop_sub_;  // gazebo_ros_control's <eStopTopic>, when the description names one
  std::vector<::ros::ServiceServer> services_;
  std::chrono::steady_clock::time_point last_clock_{};  // wall time of the last /clock
  double next_clock_ = 0.0;              // s, sim time of the next /clock
  double next_tf_ = 0.0;                 // s, sim time of the next /tf message
  double last_tf_ = -1.0;                // s, sim time of the last one
  std::vector<double> joint_positions_;  // reused by the loop thread

  // pr2_controller_manager's outputs (loop thread; only with options_.pr2).
  ::ros::Publisher pr2_joint_states_pub_, pr2_statistics_pub_, calibrated_pub_;
  double joint_state_period_ = 0.01;  // s (sim time); 0: every tick
  double statistics_period_ = 1.0;    // s (sim time); 0: every tick
  double next_joint_states_ = 0.0, next_statistics_ = 0.0;  // s, sim time when due
  JointStatesData pr2_joint_states_;
  MechanismStatisticsData pr2_statistics_;

  std::mutex bindings_mutex_;
  std::vector<std::shared_ptr<Binding>> bindings_;
  std::mutex manager_mutex_;  // one controller-manager service at a time (as ros_control)

  std::thread loop_thread_;
  std::atomic<bool> stop_{false};
  bool other_robot_ = false;  // a model of a world (no loop of its own)
  // A world's model: on_tick runs (start() to stop()); shared with the bridge's observer.
  std::shared_ptr<std::atomic<bool>> outputs_on_ = std::make_shared<std::atomic<bool>>(false);
  std::string divergence_;
  double loop_cpu_seconds_ = 0.0;  // CPU time of the loop thread, set when it ends
};

}  // namespace mechsim::ros
