// The process pool: exit statuses, signals, the time limit (a process that ignores SIGTERM is
// killed), at most N at once, and an interrupt that stops what runs.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "batch/process_pool.hpp"
#include "temp_dir_util.hpp"

namespace mechsim::batch::test {
namespace {

Job shell(std::size_t id, const std::string& script, const TempDir& dir) {
  return {id, {"/bin/sh", "-c", script}, (dir.path() / ("log" + std::to_string(id))).string()};
}

TEST(ProcessPool, ReportsExitStatusSignalAndTimeLimitWithLogs) {
  TempDir dir;
  PoolOptions o;
  o.jobs = 2;
  o.time_limit = 0.5;
  o.grace = 0.3;
  std::map<std::size_t, JobOutcome> out;
  run_jobs({shell(0, "echo hello; exit 3", dir), shell(1, "kill -SEGV $$", dir),
            shell(2, "trap '' TERM; while :; do sleep 0.05; done", dir), shell(3, "exit 0", dir),
            {4, {"/nonexistent/program"}, (dir.path() / "log4").string()}},
           o, [&](const JobOutcome& r) { out[r.id] = r; });
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[0].exit_code, 3);
  std::ifstream log(dir.path() / "log0");
  std::string line;
  std::getline(log, line);
  EXPECT_EQ(line, "hello");
  EXPECT_EQ(out[1].signal, SIGSEGV);
  EXPECT_TRUE(out[2].timed_out);
  EXPECT_EQ(out[2].signal, SIGKILL);  // it ignored SIGTERM
  EXPECT_GE(out[2].wall_time, 0.5 + 0.3);
  EXPECT_EQ(out[3].exit_code, 0);
  EXPECT_FALSE(out[3].timed_out);
  EXPECT_FALSE(out[4].started && out[4].exit_code == 0);
}

TEST(ProcessPool, RunsAtMostNAtOnce) {
  TempDir dir;
  PoolOptions o;
  o.jobs = 2;
  // Each job appends "start" and "end" to one file: never more than two open intervals.
  const std::string file = (dir.path() / "trace").string();
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < 6; ++i) jobs.push_back(shell(i, "echo s >> " + file + "; sleep 0.1; echo e >> " + file, dir));
  run_jobs(jobs, o, [](const JobOutcome&) {});
  std::ifstream in(file);
  int open = 0, most = 0, lines = 0;
  for (std::string l; std::getline(in, l); ++lines) {
    open += l == "s" ? 1 : -1;
    most = std::max(most, open);
  }
  EXPECT_EQ(lines, 12);
  EXPECT_EQ(most, 2);
}

TEST(ProcessPool, AnInterruptStopsTheRunningAndStartsNoMore) {
  TempDir dir;
  std::atomic<int> interrupt{0};
  PoolOptions o;
  o.jobs = 1;
  o.grace = 1.0;
  o.interrupt = &interrupt;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    interrupt.store(SIGINT);
  });
  std::vector<JobOutcome> out;
  const auto start = std::chrono::steady_clock::now();
  run_jobs({shell(0, "exec sleep 20", dir), shell(1, "exec sleep 20", dir)}, o, [&](const JobOutcome& r) { out.push_back(r); });
  stopper.join();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  ASSERT_EQ(out.size(), 1u);  // the second never started
  EXPECT_TRUE(out[0].interrupted);
  EXPECT_EQ(out[0].signal, SIGINT);
}

}  // namespace
}  // namespace mechsim::batch::test
