#pragma once
// GazeboWorld's physics dynamic_reconfigure server (gazebo_reconfigure.cpp).

#include <dynamic_reconfigure/server.h>
#include <mechsim_gazebo/PhysicsConfig.h>

#include "ros/gazebo_world.hpp"

namespace mechsim::ros {

struct GazeboWorld::Reconfigure {
  explicit Reconfigure(const ::ros::NodeHandle& nh) : server(nh) {}
  dynamic_reconfigure::Server<mechsim_gazebo::PhysicsConfig> server;
  bool initialised = false;
};

}  // namespace mechsim::ros
