#pragma once
// Lock-based double buffers that never block the real-time side (ros_control's
// realtime_tools::RealtimeBuffer and RealtimePublisher pattern).
//
// RealtimeBuffer<T>: one writer side outside the tick, one reader inside it. write() copies the
// value into the spare slot under a mutex (it may wait for the tick's try-lock, a few
// instructions); read_from_rt() try-locks and, when new data is there, swaps the slots by
// pointer. When the lock is busy the tick keeps the previous value: it never waits.
// Copying T must not allocate when the slot already holds a value of the same shape (vectors
// of equal size, for instance): the tick never copies, it only swaps pointers.
//
// SnapshotBuffer<T>: the other direction. The tick fills the snapshot in place if it gets the
// lock (try-lock; a reader holding it makes the tick skip one update), readers copy it out.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <utility>

namespace mechsim::control {

template <class T>
class RealtimeBuffer {
 public:
  RealtimeBuffer() : rt_(&a_), non_rt_(&b_) {}
  explicit RealtimeBuffer(const T& initial) : a_(initial), b_(initial), rt_(&a_), non_rt_(&b_) {}
  RealtimeBuffer(const RealtimeBuffer& other) : RealtimeBuffer(other.latest()) {}
  RealtimeBuffer& operator=(const RealtimeBuffer& other) {
    if (this != &other) init(other.latest());
    return *this;
  }

  // Non-real-time: sets both slots (before the tick uses the buffer, or to reset it).
  void init(const T& value) {
    std::lock_guard<std::mutex> lock(mutex_);
    *rt_ = value;
    *non_rt_ = value;
    new_data_.store(false, std::memory_order_release);
  }

  // Non-real-time: publishes a new value for the next read_from_rt().
  void write(const T& value) {
    std::lock_guard<std::mutex> lock(mutex_);
    *non_rt_ = value;
    new_data_.store(true, std::memory_order_release);
    ++writes_;
  }

  // Real-time: the newest value that could be taken without waiting.
  const T& read_from_rt() noexcept {
    // The flag spares the lock in the common case of no new data; the swap itself happens
    // under the lock, so a concurrent write() cannot be torn.
    if (new_data_.load(std::memory_order_acquire) && mutex_.try_lock()) {
      if (new_data_.load(std::memory_order_relaxed)) {
        std::swap(rt_, non_rt_);
        new_data_.store(false, std::memory_order_relaxed);
      }
      mutex_.unlock();
    }
    return *rt_;
  }

  // Real-time: the value in use without looking for new data.
  const T& current_rt() const noexcept { return *rt_; }
  // Real-time, rare (a controller's starting()): drops any pending write and lets `set(T&)`
  // change the value in use. It takes the lock, which a writer only holds for one copy of T;
  // std::mutex::lock does not allocate.
  template <class F>
  void reset_from_rt(F&& set) noexcept {
    std::lock_guard<std::mutex> lock(mutex_);
    new_data_.store(false, std::memory_order_relaxed);
    set(*rt_);
  }

  // Non-real-time: the latest written value (pending or taken).
  T latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return new_data_.load(std::memory_order_relaxed) ? *non_rt_ : *rt_;
  }
  std::uint64_t writes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return writes_;
  }

 private:
  T a_{};
  T b_{};
  T* rt_;
  T* non_rt_;
  std::atomic<bool> new_data_{false};
  std::uint64_t writes_ = 0;
  mutable std::mutex mutex_;
};

template <class T>
class SnapshotBuffer {
 public:
  // Non-real-time: shapes the snapshot (sizes its vectors) before the tick fills it.
  void init(const T& prototype) {
    std::lock_guard<std::mutex> lock(mutex_);
    value_ = prototype;
  }

  // Real-time: fill(T&) updates the snapshot in place. Returns false (and skips) when a reader
  // holds the lock.
  template <class F>
  bool publish_from_rt(F&& fill) noexcept {
    if (!mutex_.try_lock()) return false;
    fill(value_);
    // Only the tick writes the sequence: no locked read-modify-write needed.
    sequence_.store(sequence_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
    mutex_.unlock();
    return true;
  }

  // Non-real-time: a copy of the latest snapshot.
  T read() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return value_;
  }
  // Number of snapshots published so far; poll it to see whether read() has something new.
  std::uint64_t sequence() const noexcept { return sequence_.load(std::memory_order_acquire); }

 private:
  T value_{};
  std::atomic<std::uint64_t> sequence_{0};
  mutable std::mutex mutex_;
};

}  // namespace mechsim::control
