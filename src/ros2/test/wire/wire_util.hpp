#pragma once
// What the ROS 2 wire tests share: a private network namespace per test, child processes bounded
// in time, their JSON-lines output.
//
// Every test runs its DDS traffic in a network namespace of its own (unshare(CLONE_NEWNET), as
// root), with `lo` up and multicast on and 224.0.0.0/4 routed to it: discovery multicast never
// reaches the machine's interfaces, tests never see each other, and nothing is left behind (the
// namespace goes with the last process in it). Without root the tests skip, saying why.

#include <sys/types.h>

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mechsim::ros2::test {

class PrivateNetwork {
 public:
  // Moves the calling thread (and every thread and process it starts from now on) into a new
  // network namespace with a multicast loopback. `error()` says why when it could not.
  PrivateNetwork();
  // Back to the namespace the thread was in.
  ~PrivateNetwork();
  PrivateNetwork(const PrivateNetwork&) = delete;
  PrivateNetwork& operator=(const PrivateNetwork&) = delete;
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  // CYCLONEDDS_URI for Cyclone peers: the namespace's lo, multicast on.
  static std::string cyclone_uri();

 private:
  int original_ = -1;
  std::string error_;
};

// A child process with stdout and stderr in `log` (a file). The destructor stops it (SIGTERM, then
// SIGKILL) and reaps it, so a failing test leaves nothing running; a test killed outright (its
// CTest timeout) takes its children with it (PR_SET_PDEATHSIG).
class Process {
 public:
  Process(const std::vector<std::string>& argv, const std::string& log, const std::map<std::string, std::string>& env = {});
  ~Process();
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  // Waits at most `timeout` for the process to end; its exit status, or nullopt when it did not
  // end in time (it is left running).
  std::optional<int> wait(std::chrono::duration<double> timeout);
  // SIGTERM and wait (then SIGKILL); the exit status.
  int stop();
  // Waits until the log holds `text` (true) or `timeout` passes or the process ends (false).
  bool wait_for_output(const std::string& text, std::chrono::duration<double> timeout) const;
  std::string output() const;  // the log so far
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  std::string log_;
  std::optional<int> status_;
};

// A fresh folder for one test's files (removed by nobody: under the build tree's Testing/).
std::string test_dir(const std::string& name);
// The JSON lines of a peer's output (other lines skipped).
std::vector<nlohmann::json> json_lines(const std::string& text);
// The summary line of `topic` in a peer's output (null json when absent).
nlohmann::json summary(const std::vector<nlohmann::json>& lines, const std::string& topic);
// The first sample line of `topic` (null json when absent).
nlohmann::json first_sample(const std::vector<nlohmann::json>& lines, const std::string& topic);

}  // namespace mechsim::ros2::test
