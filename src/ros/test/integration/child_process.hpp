#pragma once
// Child processes for the ROS integration tests: each runs in its own process group with its
// output in a log file, and is stopped (SIGINT, then SIGKILL after a grace period) when the
// object goes away, so a failing test leaves nothing running.

#include <string>
#include <sys/types.h>
#include <vector>

namespace mechsim::ros::test {

class ChildProcess {
 public:
  // Starts argv[0] (a path) with `argv`, output to `log_path`. Throws std::runtime_error.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log_path);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool running();
  // SIGINT to the group; SIGKILL after `grace` seconds. Returns the exit status (-1: killed).
  int stop(double grace = 5.0);
  // Waits at most `timeout` s for the process to exit by itself; its exit status, or -2.
  int wait(double timeout);
  const std::string& log_path() const { return log_path_; }
  pid_t pid() const { return pid_; }  // -1 once reaped
  std::string log() const;  // the output so far

 private:
  pid_t pid_ = -1;
  int status_ = -2;
  std::string log_path_;
};

// A TCP port on 127.0.0.1 that nobody listens on right now.
int free_loopback_port();

}  // namespace mechsim::ros::test
