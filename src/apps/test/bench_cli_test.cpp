// `mechsim bench` reports start-up as a user sees it: each stage from the description to the
// first tick in wall-clock and CPU milliseconds, their total, peak memory, and the MuJoCo arena
// with its use.
// (Figures are reported, never asserted: only that they are there and add up.)

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

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

// --sensors cameras: the CC8's four ZED2 cameras render at 15 Hz during the timed ticks, and the
// stage budget names each stage, the render's own cost among them; --sensors none runs without
// sensors; a camera that does not exist is an error naming it.
TEST(BenchCli, SensorsNoneOrCamerasWithTheirStageBudget) {
  const fs::path root = MECHSIM_SOURCE_DIR;
  const std::vector<std::string> cc8 = {MECHSIM_EXE, "bench", (root / "robots/cc8/urdf/cc8.urdf.xacro").string(), "--package",
                                        "mechsim_cc8=" + (root / "robots/cc8").string(), "--controllers",
                                        (root / "robots/cc8/config/controllers.yaml").string(), "--seconds", "0.2"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> argv = cc8;
    argv.insert(argv.end(), extra.begin(), extra.end());
    return run_process(argv, 120.0);
  };
  const ProcessResult none = with({"--sensors", "none"});
  ASSERT_EQ(none.exit_code, 0) << none.out << none.err;
  EXPECT_THAT(none.out, HasSubstr("sensors: none"));
  EXPECT_THAT(none.out, ::testing::Not(HasSubstr("stage budget")));

  const ProcessResult cams = with({"--sensors", "cameras", "--camera-width", "160"});
  ASSERT_EQ(cams.exit_code, 0) << cams.out << cams.err;
  if (cams.err.find("cameras cannot render") != std::string::npos) GTEST_SKIP() << "no OpenGL here: " << cams.err;
  EXPECT_THAT(cams.out, HasSubstr("cameras (4): zed2_left_raw_camera zed2_left_camera zed2_right_raw_camera zed2_right_camera"));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(cams.out, m, std::regex("([0-9.]+) instants, ([0-9.]+) renders")));
  EXPECT_NEAR(std::stod(m[1]), 15.0, 5.1);  // 3 or 4 instants in 0.2 s at 15 Hz
  EXPECT_GT(std::stod(m[2]), 0.0);
  for (const char* stage : {"scene", "prep", "draw", "read", "convert", "resample", "noise", "points"})
    EXPECT_GE(stage_ms(cams.out, stage, 1), 0.0) << stage;
  EXPECT_GT(stage_ms(cams.out, "draw", 0), 0.0);
  ASSERT_TRUE(std::regex_search(cams.out, m, std::regex("real-time factor ([0-9.]+) \\(wall\\)")));
  EXPECT_GT(std::stod(m[1]), 0.0);

  const ProcessResult bad = with({"--sensors", "cameras", "--camera", "no_such_camera"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_THAT(bad.err, HasSubstr("--camera no_such_camera: no camera sensor"));
}

}  // namespace
}  // namespace mechsim::apps::test
