#include "sim/tick_timing.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace mechsim::sim {

namespace {

double clock_seconds(clockid_t id) {
  timespec t{};
  clock_gettime(id, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The q-quantile (0..1) of v by nearest rank; reorders v.
double quantile(std::vector<double>& v, double q) {
  const auto k = static_cast<std::size_t>(std::min<double>(static_cast<double>(v.size()) - 1.0,
                                                           std::ceil(q * static_cast<double>(v.size())) - 1.0));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

long resident_kb() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  if (!(statm >> size >> resident)) return -1;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

TickTiming::TickTiming(double window, double period) : window_(window), next_end_(window) {
  if (!(window > 0.0) || !(period > 0.0)) throw std::invalid_argument("timing window and tick period must be > 0 s");
  ticks_.reserve(static_cast<std::size_t>(std::ceil(window / period)) + 16);
  wall_start_ = clock_seconds(CLOCK_MONOTONIC);
  cpu_start_ = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
}

void TickTiming::tick(double seconds, double sim_time) {
  // Past the reserve only when the period changes under us: then growing is the lesser evil.
  ticks_.push_back(seconds);
  if (sim_time + 1e-9 >= next_end_) {
    close_window(sim_time);
    while (next_end_ <= sim_time + 1e-9) next_end_ += window_;
  }
}

void TickTiming::finish(double sim_time) {
  if (!ticks_.empty()) close_window(sim_time);
}

void TickTiming::close_window(double sim_time) {
  TimingWindow w;
  w.sim_end = sim_time;
  w.ticks = ticks_.size();
  w.tick_max = *std::max_element(ticks_.begin(), ticks_.end());
  w.tick_p99 = quantile(ticks_, 0.99);
  w.tick_p50 = quantile(ticks_, 0.50);
  const double wall = clock_seconds(CLOCK_MONOTONIC), cpu = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
  w.wall = wall - wall_start_;
  w.cpu = cpu - cpu_start_;
  wall_start_ = wall;
  cpu_start_ = cpu;
  w.rss_kb = resident_kb();
  windows_.push_back(w);
  ticks_.clear();
}

void TickTiming::write_csv(const std::string& path) const {
  std::ofstream out(path);
  out << "sim_end_s,ticks,tick_p50_us,tick_p99_us,tick_max_us,wall_s,cpu_s,rss_kb\n";
  for (const TimingWindow& w : windows_) {
    out << w.sim_end << ',' << w.ticks << ',' << 1e6 * w.tick_p50 << ',' << 1e6 * w.tick_p99 << ',' << 1e6 * w.tick_max
        << ',' << w.wall << ',' << w.cpu << ',' << w.rss_kb << '\n';
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace mechsim::sim
