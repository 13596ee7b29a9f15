#pragma once
// Start-up stages timed two ways: wall-clock time, what a user waits, and this process's CPU time,
// what the stage costs when other processes share the cores (on a loaded machine wall time is
// several times the CPU time).

#include <chrono>
#include <ctime>

namespace mechsim::physics {

struct StageTime {
  double wall_ms = 0.0;
  double cpu_ms = 0.0;  // the whole process's CPU time (start-up is single-threaded)
  StageTime& operator+=(const StageTime& o) {
    wall_ms += o.wall_ms;
    cpu_ms += o.cpu_ms;
    return *this;
  }
};

class StageTimer {
 public:
  StageTimer() { restart(); }
  void restart() {
    wall_ = std::chrono::steady_clock::now();
    cpu_ = cpu_now_ms();
  }
  // Time since construction or the last lap()/restart(); starts the next stage.
  StageTime lap() {
    const auto wall = std::chrono::steady_clock::now();
    const double cpu = cpu_now_ms();
    const StageTime t{std::chrono::duration<double, std::milli>(wall - wall_).count(), cpu - cpu_};
    wall_ = wall;
    cpu_ = cpu;
    return t;
  }

 private:
  static double cpu_now_ms() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
  }
  std::chrono::steady_clock::time_point wall_;
  double cpu_ = 0.0;
};

}  // namespace mechsim::physics
