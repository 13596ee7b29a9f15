#pragma once
// A thread that runs the slow service handlers (spawn and delete, controller switches, parameter
// changes that reconfigure a controller) in the order their requests came, so that Fast DDS's
// receive threads, which deliver every sample, never wait on the world. A full queue refuses the
// job (the caller answers the request as refused): a flood of requests costs memory bounded by
// kMaxJobs, never the simulation.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace mechsim::ros2 {

class Worker {
 public:
  static constexpr std::size_t kMaxJobs = 1000;
  Worker() : thread_([this] { run(); }) {}
  // Runs what is queued, then joins.
  ~Worker() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // False when the queue is full or the worker is stopping (the job is not run).
  bool post(std::function<void()> job) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_ || jobs_.size() >= kMaxJobs) return false;
      jobs_.push_back(std::move(job));
    }
    wake_.notify_one();
    return true;
  }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
      if (jobs_.empty()) return;  // stop_ and nothing left
      std::function<void()> job = std::move(jobs_.front());
      jobs_.pop_front();
      lock.unlock();
      job();
      lock.lock();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stop_ = false;
  std::thread thread_;  // last: starts once the rest exists
};

}  // namespace mechsim::ros2
