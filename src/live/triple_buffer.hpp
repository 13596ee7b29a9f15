#pragma once
// A lock-free single-writer / single-reader triple buffer: the simulation's tick (the writer)
// fills one buffer and publishes it with one atomic exchange; the streaming thread (the reader)
// takes the newest published buffer with another. Neither side ever waits for the other, and a
// reader that falls behind skips snapshots instead of holding the writer up (newest wins).
//
// The three buffers are copies of one prototype made at construction, so that a writer that
// only assigns into presized members (std::copy into vectors of the same size) never allocates.

#include <array>
#include <atomic>
#include <cstdint>

namespace mechsim::live {

template <class T>
class TripleBuffer {
 public:
  explicit TripleBuffer(const T& prototype) : buffers_{prototype, prototype, prototype} {}
  TripleBuffer(const TripleBuffer&) = delete;
  TripleBuffer& operator=(const TripleBuffer&) = delete;

  // Writer side: the buffer to fill; it stays the writer's until publish().
  T& write_buffer() noexcept { return buffers_[write_]; }
  // Writer side: makes the filled buffer the newest one and takes the one it replaces (the
  // previously newest, unless the reader holds it) to fill next.
  void publish() noexcept {
    const std::uint32_t old = middle_.exchange(write_ | kFresh, std::memory_order_acq_rel);
    write_ = old & kIndex;
    published_.fetch_add(1, std::memory_order_relaxed);
  }

  // Reader side: the newest buffer published since the last take(), or null when none is new.
  // The pointer stays valid (and unchanged by the writer) until the next take().
  const T* take() noexcept {
    if ((middle_.load(std::memory_order_acquire) & kFresh) == 0) return nullptr;
    const std::uint32_t old = middle_.exchange(read_, std::memory_order_acq_rel);
    read_ = old & kIndex;
    taken_.fetch_add(1, std::memory_order_relaxed);
    return &buffers_[read_];
  }

  // Counters (any thread): buffers published and taken; published - taken were overwritten unread.
  std::uint64_t published() const noexcept { return published_.load(std::memory_order_relaxed); }
  std::uint64_t taken() const noexcept { return taken_.load(std::memory_order_relaxed); }

 private:
  static constexpr std::uint32_t kIndex = 3, kFresh = 4;
  std::array<T, 3> buffers_;
  // The buffer between writer and reader: its index, and kFresh when the writer published it
  // after the reader's last take.
  std::atomic<std::uint32_t> middle_{1};
  std::uint32_t write_ = 0;  // writer's own
  std::uint32_t read_ = 2;   // reader's own
  std::atomic<std::uint64_t> published_{0}, taken_{0};
};

}  // namespace mechsim::live
