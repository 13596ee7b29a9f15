#pragma once
// Tick times and memory over a long run, window by window (`mechsim run --timing SECONDS`,
// scripts/soak.sh): for each window of simulated time, the wall time of each tick (median, 99th
// percentile, maximum), the process's CPU time and its resident memory at the window's end.
// Storage is reserved up front for one window's ticks, so measuring allocates nothing per tick.

#include <cstddef>
#include <string>
#include <vector>

namespace mechsim::sim {

struct TimingWindow {
  double sim_end = 0.0;           // s of simulated time at the window's end
  std::size_t ticks = 0;
  double tick_p50 = 0.0, tick_p99 = 0.0, tick_max = 0.0;  // s of wall time per tick
  double wall = 0.0;              // s of wall time the window took
  double cpu = 0.0;               // s of the process's CPU time in the window
  long rss_kb = 0;                // resident set at the window's end (kB), /proc/self/statm
};

class TickTiming {
 public:
  // window: s of simulated time per row; period: s per tick (sizes the per-window storage).
  TickTiming(double window, double period);
  // After each tick: its wall time (s) and the simulated time it reached (s).
  void tick(double seconds, double sim_time);
  // Closes a partial last window (at least one tick).
  void finish(double sim_time);
  const std::vector<TimingWindow>& windows() const { return windows_; }
  // timing.csv: one row per window (sim_end_s, ticks, tick_p50_us, tick_p99_us, tick_max_us,
  // wall_s, cpu_s, rss_kb). Throws std::runtime_error naming the file when it cannot be written.
  void write_csv(const std::string& path) const;

 private:
  void close_window(double sim_time);
  double window_;
  double next_end_;
  std::vector<double> ticks_;
  double wall_start_ = 0.0, cpu_start_ = 0.0;
  std::vector<TimingWindow> windows_;
};

// Resident set size of this process (kB), or -1 when /proc cannot tell.
long resident_kb();

}  // namespace mechsim::sim
