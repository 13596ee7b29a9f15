#pragma once
// Noticing that the ROS master restarted. roscpp registers a node's publishers, subscribers and
// services once; a new master knows none of them and roscpp never registers again, so the node
// would run on unseen (rostopic list, rosservice call and new subscribers find nothing). A new
// master also starts with an empty parameter server (robot_description, the controllers'
// parameters, /use_sim_time are gone), so a node cannot simply carry on either: mechsim_node and
// mechsim_spawner say so and exit (src/ros/README.md, "Master restarts").
//
// MasterWatch::poll() asks the master for its pid and about this node (lookupNode): another pid
// than the one this node registered with, or a master that does not know the node, is a new
// master. A master that does not answer is waited for (said once).
// Header-only: the spawner links roscpp but not the node's library.

#include <string>

#include <ros/ros.h>

namespace mechsim::ros {

class MasterWatch {
 public:
  enum class State { Registered, Unreachable, Restarted };

  // Construct right after ros::init (before the node advertises anything): the master that
  // answers then is the one the node registers with.
  MasterWatch() : name_(::ros::this_node::getName()), uri_(::ros::master::getURI()) {
    pid_ = master_pid();
    ::ros::param::get("/run_id", run_id_);
  }

  // A getPid and a lookupNode round trip (the master's own timeout when it hangs). Logs the first
  // Unreachable of an outage (WARN) and Restarted (ERROR, with the run_ids when roslaunch set them).
  State poll() {
    const int pid = master_pid();
    if (pid < 0) {
      if (!unreachable_) {
        ROS_WARN_STREAM(name_ << ": the ROS master at " << uri_ << " does not answer; waiting for it");
      }
      unreachable_ = true;
      return State::Unreachable;
    }
    if (unreachable_) ROS_INFO_STREAM(name_ << ": the ROS master at " << uri_ << " answers again");
    unreachable_ = false;
    if (pid_ < 0) pid_ = pid;  // the master was not up at start
    bool known = knows_this_node();
    // The same master (its pid) not knowing the node: a lookup that failed on a loaded machine
    // (a node of the CI's tests once exited so), as a restarted master has another pid. Asked
    // again before it is believed.
    for (int retry = 0; retry < 3 && !known && pid == pid_ && ::ros::ok(); ++retry) {
      ::ros::WallDuration(0.2).sleep();
      known = knows_this_node();
    }
    if (known && pid == pid_) return State::Registered;
    // A node shutting down unregisters itself: the master forgets it without having restarted.
    if (::ros::isShuttingDown() || !::ros::ok()) return State::Registered;
    if (!known && master_pid() < 0) return State::Unreachable;  // it went away during the lookup
    std::string run_id;
    ::ros::param::get("/run_id", run_id);
    ROS_ERROR_STREAM(name_ << ": the ROS master at " << uri_ << " restarted"
                           << (run_id_.empty() && run_id.empty() ? std::string()
                                                                 : " (run_id " + (run_id_.empty() ? "?" : run_id_) +
                                                                       " -> " + (run_id.empty() ? "?" : run_id) + ")")
                           << ": the new master does not know this node's topics and services, and its "
                              "parameter server starts empty. roscpp cannot register again: exiting; start the "
                              "launch (or the node) again");
    return State::Restarted;
  }

 private:
  bool knows_this_node() const {
    XmlRpc::XmlRpcValue args, result, payload;
    args[0] = name_;
    args[1] = name_;
    return ::ros::master::execute("lookupNode", args, result, payload, false);
  }

  static int master_pid() {
    XmlRpc::XmlRpcValue args, result, payload;
    args[0] = ::ros::this_node::getName();
    if (!::ros::master::execute("getPid", args, result, payload, false)) return -1;
    return payload.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(payload) : -1;
  }

  std::string name_, uri_, run_id_;
  int pid_ = -1;
  bool unreachable_ = false;
};

}  // namespace mechsim::ros
