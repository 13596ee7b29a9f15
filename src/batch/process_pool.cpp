#include "batch/process_pool.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

extern char** environ;

namespace mechsim::batch {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  Job job;
  pid_t pid = -1;
  Clock::time_point started;
  Clock::time_point term_sent{};  // when SIGTERM/SIGINT went out
  bool timed_out = false;
  bool interrupted = false;
  bool killed = false;
};

// posix_spawn with stdout and stderr in the log file and stdin from /dev/null; -1 on failure
// (the log says why).
pid_t spawn(const Job& job) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  for (const std::string& a : job.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // The child starts with SIGINT and SIGTERM at their defaults and nothing blocked, whatever this
  // process inherited (a shell's background job ignores SIGINT): the pool stops it with them.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

void run_jobs(const std::vector<Job>& jobs, const PoolOptions& options, const std::function<void(const JobOutcome&)>& done) {
  std::vector<Running> running;
  std::size_t next = 0;
  const auto interrupted = [&] { return options.interrupt != nullptr && options.interrupt->load() != 0; };
  while (next < jobs.size() || !running.empty()) {
    while (!interrupted() && next < jobs.size() && static_cast<int>(running.size()) < std::max(1, options.jobs)) {
      const Job& job = jobs[next++];
      const pid_t pid = spawn(job);
      if (pid < 0) {
        JobOutcome o;
        o.id = job.id;
        done(o);
        continue;
      }
      running.push_back({job, pid, Clock::now()});
    }
    const Clock::time_point now = Clock::now();
    for (std::size_t i = 0; i < running.size();) {
      Running& r = running[i];
      int status = 0;
      const pid_t w = waitpid(r.pid, &status, WNOHANG);
      if (w == r.pid || (w < 0 && errno == ECHILD)) {
        JobOutcome o;
        o.id = r.job.id;
        o.started = true;
        o.wall_time = seconds(now - r.started);
        if (w == r.pid && WIFEXITED(status)) o.exit_code = WEXITSTATUS(status);
        if (w == r.pid && WIFSIGNALED(status)) o.signal = WTERMSIG(status);
        o.timed_out = r.timed_out;
        o.interrupted = r.interrupted;
        running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
        done(o);
        continue;
      }
      // A time limit or an interrupt: ask first (the run stops at its next tick and says so), then
      // kill what did not listen.
      const bool over_time = seconds(now - r.started) > options.time_limit;
      if (r.term_sent == Clock::time_point{} && (over_time || interrupted())) {
        r.timed_out = over_time && !interrupted();
        r.interrupted = !r.timed_out;
        kill(r.pid, r.timed_out ? SIGTERM : SIGINT);
        r.term_sent = now;
      } else if (r.term_sent != Clock::time_point{} && !r.killed && seconds(now - r.term_sent) > options.grace) {
        kill(r.pid, SIGKILL);
        r.killed = true;
      }
      ++i;
    }
    if (interrupted() && running.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace mechsim::batch
