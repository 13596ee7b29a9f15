// mechsim's CC8 at the edges of the world and on slopes, through the scenario runner:
//  - driving off a height field's edge stops the run (summary.json says why, completed is false)
//    or, with world.on_leaving: continue, goes on until the robot has fallen off the world;
//  - spawning inside the Mars Yard's flat border warns at spawn and stops the run;
//  - spawned on a 22 degree slope without roll and pitch, the rover is stood on the slope and
//    stays put; spawned level (roll and pitch fixed at 0) it lands hard.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "physics/heightmap_io.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/test/scenario/scenario_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

class TerrainEdge : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_terrain_edge_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // mechsim's CC8 with its rover drive, on the world `world` (a heightmap file or a name).
  Scenario cc8_on(const std::string& world) const {
    Scenario s = load_scenario((fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8/scenarios/straight_5m.yaml").string());
    s.world.name = world;
    s.timeline.clear();
    s.checks.clear();
    return s;
  }
  std::string terrain_file(const physics::Heightmap& map) const {
    const fs::path file = dir_ / "terrain.tif";
    physics::save_heightmap_tiff(map, file);
    return file.string();
  }
  static void drive(Scenario& s, double vx) {
    TimelineEvent e;
    e.at = 0.5;
    e.controller = "rover_drive_controller";
    e.kind = TimelineEvent::Kind::Twist;
    e.twist.linear.x = vx;
    s.timeline.push_back(e);
  }
  fs::path dir_;
};

// An 8 m square field at 0.5 m: its edge at x = 4 m. Driving at 0.5 m/s from x = 0, the front
// wheels (0.45 m ahead of the base) cross it after about 7 s.
TEST_F(TerrainEdge, DrivingOffAHeightFieldsEdgeStopsTheRunAndSaysWhy) {
  Scenario s = cc8_on(terrain_file(step_terrain(8.0, 0.05, [](double, double) { return 0.5; })));
  s.duration = 20.0;
  s.spawn = {0.0, 0.0, 0.05, 0.0, 0.0, 0.0};
  drive(s, 0.5);
  RunOptions options;
  options.output_dir = (dir_ / "out").string();
  options.plots = false;
  const ScenarioResult r = run_scenario(s, options);
  EXPECT_FALSE(r.completed);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.error.find("left the usable ground"), std::string::npos) << r.error;
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].kind, "left_terrain");
  EXPECT_GT(r.events[0].time, 5.0);
  EXPECT_LT(r.events[0].time, 10.0);
  EXPECT_LT(r.sim_time, 10.0) << "the run stopped there";
  // Stopped at the edge, on the ground: not fallen.
  EXPECT_GT(r.final_x, 3.0);
  EXPECT_LT(r.final_x, 4.0);
  EXPECT_GT(r.final_z, 0.4);
  nlohmann::json summary;
  std::ifstream(dir_ / "out" / "summary.json") >> summary;
  EXPECT_EQ(summary["completed"], false);
  EXPECT_NE(summary["error"].get<std::string>().find("left the usable ground"), std::string::npos);
  ASSERT_EQ(summary["events"].size(), 1u);
  EXPECT_EQ(summary["events"][0]["event"], "left_terrain");
  EXPECT_NEAR(summary["events"][0]["x_m"].get<double>(), r.final_x, 0.01) << "where the base was when it left";
  std::cout << "[ figures  ] " << r.error << "\n";
}

TEST_F(TerrainEdge, WithOnLeavingContinueTheRunGoesOnUntilTheRobotHasFallenOffTheWorld) {
  Scenario s = cc8_on(terrain_file(step_terrain(8.0, 0.05, [](double, double) { return 0.5; })));
  s.duration = 20.0;
  s.spawn = {0.0, 0.0, 0.05, 0.0, 0.0, 0.0};
  s.on_leaving = LeavingTerrain::Continue;
  drive(s, 0.5);
  const ScenarioResult r = run_scenario(s, RunOptions{});
  EXPECT_FALSE(r.completed);
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_EQ(r.events[0].kind, "left_terrain");
  EXPECT_EQ(r.events[1].kind, "fell_off_world");
  // Over the edge it falls: 10 m below the ground takes about 1.5 s more.
  EXPECT_GT(r.events[1].time, r.events[0].time + 1.0);
  EXPECT_LT(r.events[1].time, r.events[0].time + 4.0);
  EXPECT_LT(r.final_z, 0.5 - 9.0);
  EXPECT_GT(r.final_z, 0.5 - 15.0) << "stopped when it fell, not at z = -17 km";
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("left the usable ground (world.on_leaving: continue)"), std::string::npos) << r.warnings[0];
}

