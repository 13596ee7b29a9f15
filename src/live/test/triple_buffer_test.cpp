#include "live/triple_buffer.hpp"

#include <atomic>
#include <thread>

#include <gtest/gtest.h>

namespace mechsim::live {
namespace {

TEST(TripleBuffer, NothingToTakeUntilPublished) {
  TripleBuffer<int> buffer(0);
  EXPECT_EQ(buffer.take(), nullptr);
  buffer.write_buffer() = 7;
  buffer.publish();
  const int* got = buffer.take();
  ASSERT_NE(got, nullptr);
  EXPECT_EQ(*got, 7);
  EXPECT_EQ(buffer.take(), nullptr);  // nothing new since
}

TEST(TripleBuffer, ReaderGetsTheNewestAndKeepsItsBufferWhileTheWriterGoesOn) {
  TripleBuffer<int> buffer(0);
  for (int k = 1; k <= 5; ++k) {
    buffer.write_buffer() = k;
    buffer.publish();
  }
  const int* got = buffer.take();
  ASSERT_NE(got, nullptr);
  EXPECT_EQ(*got, 5);  // 1..4 were overwritten unread
  // The writer fills and publishes many more; the reader's buffer stays as it was.
  for (int k = 6; k <= 20; ++k) {
    buffer.write_buffer() = k;
    buffer.publish();
    EXPECT_EQ(*got, 5);
  }
  EXPECT_EQ(*buffer.take(), 20);
  EXPECT_EQ(buffer.published(), 20u);
  EXPECT_EQ(buffer.taken(), 2u);
}

// A writer and a reader on two threads: every buffer the reader takes is whole (all its values
// from one write) and newer than the last one it took.
TEST(TripleBuffer, TwoThreadsNeverSeeATornOrOlderBuffer) {
  struct Block {
    std::uint64_t values[64] = {};
  };
  TripleBuffer<Block> buffer(Block{});
  constexpr std::uint64_t kWrites = 200000;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (std::uint64_t k = 1; k <= kWrites; ++k) {
      Block& b = buffer.write_buffer();
      for (std::uint64_t& v : b.values) v = k;
      buffer.publish();
    }
    done.store(true);
  });
  std::uint64_t last = 0, takes = 0, torn = 0, older = 0;
  while (true) {
    const bool finished = done.load();
    if (const Block* b = buffer.take()) {
      ++takes;
      for (const std::uint64_t v : b->values) torn += v != b->values[0] ? 1 : 0;
      older += b->values[0] <= last ? 1 : 0;
      last = b->values[0];
    }
    if (finished && buffer.published() == kWrites) {
      if (const Block* b = buffer.take()) last = b->values[0];
      break;
    }
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(older, 0u);
  EXPECT_GT(takes, 0u);
  EXPECT_EQ(last, kWrites);  // the newest is never lost
}

}  // namespace
}  // namespace mechsim::live
