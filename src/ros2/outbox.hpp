#pragma once
// The thread that writes mechsim's ROS 2 samples, so that the simulation's loop thread only fills
// messages. A DDS write (serialization, the writer's history, a UDP send per matched reader) costs
// ~10-20 us; the CC8's whole tick costs ~30 us, so writing /clock every tick from the loop would
// halve its real-time factor.
//
//   - post(job): the job runs on the outbox thread, in order. A full queue (kMaxJobs) drops the
//     newest job and counts it: the loop never waits on DDS or on a slow peer.
//   - set_clock(t): /clock goes through a small ring: the thread writes every time that waits, up
//     to 1100 a wall second on average (a token bucket, bursts of 50): at real time that is every
//     tick (1 kHz); a world running 17 times faster gets about 1100 a wall second, the newest each
//     time (never a time older than one already sent).
//   - end_of_tick(): wakes the thread when it sleeps and there is work: for a new clock time at
//     most every 0.9 ms of wall time (a futex wake costs the tick a few microseconds: at real time
//     every tick still wakes it, a world running 17 times faster does not pay it each tick).
//
// Threads: post, set_clock and end_of_tick from one producer (the loop thread) or under its lock;
// flush() from any other thread.

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace mechsim::ros2 {

struct OutboxStats {
  std::uint64_t jobs = 0;      // run
  std::uint64_t dropped = 0;   // not queued: the queue was full
  std::uint64_t clocks = 0;    // /clock samples published
  std::uint64_t coalesced = 0; // clock times replaced by a newer one before they went out
};

class Outbox {
 public:
  // `publish_clock(t)` writes /clock (called on the outbox thread).
  explicit Outbox(std::function<void(double time)> publish_clock);
  ~Outbox();  // runs what is queued, then joins
  Outbox(const Outbox&) = delete;
  Outbox& operator=(const Outbox&) = delete;

  bool post(std::function<void()> job);
  void set_clock(double time);
  void end_of_tick();
  // Returns once everything posted before the call has run.
  void flush();
  OutboxStats stats() const;

 private:
  static constexpr std::size_t kMaxJobs = 512;
  void run();

  std::function<void(double)> publish_clock_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<std::function<void()>> jobs_;  // under mutex_
  bool stop_ = false;                       // under mutex_
  bool busy_ = false;                       // under mutex_
  OutboxStats stats_;                       // under mutex_ (the atomics below aside)
  // The clock channel and the thread's sleep, lock-free for the loop thread: the producer stores
  // the time in the ring, then counts it, then reads sleeping; the thread sets sleeping, then
  // reads the count (sequentially consistent, so one of them sees the other: no lost wake-up).
  static constexpr std::size_t kClockRing = 64;
  static constexpr double kClockRate = 1100.0;  // clock writes a wall second, on average
  static constexpr double kClockBurst = 50.0;   // and at once
  double clock_tokens_ = kClockBurst;           // the thread's
  std::chrono::steady_clock::time_point clock_refill_ = std::chrono::steady_clock::now();
  std::array<std::atomic<double>, kClockRing> clock_ring_{};
  std::atomic<std::uint64_t> clock_written_{0};  // times the producer stored
  std::atomic<std::uint64_t> clock_read_{0};     // times the thread took
  bool clock_pending() const { return clock_written_.load() != clock_read_.load(); }
  std::atomic<bool> sleeping_{false};
  std::atomic<bool> jobs_posted_{false};
  std::atomic<std::uint64_t> coalesced_{0};
  std::chrono::steady_clock::time_point last_wake_{};   // the producer's
  std::thread thread_;  // last: starts once the rest exists
};

}  // namespace mechsim::ros2
