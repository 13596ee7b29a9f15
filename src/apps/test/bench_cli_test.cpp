// `mechsim bench` reports start-up as a user sees it: each stage from the description to the
// first tick in wall-clock and CPU milliseconds, their total, peak memory, and the MuJoCo arena
// with its use.
// (Figures are reported, never asserted: only that they are there and add up.)

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A stage's wall-clock (column 0) or CPU (column 1) milliseconds.
double stage_ms(const std::string& out, const std::string& stage, int column) {
  const std::regex line("\\n  " + stage + " +([0-9.]+) +([0-9.]+)");
  std::smatch m;
  if (!std::regex_search(out, m, line)) {
    ADD_FAILURE() << "no '" << stage << "' line in\n" << out;
    return -1.0;
  }
  return std::stod(m[1 + column]);
}

TEST(BenchCli, ReportsStartUpStagesPeakMemoryAndTheArena) {
  const fs::path root = MECHSIM_SOURCE_DIR;
  const ProcessResult r = run_process({MECHSIM_EXE, "bench", (root / "robots/cc8/urdf/cc8.urdf.xacro").string(), "--package",
                                       "mechsim_cc8=" + (root / "robots/cc8").string(), "--controllers",
                                       (root / "robots/cc8/config/controllers.yaml").string(), "--start",
                                       "joint_state_controller", "--start", "rover_drive_controller", "--seconds", "0.01"},
                                      120.0);
  ASSERT_TRUE(r.started);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("start-up (description -> first tick):  wall ms   CPU ms"));
  for (int column : {0, 1}) {
    double sum = 0.0;
    for (const char* stage : {"description", "world", "MJCF", "compile", "data", "controllers", "sensors", "first tick"}) {
      const double ms = stage_ms(r.out, stage, column);
      EXPECT_GE(ms, 0.0) << stage;
      sum += ms;
    }
    const double total = stage_ms(r.out, "total", column);
    // The stages cover the whole start-up but for what lies between them (options, timers). On a
    // loaded machine the process also waits for a core there, tens of ms of wall-clock time: the
    // CPU column is the one that adds up.
    EXPECT_LE(sum, total + 0.5) << "column " << column;
    if (column == 1) {
      EXPECT_GE(sum, 0.9 * total - 1.0);
    }
    EXPECT_GT(total, 0.0) << "column " << column;
  }
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("peak memory at the first tick: ([0-9.]+) MB")));
  EXPECT_GT(std::stod(m[1]), 1.0);
  // The arena is sized from the CC8 (6 wheels on the ground plane, 4 contacts each) and it was not
  // outgrown standing still.
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("arena: ([0-9]+) contacts, ([0-9]+) constraint rows")));
  EXPECT_GE(std::stoi(m[1]), 24);
  EXPECT_THAT(r.out, HasSubstr("grew 0 times"));
  EXPECT_THAT(r.out, HasSubstr("bare physics step"));
}

}  // namespace
}  // namespace mechsim::apps::test
