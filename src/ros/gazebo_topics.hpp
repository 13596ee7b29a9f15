#pragma once
// GazeboWorld's topics (gazebo_topics.cpp): what the world's loop thread and the 1 Hz timer keep.

#include <atomic>
#include <vector>

#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/ModelStates.h>
#include <ros/ros.h>

#include "ros/gazebo_world.hpp"

namespace mechsim::ros {

struct GazeboWorld::Topics {
  ::ros::Publisher model_states, link_states, performance;
  // Subscriber counts from roscpp's connect callbacks: the loop thread loads an atomic.
  std::atomic<int> model_subscribers{0}, link_subscribers{0};
  double next_states = 0.0;  // s, sim time (loop thread)
  // The world's loop thread fills these (reused: no allocation once sized).
  std::vector<bridge::NamedState> models, links;
  gazebo_msgs::ModelStates model_msg;
  gazebo_msgs::LinkStates link_msg;
  ::ros::WallTimer performance_timer;
  double last_sim = -1.0;
  ::ros::WallTime last_wall;
};

}  // namespace mechsim::ros
