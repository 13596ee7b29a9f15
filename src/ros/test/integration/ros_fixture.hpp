#pragma once
// The ROS integration tests' world: a real master (rosmaster --core) on a free loopback port,
// started once per test program (ctest runs each test in its own program), this process as a
// roscpp client with a spinner, and per test a mechsim_node on the CC8 of robots/cc8.

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <ros/ros.h>

#include "child_process.hpp"

namespace mechsim::ros::test {

// The folder of this program's logs (master, node, spawners); kept for a failing run.
const std::string& log_dir();
int master_port();

// Polls `done` every 10 ms until it is true or `timeout` seconds (wall) pass.
bool wait_until(const std::function<bool()>& done, double timeout);

// A master's answer to lookupNode(name) on 127.0.0.1:port: 1 known, -1 unknown, 0 no answer.
int lookup_node(int port, const std::string& name);
// Starts a second `rosmaster --core` on `port` (for tests that stop and restart a master; the
// fixture's own master stays) and returns once it answers (test failures otherwise).
std::unique_ptr<ChildProcess> start_master_on(int port, const std::string& log);

// Calls a service after waiting at most `timeout` s for it; false when absent or the call fails.
template <class S>
bool call(const std::string& name, S& srv, double timeout = 10.0) {
  if (!::ros::service::waitForService(name, ::ros::Duration(timeout))) return false;
  return ::ros::service::call(name, srv);
}

class CC8Node : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  // More mechsim_node arguments (private parameters as _name:=value).
  virtual std::vector<std::string> extra_node_args() const { return {}; }

  // Runs mechsim_spawner with `args` (in namespace /cc8); the process stays until stopped.
  ChildProcess& spawner(const std::vector<std::string>& args, const std::string& name);
  // `rosparam load FILE` (the robots' controller YAML, which names its namespace).
  void rosparam_load(const std::string& file);
  // Writes `text` into the log folder and returns the path.
  std::string write_file(const std::string& name, const std::string& text);
  // The latest /clock (s); NaN when none came within 5 s.
  double clock_now();

  std::unique_ptr<ChildProcess> node_;
  std::vector<std::unique_ptr<ChildProcess>> spawners_;
  ::ros::NodeHandle nh_;
  ::ros::Subscriber clock_sub_;
  std::mutex clock_mutex_;
  double clock_ = -1.0;
};

}  // namespace mechsim::ros::test
