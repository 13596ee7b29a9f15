#pragma once
// Runs programs as child processes, at most N at once, each with its output in a log file and a
// wall-clock time limit: the local half of a sweep (each point in its own process, so that a
// crash or a hang costs that point only).

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mechsim::batch {

struct Job {
  std::size_t id = 0;
  std::vector<std::string> argv;  // argv[0]: the program's path
  std::string log_file;           // stdout and stderr (created, truncated)
};

struct JobOutcome {
  std::size_t id = 0;
  bool started = false;
  int exit_code = -1;        // when it exited
  int signal = 0;            // that ended it
  bool timed_out = false;    // killed at the time limit
  bool interrupted = false;  // stopped because the pool was interrupted
  double wall_time = 0.0;    // s
};

struct PoolOptions {
  int jobs = 1;               // processes at once
  double time_limit = 3600.0;  // s per job: then SIGTERM, and SIGKILL `grace` s later
  double grace = 5.0;          // s
  // Non-zero (written by a signal handler): no job starts any more, the running ones get SIGINT
  // (SIGKILL `grace` s later) and are reported interrupted.
  const std::atomic<int>* interrupt = nullptr;
};

// Runs `jobs` in order; `done` is called in this thread as each ends. Returns when all have ended
// (or, interrupted, when the running ones have).
void run_jobs(const std::vector<Job>& jobs, const PoolOptions& options, const std::function<void(const JobOutcome&)>& done);

}  // namespace mechsim::batch
