// TickTiming: windows of simulated time, nearest-rank percentiles of the tick times, resident
// memory that sees an allocation, and the CSV.
#include <gmock/gmock.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "sim/tick_timing.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

TEST(TickTiming, OneRowPerWindowWithNearestRankPercentiles) {
  TickTiming timing(0.1, 0.001);  // 100 ticks per window
  double t = 0.0;
  for (int k = 1; k <= 250; ++k) {
    t = 0.001 * k;
    // Window 1: 1..100 us; window 2: 101..200 us; then 50 ticks of 7 us.
    timing.tick(k <= 200 ? 1e-6 * k : 7e-6, t);
  }
  timing.finish(t);
  const auto& w = timing.windows();
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].ticks, 100u);
  EXPECT_NEAR(w[0].sim_end, 0.1, 1e-12);
  EXPECT_NEAR(w[0].tick_p50, 50e-6, 1e-12);
  EXPECT_NEAR(w[0].tick_p99, 99e-6, 1e-12);
  EXPECT_NEAR(w[0].tick_max, 100e-6, 1e-12);
  EXPECT_NEAR(w[1].tick_p50, 150e-6, 1e-12);
  EXPECT_EQ(w[2].ticks, 50u) << "the partial last window";
  EXPECT_NEAR(w[2].tick_max, 7e-6, 1e-15);
  EXPECT_GT(w[0].rss_kb, 0);
  EXPECT_GE(w[1].wall, 0.0);
}

TEST(TickTiming, ResidentMemorySeesTouchedPages) {
  const long before = resident_kb();
  ASSERT_GT(before, 0);
  const std::size_t bytes = 64u << 20;
  auto block = std::make_unique<char[]>(bytes);
  std::memset(block.get(), 1, bytes);
  EXPECT_GE(resident_kb() - before, 60 * 1024) << "64 MiB touched";
  EXPECT_EQ(block[bytes - 1], 1);
}

TEST(TickTiming, CsvHasAHeaderAndARowPerWindowAndBadPathsAreNamed) {
  TickTiming timing(1.0, 0.5);
  timing.tick(2e-6, 0.5);
  timing.tick(4e-6, 1.0);
  const fs::path path = fs::temp_directory_path() / ("mechsim_tick_timing_" + std::to_string(::getpid()) + ".csv");
  timing.write_csv(path.string());
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  fs::remove(path);
  EXPECT_THAT(text.str(), ::testing::StartsWith("sim_end_s,ticks,tick_p50_us,tick_p99_us,tick_max_us,wall_s,cpu_s,rss_kb\n1,2,2,4,4,"));
  EXPECT_THROW(timing.write_csv("/nonexistent_dir/timing.csv"), std::runtime_error);
  EXPECT_THROW(TickTiming(0.0, 0.001), std::invalid_argument);
}

}  // namespace
}  // namespace mechsim::sim
