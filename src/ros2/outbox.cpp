// The writing thread (outbox.hpp).
#include "ros2/outbox.hpp"

#include <algorithm>

namespace mechsim::ros2 {

namespace {
// A new clock time wakes the sleeping thread at most this often (a futex wake costs the tick a few
// microseconds); at real time (1 ms ticks) every tick still does.
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
  const std::uint64_t n = clock_written_.load(std::memory_order_relaxed);
  clock_ring_[n % kClockRing].store(time, std::memory_order_relaxed);
  clock_written_.store(n + 1);
}

void Outbox::end_of_tick() {
  if (!sleeping_.load()) return;  // at work: it looks again before it sleeps
  const bool jobs = jobs_posted_.exchange(false);
  if (!jobs) {
    if (!clock_pending()) return;
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
  idle_.wait(lock, [this] { return (jobs_.empty() && !busy_ && !clock_pending()) || stop_; });
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
    if (jobs_.empty() && !clock_pending()) {
      busy_ = false;
      idle_.notify_all();
      if (stop_) return;
      sleeping_.store(true);
      // A bounded wait besides: a clock time that came while the producer skipped the wake-up
      // (kClockWakeInterval) goes out within 2 ms anyway.
      wake_.wait_for(lock, std::chrono::milliseconds(2), [this] { return stop_ || clock_pending() || !jobs_.empty(); });
      sleeping_.store(false);
      continue;
    }
    busy_ = true;
    const std::uint64_t written = clock_written_.load();
    if (written != clock_read_.load()) {
      // A token bucket of kClockRate a second (kClockBurst deep): every waiting time in order
      // while tokens last (at real time, every tick, bursts included); short of them the newest
      // alone, as soon as there is one.
      const auto now = std::chrono::steady_clock::now();
      clock_tokens_ = std::min(kClockBurst, clock_tokens_ + kClockRate * std::chrono::duration<double>(now - clock_refill_).count());
      clock_refill_ = now;
      const std::uint64_t waiting = written - clock_read_.load();
      if (clock_tokens_ < 1.0 && jobs_.empty() && !stop_) {
        wake_.wait_for(lock, std::chrono::duration<double>((1.0 - clock_tokens_) / kClockRate),
                       [this] { return stop_ || !jobs_.empty(); });
        continue;
      }
      std::uint64_t from = clock_read_.load();
      if (waiting > kClockRing || static_cast<double>(waiting) > clock_tokens_) {
        coalesced_.fetch_add(waiting - 1, std::memory_order_relaxed);
        from = written - 1;
      }
      clock_tokens_ -= static_cast<double>(written - from);
      clock_read_.store(written);
      stats_.clocks += written - from;
      lock.unlock();
      for (std::uint64_t k = from; k < written; ++k) publish_clock_(clock_ring_[k % kClockRing].load(std::memory_order_relaxed));
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
