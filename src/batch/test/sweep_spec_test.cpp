// Reading sweep files: the axes as written, and every mistake as an error naming the file, the
// line and the key.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "batch/sweep_spec.hpp"
#include "temp_dir_util.hpp"

namespace mechsim::batch::test {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string sweep_text(const std::string& axes, const std::string& extra = "") {
  return "scenario: " + test_scenario() + "\n" + extra + "axes:\n" + axes;
}

// The message of the SweepError that loading `text` throws ("" when it loads).
std::string error_of(const TempDir& dir, const std::string& text, bool force = false) {
  const std::string file = dir.write("sweep.yaml", text);
  try {
    load_sweep(file, force);
  } catch (const SweepError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepSpec, ReadsEveryKindOfAxis) {
  TempDir dir;
  const std::string file = dir.write("my_sweep.yaml", sweep_text(
      "  - {path: world.seed, list: [1, 2, 3]}\n"
      "  - {path: spawn.yaw, grid: {from: -0.5, to: 0.5, steps: 5}}\n"
      "  - {path: controllers.params.rover_drive_controller.wheel_pid.p, uniform: [2, 8]}\n"
      "  - {path: spawn.x, normal: {mean: 1, stddev: 0.1}}\n"
      "  - {path: controllers.params.rover_drive_controller.wheel_pid.i, log_uniform: [5, 50]}\n"
      "  - {path: spawn.y, lhs: [-1, 1]}\n"
      "  - {path: seed, uniform: [1, 100], integer: true}\n",
      "samples: 4\nseed: 9\ntime_limit: 30\nmetrics: [distance, wall_time]\nset: {duration: 1}\n"));
  const SweepSpec s = load_sweep(file, false);
  EXPECT_EQ(s.name, "my_sweep");
  EXPECT_EQ(s.scenario, test_scenario());
  ASSERT_EQ(s.axes.size(), 7u);
  EXPECT_EQ(s.axes[0].kind, Axis::Kind::List);
  EXPECT_EQ(s.axes[0].values, (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(s.axes[1].kind, Axis::Kind::Grid);
  EXPECT_EQ(s.axes[1].steps, 5);
  EXPECT_EQ(s.axes[2].kind, Axis::Kind::Uniform);
  EXPECT_EQ(s.axes[3].kind, Axis::Kind::Normal);
  EXPECT_EQ(s.axes[4].kind, Axis::Kind::LogUniform);
  EXPECT_EQ(s.axes[5].kind, Axis::Kind::Lhs);
  EXPECT_TRUE(s.axes[6].integer);
  EXPECT_THAT(s.axes[1].location, HasSubstr("my_sweep.yaml:"));
  EXPECT_EQ(s.samples, 4u);
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(s.time_limit, 30.0);
  EXPECT_EQ(point_count(s), 3u * 5u * 4u);
  ASSERT_EQ(s.set.size(), 1u);
  EXPECT_EQ(s.set[0].path, "duration");
  EXPECT_EQ(s.maps, (std::vector<std::string>{"world.seed", "spawn.yaw"}));
}

TEST(SweepSpec, AnEmptyAxisNamesFileLineAndKey) {
  TempDir dir;
  const std::string e = error_of(dir, sweep_text("  - {path: world.seed, list: []}\n"));
  EXPECT_THAT(e, AllOf(HasSubstr("sweep.yaml:3"), HasSubstr("list"), HasSubstr("empty")));
  const std::string g = error_of(dir, sweep_text("  - {path: spawn.yaw, grid: {from: 0, to: 1, steps: 0}}\n"));
  EXPECT_THAT(g, AllOf(HasSubstr("sweep.yaml:3"), HasSubstr("steps"), HasSubstr(">= 1")));
}

TEST(SweepSpec, TenMillionPointsNeedForce) {
  TempDir dir;
  std::string axes;
  for (const char* p : {"spawn.x", "spawn.y", "spawn.yaw", "world.seed", "seed", "duration", "period"}) {
    axes += std::string("  - {path: ") + p + ", grid: {from: 1, to: 10, steps: 10}}\n";
  }
  const std::string e = error_of(dir, sweep_text(axes));
  EXPECT_THAT(e, AllOf(HasSubstr("sweep.yaml:3"), HasSubstr("/axes"), HasSubstr("10000000 points"), HasSubstr("--force")));
  const std::string file = dir.write("sweep.yaml", sweep_text(axes));
  EXPECT_EQ(point_count(load_sweep(file, true)), 10000000u);
}

TEST(SweepSpec, MistakesNameFileLineAndKey) {
  TempDir dir;
  EXPECT_THAT(error_of(dir, sweep_text("  - {path: spawn.yaw, lisst: [1]}\n")),
              AllOf(HasSubstr("sweep.yaml:3"), HasSubstr("unknown key 'lisst'")));
  EXPECT_THAT(error_of(dir, sweep_text("  - {path: spawn.yaw, uniform: [1, 2]}\n")),
              AllOf(HasSubstr("sweep.yaml"), HasSubstr("samples")));
  EXPECT_THAT(error_of(dir, sweep_text("  - {path: spawn.yaw, uniform: [2, 1]}\n", "samples: 3\n")),
              AllOf(HasSubstr("sweep.yaml:4"), HasSubstr("uniform"), HasSubstr("low < high")));
  EXPECT_THAT(error_of(dir, sweep_text("  - {path: spawn..yaw, list: [1]}\n")),
              AllOf(HasSubstr("sweep.yaml:3"), HasSubstr("path"), HasSubstr("spawn..yaw")));
  EXPECT_THAT(error_of(dir, sweep_text("  - {path: spawn.yaw, list: [1]}\n", "metrics: [distanse]\n")),
              AllOf(HasSubstr("sweep.yaml:2"), HasSubstr("metrics"), HasSubstr("unknown metric 'distanse'")));
  EXPECT_THAT(error_of(dir, "scenario: nowhere.yaml\naxes:\n  - {path: spawn.yaw, list: [1]}\n"),
              AllOf(HasSubstr("sweep.yaml:1"), HasSubstr("scenario"), HasSubstr("no such scenario file")));
  EXPECT_THAT(error_of(dir, sweep_text("  - {path: spawn.yaw, list: [1]}\n  - {path: spawn.yaw, list: [2]}\n")),
              AllOf(HasSubstr("sweep.yaml:4"), HasSubstr("two axes")));
}

}  // namespace
}  // namespace mechsim::batch::test
