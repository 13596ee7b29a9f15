#pragma once
// GazeboWorld: mechsim_node as gazebo_ros' gzserver (`~gazebo:=true`, what gazebo_ros'
// empty_world.launch starts). The world starts empty: its clock runs (paused or not) and robots
// come in through /gazebo/spawn_urdf_model or spawn_sdf_model (gazebo_ros' spawn_model), as in
// Gazebo. It offers gazebo_ros' /gazebo/* API with gazebo_msgs' wire format (gazebo_services.cpp)
// and topics (gazebo_topics.cpp).
//
// Models: the world's own (a ground plane, static boxes of an SDF world) and the robots spawned
// into it. While any robot is in, the world is a SimNode of its own with no robot (`world_`,
// NodeOptions::world_only: the loop thread, /clock, the world's physics), and each robot is
// another robot of it (sim::Simulation::add_other; SimNode with a host): its own controller
// manager under its robot namespace, topics, model plugins and sensors, in the one physics (they
// collide). Spawning one during a run takes it in between two ticks: the robots already there go
// on undisturbed (no time jump, no controller restart); deleting one stops and unloads its
// controllers first, the others going on. The world's SimNode comes with the first robot (from
// the world's time) and goes with the last (the clock goes on from its time).
//
// Threads: while no robot is in, the clock thread advances time (paced at the real-time factor,
// real time when that is 0) and publishes /clock; while one is, the world's SimNode runs the loop
// thread, and everything that reads or changes the physics runs there between ticks (SimBridge's
// model API). Services run on the node's spinner threads, one at a time (`mutex_`).

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <ros/ros.h>

#include "description/pose.hpp"
#include "ros/sim_node.hpp"

namespace mechsim::ros {

struct GazeboWorldOptions {
  std::string world = "empty";  // mechsim world name, heightmap, or an SDF .world file
  bool paused = false;
  double real_time_factor = 1.0;  // 0: as fast as possible (the empty world keeps real time)
  double period = 0.001;          // s
  NodeOptions node;               // each robot's node options (its namespace comes from the spawn)
  bool lenient = true;            // description problems Gazebo tolerates are warnings
  // Hz (sim time) of /gazebo/model_states and link_states while subscribed; 0: every tick
  // (gazebo_ros publishes them at every world update).
  double model_states_rate = 0.0;
};

class GazeboWorld {
 public:
  // Throws std::runtime_error when the world cannot be built (names the file or world).
  GazeboWorld(::ros::NodeHandle private_nh, GazeboWorldOptions options);
  ~GazeboWorld();
  GazeboWorld(const GazeboWorld&) = delete;
  GazeboWorld& operator=(const GazeboWorld&) = delete;

  void start();  // the clock thread
  void stop();   // stops the robot's loop and the clock thread

 private:
  struct Entity;  // a frame a request names (gazebo_services.cpp)
  struct Topics;  // model_states, link_states, performance_metrics (gazebo_topics.cpp)

  // ---- gazebo_world.cpp: lifecycle
  void clock_loop();
  void advertise_world_services();
  bool spawn(const std::string& name, const std::string& xml, const std::string& robot_namespace,
             const description::Pose& X_RM, const std::string& reference_frame, std::string* status);
  bool remove(const std::string& name, std::string* status);
  double time() const;  // s
  bool paused() const;
  void set_paused(bool paused);
  // `steps` ticks while paused; answers when they ran. At most kMaxSteps (100 s of simulated
  // time at 1 kHz) per call.
  static constexpr std::uint64_t kMaxSteps = 100000;
  bool step(std::uint64_t steps, std::string* status);
  // ---- gazebo_services.cpp: the state, property and force services
  void advertise_model_services();
  bool resolve(const std::string& name, Entity& out, std::string* status) const;
  std::vector<std::string> model_names() const;
  // ---- gazebo_topics.cpp
  void advertise_topics();
  void publish_states(double time);  // the world's loop thread
  void publish_performance();        // 1 Hz wall

  ::ros::NodeHandle private_nh_, root_nh_;
  GazeboWorldOptions options_;
  std::string world_name_;
  // The world's own models, by name: an SDF world's (world_model_poses_: where the SDF puts them;
  // a robot's physics has the moving ones), or the ground plane of mechsim's worlds.
  std::vector<std::string> world_models_;
  std::vector<description::Pose> world_model_poses_;
  std::size_t sdf_model_count_ = 0;  // the first ones are the SDF world's (the robot's physics has them)
  bool has_ground_ = true;
  description::Vec3 gravity_{0.0, 0.0, -9.81};  // m/s^2, for robots spawned later

  std::mutex mutex_;  // one /gazebo service at a time; guards the robots' lifetimes
  struct Robot {
    std::string name;       // the model's name
    std::string ns;         // its controller manager's namespace
    bool pr2 = false;       // pr2_controller_manager's services (one per world: they have fixed names)
    bool controller_manager = false;  // <ns>/controller_manager/* (gazebo_ros_control's plugin)
    std::unique_ptr<SimNode> node;
  };
  // The world's loop while a robot is in (no robot of its own); null otherwise. Set and reset
  // under mutex_ and clock_mutex_.
  std::unique_ptr<SimNode> world_;
  // In spawn order. Changed by services under mutex_ and, since the loop thread reads it
  // (publish_states), also under robots_mutex_, never held while waiting for the loop.
  std::vector<Robot> robots_;
  mutable std::mutex robots_mutex_;
  SimNode* host() const { return world_.get(); }
  const Robot* find_robot(const std::string& name) const;
  // The world's SimNode, from the clock's time (spawn of the first robot; `status` says why not);
  // and back to the clock thread when no robot is left.
  void open_world(std::string* status);
  void close_world_if_empty();

  // The clock while no robot is in (clock_mutex_ guards ticks_ against the spawn's handover).
  mutable std::mutex clock_mutex_;
  std::uint64_t ticks_ = 0;
  std::atomic<bool> paused_{false};
  std::atomic<std::uint64_t> pending_steps_{0};
  std::atomic<double> real_time_factor_{1.0};
  std::atomic<bool> stop_{false};
  std::thread clock_thread_;
  ::ros::Publisher clock_pub_;

  std::vector<::ros::ServiceServer> services_;
  ::ros::Subscriber model_state_sub_;  // /gazebo/set_model_state
  std::unique_ptr<Topics> topics_;
};

}  // namespace mechsim::ros
