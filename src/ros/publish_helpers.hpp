#pragma once
// What the node's periodic publishers share (controller_bindings.cpp, pr2_outputs.cpp).

#include <cmath>

#include <sensor_msgs/JointState.h>

#include "ros/bridge_names.hpp"

namespace mechsim::ros {

// The first whole multiple of `period` after `time` (s, sim time); `time` itself when period is
// 0. Whole multiples: a rate whose period is not a whole number of ticks (Pr2Odometry's 30 Hz)
// keeps its average instead of rounding every period up.
inline double next_due_after(double time, double period) {
  if (period <= 0.0) return time;
  return (std::floor(time / period + 1e-6) + 1.0) * period;
}

inline sensor_msgs::JointState to_msg(const JointStatesData& d) {
  sensor_msgs::JointState msg;
  msg.header.stamp = ::ros::Time(d.stamp);
  msg.name = d.names;
  msg.position = d.position;
  msg.velocity = d.velocity;
  msg.effort = d.effort;
  return msg;
}

}  // namespace mechsim::ros
