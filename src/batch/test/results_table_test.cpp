// The results table from the points' results: a row per point in order, its values, checks and
// metrics, and the points without a result; plan.json round trip; the Slurm array spec.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "batch/point_result.hpp"
#include "batch/results_table.hpp"
#include "batch/slurm.hpp"
#include "temp_dir_util.hpp"

namespace mechsim::batch::test {
namespace {

Plan small_plan() {
  Plan plan;
  plan.name = "t";
  plan.scenario = test_scenario();
  plan.axes = {{"spawn.yaw", "list", "s.yaml:3"}, {"world.seed", "grid", "s.yaml:4"}};
  plan.points = {{0, {"0.1", "1"}}, {1, {"0.2", "1"}}, {2, {"0.3", "2"}}};
  plan.metrics = {"distance", "final_error"};
  plan.maps = {"spawn.yaw", "world.seed"};
  return plan;
}

std::string read(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ResultsTable, OneRowPerPointWithValuesChecksAndMetrics) {
  TempDir dir;
  const Plan plan = small_plan();
  PointResult a;
  a.index = 0;
  a.status = PointStatus::Passed;
  a.metrics = {{"distance", 0.125}, {"final_error", 1.0 / 3.0}, {"wall_time", 2.0}};
  a.checks = {{"distance >= 0.3", true}, {"upright", true}};
  write_point_result(point_dir(dir.path(), 0), a);
  PointResult b;
  b.index = 2;
  b.status = PointStatus::Crashed;
  b.signal = 11;
  b.error = "killed by signal 11 (Segmentation fault), log: x";
  write_point_result(point_dir(dir.path(), 2), b);

  const Table t = collect_table(dir.path(), plan);
  EXPECT_EQ(t.passed, 1u);
  EXPECT_EQ(t.not_passed, 1u);
  EXPECT_EQ(t.missing, 1u);
  write_table(dir.path(), plan, t);
  EXPECT_EQ(read(dir.path() / "results.csv"),
            "index,status,passed,spawn.yaw,world.seed,checks_passed,checks_total,distance,final_error,error\n"
            "0,passed,1,0.1,1,2,2,0.125,0.3333333333333333,\n"
            "1,missing,0,0.2,1,,,,,\n"
            "2,crashed,0,0.3,2,0,0,,,\"killed by signal 11 (Segmentation fault), log: x\"\n");
  const std::string json = read(dir.path() / "results.json");
  EXPECT_THAT(json, ::testing::HasSubstr("\"final_error\": 0.3333333333333333"));
  EXPECT_THAT(json, ::testing::HasSubstr("\"status\": \"crashed\""));
  // Read back as written.
  const auto again = read_point_result(point_dir(dir.path(), 0));
  ASSERT_TRUE(again);
  EXPECT_EQ(again->metrics.at("final_error"), 1.0 / 3.0);
  EXPECT_EQ(again->checks, a.checks);
}

TEST(ResultsTable, PlanJsonRoundTrips) {
  TempDir dir;
  Plan plan = small_plan();
  plan.set = {{"duration", "1", "s.yaml:2"}};
  write_plan(dir.path(), plan);
  const Plan back = read_plan(dir.path());
  EXPECT_EQ(plan_json(back), plan_json(plan));
  EXPECT_EQ(back.points[2].values, plan.points[2].values);
  EXPECT_THROW(read_plan(dir.path() / "nothing"), SweepError);
  // Resuming with other metrics, maps, time limit or lines is the same sweep; other values are not.
  Plan other = plan;
  other.metrics = {"wall_time"};
  other.time_limit = 5;
  other.axes[0].location = "s.yaml:9";
  EXPECT_TRUE(same_points(plan, other));
  other.points[1].values[0] = "0.25";
  EXPECT_FALSE(same_points(plan, other));
}

TEST(Slurm, ArraySpecsAndTasks) {
  EXPECT_EQ(array_spec({0, 1, 2, 3}, 4), "0-3%4");
  EXPECT_EQ(array_spec({3, 7, 8, 9, 12}, 0), "3,7-9,12");
  SlurmOptions o;
  o.max_array_size = 1000;
  EXPECT_EQ(points_per_task(200, o), 1u);
  EXPECT_EQ(points_per_task(2500, o), 3u);
  o.points_per_task = 7;
  EXPECT_EQ(points_per_task(2500, o), 7u);
  // Tasks with a point lacking a final result: task 1 (points 2, 3) has a crash, task 2 none yet.
  TempDir dir;
  Plan plan = small_plan();
  plan.points.push_back({3, {"0.4", "2"}});
  plan.points.push_back({4, {"0.5", "2"}});
  PointResult r;
  r.status = PointStatus::Failed;
  for (std::size_t i : {0, 1, 2}) {
    r.index = i;
    write_point_result(point_dir(dir.path(), i), r);
  }
  r.index = 3;
  r.status = PointStatus::Timeout;
  write_point_result(point_dir(dir.path(), 3), r);
  EXPECT_EQ(tasks_to_run(dir.path(), plan, 2), (std::vector<std::size_t>{1, 2}));
}

}  // namespace
}  // namespace mechsim::batch::test
