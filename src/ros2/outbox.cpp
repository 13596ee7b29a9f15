// The writing thread (outbox.hpp).
#include "ros2/outbox.hpp"

namespace mechsim::ros2 {

namespace {
// A new clock time wakes the sleeping thread at most this often, and the thread writes one at most
// this often: at real time (1 ms ticks) every tick, a world 17 times faster about 1100 a second of
// wall time, the newest each time (DDS, every use_sim_time node and the cores the simulation shares
// are spared 17000 wake-ups and writes a second).
constexpr std::chrono::microseconds kClockWakeInterval{900};
}  // namespace

Outbox::Outbox(std::function<void(double)> publish_clock)
    : publish_clock_(std::move(publish_clock)), thread_([this] { run(); }) {}

Outbox::~Outbox() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

bool Outbox::post(std::function<void()> job) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (jobs_.size() >= kMaxJobs) {
    ++stats_.dropped;
    return false;
  }
  jobs_.push_back(std::move(job));
  jobs_posted_.store(true);
  return true;
}

void Outbox::set_clock(double time) {
  clock_.store(time, std::memory_order_relaxed);
  if (clock_pending_.exchange(true)) coalesced_.fetch_add(1, std::memory_order_relaxed);
}

void Outbox::end_of_tick() {
  if (!sleeping_.load()) return;  // at work: it looks again before it sleeps
  const bool jobs = jobs_posted_.exchange(false);
  if (!jobs) {
    if (!clock_pending_.load()) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_wake_ < kClockWakeInterval) return;
    last_wake_ = now;
  }
  { std::lock_guard<std::mutex> lock(mutex_); }  // the thread is in wait() or has not checked yet
  wake_.notify_one();
}

void Outbox::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.notify_one();
  idle_.wait(lock, [this] { return (jobs_.empty() && !busy_ && !clock_pending_.load()) || stop_; });
}

OutboxStats Outbox::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  OutboxStats s = stats_;
  s.coalesced = coalesced_.load();
  return s;
}

void Outbox::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (jobs_.empty() && !clock_pending_.load()) {
      busy_ = false;
      idle_.notify_all();
      if (stop_) return;
      sleeping_.store(true);
      // A bounded wait besides: a clock time that came while the producer skipped the wake-up
      // (kClockWakeInterval) goes out within 2 ms anyway.
      wake_.wait_for(lock, std::chrono::milliseconds(2),
                     [this] { return stop_ || clock_pending_.load() || !jobs_.empty(); });
      sleeping_.store(false);
      continue;
    }
    busy_ = true;
    const auto now = std::chrono::steady_clock::now();
    if (clock_pending_.load() && now - last_clock_ < kClockWakeInterval && jobs_.empty() && !stop_) {
      // Too soon after the last one: wait for the interval (a newer time may replace this one).
      wake_.wait_for(lock, kClockWakeInterval - (now - last_clock_), [this] { return stop_ || !jobs_.empty(); });
      continue;
    }
    if (clock_pending_.load() && (now - last_clock_ >= kClockWakeInterval || stop_) && clock_pending_.exchange(false)) {
      const double t = clock_.load(std::memory_order_relaxed);
      ++stats_.clocks;
      last_clock_ = now;
      lock.unlock();
      publish_clock_(t);
      lock.lock();
    }
    if (!jobs_.empty()) {
      std::function<void()> job = std::move(jobs_.front());
      jobs_.pop_front();
      ++stats_.jobs;
      lock.unlock();
      job();
      lock.lock();
    }
  }
}

}  // namespace mechsim::ros2