TEST_F(TerrainEdge, SpawningInTheMarsYardsBorderWarnsAtSpawnAndStops) {
  // The usable ground ends at x = -18.75 m; the border's flat ground runs on to -20.25 m.
  Scenario s = cc8_on("mars_yard_2024");
  s.duration = 2.0;
  s.spawn = {-19.6, 0.0, 0.05, 0.0, 0.0, 0.0};
  std::vector<std::string> told;
  RunOptions options;
  options.warning = [&](const std::string& w) { told.push_back(w); };
  const ScenarioResult r = run_scenario(s, options);
  ASSERT_FALSE(told.empty());
  EXPECT_EQ(told[0].rfind("at spawn, the robot's footprint", 0), 0u) << told[0];
  EXPECT_NE(told[0].find("mars_yard_2024's usable ground (inside its 1.5 m border)"), std::string::npos) << told[0];
  EXPECT_FALSE(r.completed);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].kind, "left_terrain");
  EXPECT_LT(r.events[0].time, 0.01) << "at the first tick";
}

TEST_F(TerrainEdge, InsideTheMarsYardNothingIsSaid) {
  Scenario s = cc8_on("mars_yard_2024");
  s.duration = 0.5;
  s.spawn = {-16.25, 0.65, 0.05, 0.0, 0.0, 0.0};  // the start pad of mars_yard_route.yaml
  const ScenarioResult r = run_scenario(s, RunOptions{});
  EXPECT_TRUE(r.completed) << r.error;
  EXPECT_TRUE(r.events.empty());
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
}

// A plane rising 22 degrees towards +x; the rover stands across it (heading +y), so that a level
// spawn leaves its uphill wheels in the ground and its downhill wheels 0.2 m in the air.
struct SlopeRun {
  ScenarioResult result;
  double spawn_roll = 0.0;  // rad, summary.json's spawn pose
};

TEST_F(TerrainEdge, OnASteepSlopeTheRoverIsStoodOnTheGroundPlaneAndStaysPut) {
  const double slope = 22.0 * kDeg;
  const std::string file = terrain_file(step_terrain(10.0, 0.05, [&](double x, double) { return 2.0 + std::tan(slope) * x; }));
  auto run = [&](bool settle) {
    Scenario s = cc8_on(file);
    s.duration = 3.0;
    s.spawn = {0.0, 0.0, 0.05, 0.0, 0.0, 90.0 * kDeg};
    s.settle_on_ground = settle;
    RunOptions options;
    options.output_dir = (dir_ / (settle ? "settled" : "level")).string();
    options.plots = false;
    SlopeRun out;
    out.result = run_scenario(s, options);
    nlohmann::json summary;
    std::ifstream(fs::path(options.output_dir) / "summary.json") >> summary;
    out.spawn_roll = summary["spawn_pose"]["roll_rad"];
    return out;
  };
  const SlopeRun settled = run(true);
  ASSERT_TRUE(settled.result.completed) << settled.result.error;
  // Heading +y, uphill +x on its right: rolled by -22 deg (left side down) about its heading.
  EXPECT_NEAR(settled.spawn_roll, -slope, 0.2 * kDeg);
  const double moved = std::hypot(settled.result.final_x, settled.result.final_y);
  std::cout << "[ figures  ] settled on 22 deg: moved " << moved << " m, max tilt " << settled.result.max_tilt / kDeg
            << " deg, final yaw " << settled.result.final_yaw / kDeg << " deg\n";
  EXPECT_LT(moved, 0.05);
  EXPECT_LT(settled.result.max_tilt, slope + 2.0 * kDeg) << "no rocking on landing";
  EXPECT_NEAR(settled.result.final_yaw, 90.0 * kDeg, 2.0 * kDeg);

  const SlopeRun level = run(false);
  EXPECT_NEAR(level.spawn_roll, 0.0, 1e-9);
  const double level_moved = std::hypot(level.result.final_x, level.result.final_y);
  std::cout << "[ figures  ] spawned level on 22 deg: moved " << level_moved << " m, max tilt "
            << level.result.max_tilt / kDeg << " deg, final yaw " << level.result.final_yaw / kDeg << " deg\n";
  // What the settling avoids: thrown off its spawn point by the uphill wheels in the ground, it
  // tips over (measured: 1.7 m and 148 deg).
  EXPECT_GT(level_moved, 5.0 * moved + 0.05);
  EXPECT_GT(level.result.max_tilt, slope + 20.0 * kDeg);
}

}  // namespace
}  // namespace mechsim::sim
