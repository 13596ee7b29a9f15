// mechsim's CC8 on terrain and on soil (issue: rovers on real terrain): the shipped terrain and
// soil scenarios meet their checks; on loose soil it climbs less than on rigid ground and its
// wheels slip more uphill than downhill; standing on a 10 degree slope of soil it does not creep;
// and on height fields it has never seen it drives without falling through or blowing up, on
// rigid ground and on soil: a generated one, and a real public DEM (Olinda, Brazil, from Debian's
// r-cran-stars; scripts/fetch-test-data.sh) laid onto 45 m x 45 m.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

#include "physics/heightmap_io.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

Scenario shipped(const std::string& name) {
  return load_scenario((fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8/scenarios" / (name + ".yaml")).string());
}

ScenarioResult run(const std::string& what, const Scenario& s) {
  const ScenarioResult r = run_scenario(s, RunOptions{});
  std::cout << "[ figures  ] " << what << ": distance " << r.distance << " m, final (" << r.final_x << ", " << r.final_y
            << ", " << r.final_z << ") yaw " << r.final_yaw * 57.29577951308232 << " deg, max tilt "
            << r.max_tilt * 57.29577951308232 << " deg";
  if (!r.wheels.empty()) std::cout << ", mean slip " << r.wheels[0].mean_slip << " (" << r.wheels[0].link << ")";
  std::cout << "\n";
  for (const CheckOutcome& c : r.checks) std::cout << "[ figures  ]   " << (c.passed ? "PASS " : "FAIL ") << c.detail << "\n";
  return r;
}

TEST(Cc8Terrain, ShippedTerrainAndSoilScenariosMeetTheirChecks) {
  for (const char* name : {"soil_slope_climb", "crab_mars_yard"}) {
    const ScenarioResult r = run(name, shipped(name));
    ASSERT_TRUE(r.completed) << name << ": " << r.error;
    EXPECT_TRUE(r.passed) << name;
  }
}

// The CC8 on the slope world at `deg`, soil `soil` (empty: rigid), facing uphill (or downhill),
// driving at 0.3 m/s from t = 1 s for `seconds`.
Scenario on_slope(double deg, const std::string& soil, bool uphill = true, double seconds = 10.0) {
  Scenario s = shipped("soil_slope_climb");
  s.world.slope_deg = deg;
  s.world.soil = soil.empty() ? std::nullopt : physics::find_soil(soil);
  s.spawn.yaw = uphill ? 0.0 : M_PI;
  s.duration = 1.0 + seconds;
  s.checks.clear();
  return s;
}

// How far it got along its heading (the slope's x axis, up or down).
double progress(const Scenario& s, const ScenarioResult& r) { return (r.final_x - s.spawn.x) * std::cos(s.spawn.yaw); }

// Dry sand stops the CC8 on 4 degrees, where rigid ground lets it drive at full speed; rigid
// ground takes it up 15 degrees too.
TEST(Cc8Terrain, OnLooseSoilItClimbsLessThanOnRigidGround) {
  for (const auto& [deg, soil, climbs] : {std::tuple{4.0, "dry_sand", false}, std::tuple{4.0, "", true}, std::tuple{15.0, "", true}}) {
    const Scenario s = on_slope(deg, soil);
    const ScenarioResult r = run(std::to_string(deg) + " deg, " + (*soil ? soil : "rigid"), s);
    ASSERT_TRUE(r.completed) << r.error;
    const double up = progress(s, r);
    if (climbs) {
      EXPECT_GT(up, 2.5) << deg << " deg " << soil;
    } else {
      EXPECT_LT(up, 0.5) << deg << " deg " << soil;
    }
  }
}

TEST(Cc8Terrain, OnLooseSoilItsWheelsSlipMoreUphillThanDownhill) {
  double mean_slip[2] = {0.0, 0.0};
  for (const bool uphill : {true, false}) {
    const Scenario s = on_slope(2.0, "dry_sand", uphill, 6.0);
    const ScenarioResult r = run(uphill ? "2 deg dry sand, uphill" : "2 deg dry sand, downhill", s);
    ASSERT_TRUE(r.completed) << r.error;
    ASSERT_EQ(r.wheels.size(), 6u);
    for (const WheelOutcome& w : r.wheels) mean_slip[uphill ? 0 : 1] += w.mean_slip / 6.0;
    EXPECT_GT(progress(s, r), 0.5) << "it drove";
  }
  std::printf("[ figures  ] mean slip uphill %.3f, downhill %.3f\n", mean_slip[0], mean_slip[1]);
  EXPECT_GT(mean_slip[0], mean_slip[1] + 0.2);
}

// The same sand under Ding et al.'s model (physics/terramechanics.hpp: the rim in contact behind
// its lowest point, up to the soil's rebound): the CC8's 9 cm wheels meet less compaction
// resistance and it climbs the 4 degrees Wong-Reece's model stops it on (docs/soil.md: it
// climbs 6 deg at slip 0.24 and stalls on 8).
TEST(Cc8Terrain, UnderDingsModelItClimbsTheDrySandWongReecesStopsItOn) {
  Scenario s = on_slope(4.0, "dry_sand");
  s.world.soil->model = physics::WheelSoilModel::Ding;
  const ScenarioResult r = run("4 deg dry sand, ding", s);
  ASSERT_TRUE(r.completed) << r.error;
  EXPECT_GT(progress(s, r), 2.0);
  double slip = 0.0;
  for (const WheelOutcome& w : r.wheels) slip += w.mean_slip / static_cast<double>(r.wheels.size());
  EXPECT_LT(slip, 0.3);
}

// Parked (rover drive holding zero) on 10 degrees of soil, facing uphill and across the slope.
TEST(Cc8Terrain, StandingOnATenDegreeSlopeOfSoilItDoesNotCreep) {
  for (const char* soil : {"dry_sand", "lunar_regolith"}) {
    for (const double yaw : {0.0, M_PI / 2}) {
      Scenario s = on_slope(10.0, soil);
      s.timeline.clear();
      s.spawn.yaw = yaw;
      s.duration = 11.0;
      const ScenarioResult r = run(std::string("parked on 10 deg of ") + soil + (yaw == 0.0 ? ", facing uphill" : ", across"), s);
      ASSERT_TRUE(r.completed) << r.error;
      // From where it landed (spawned 2 cm up, it sinks 2-3 cm into the soil): the whole run's
      // horizontal displacement, the settling included.
      const double moved = std::hypot(r.final_x - s.spawn.x, r.final_y - s.spawn.y);
      std::printf("[ figures  ] moved %.2f mm in %.0f s\n", 1000 * moved, s.duration);
      EXPECT_LT(moved, 0.01) << soil << " yaw " << yaw;
    }
  }
}

// Multi-pass (soil multi_pass: true) on the CC8 climbing 2 degrees of dry sand for 10 s: its front
// wheels break virgin soil, its middle and rear wheels run in the ruts of the wheels ahead (the
// rocker-bogie's wheels are nearly in line): over the run (the first seconds before they reach the
// ruts included) they meet ruts of a fifth of the front wheels' sinkage or more. The wheels behind
// meet less compaction resistance, so the rover slips less and climbs further than with every wheel
// on virgin soil. Parked on 10 degrees of it, it does not creep: a wheel is never in its own rut.
TEST(Cc8Terrain, WithMultiPassItsMiddleAndRearWheelsRunInTheFrontWheelsRuts) {
  double progress_of[2] = {0.0, 0.0}, slip_of[2] = {0.0, 0.0};
  for (const bool multi_pass : {false, true}) {
    Scenario s = on_slope(2.0, "dry_sand", true, 10.0);
    s.world.soil->multi_pass = multi_pass;
    const ScenarioResult r = run(std::string("2 deg dry sand, multi-pass ") + (multi_pass ? "on" : "off"), s);
    ASSERT_TRUE(r.completed) << r.error;
    ASSERT_EQ(r.wheels.size(), 6u);
    progress_of[multi_pass ? 1 : 0] = progress(s, r);
    double front_sinkage = 0.0, front_rut = 0.0, behind_rut = 1e9;
    for (const WheelOutcome& w : r.wheels) {
      const bool front = w.link.find("_F") != std::string::npos;
      std::printf("[ figures  ]   %s: mean sinkage %.2f mm, mean rut met %.2f mm, slip %.3f\n", w.link.c_str(),
                  1000 * w.mean_sinkage, 1000 * w.mean_rut_depth, w.mean_slip);
      slip_of[multi_pass ? 1 : 0] += w.mean_slip / 6.0;
      if (front) {
        front_sinkage += w.mean_sinkage / 2.0;
        front_rut += w.mean_rut_depth / 2.0;
      } else {
        behind_rut = std::min(behind_rut, w.mean_rut_depth);
      }
    }
    if (!multi_pass) {
      EXPECT_EQ(front_rut + behind_rut, 0.0) << "off: virgin soil everywhere";
      continue;
    }
    EXPECT_LT(front_rut, 0.05 * front_sinkage) << "the front wheels break virgin soil";
    EXPECT_GT(behind_rut, 0.2 * front_sinkage) << "every wheel behind runs in ruts";
  }
  std::printf("[ figures  ] up 2 deg of dry sand in 10 s: %.2f m at mean slip %.3f single-pass, %.2f m at %.3f multi-pass\n",
              progress_of[0], slip_of[0], progress_of[1], slip_of[1]);
  EXPECT_GT(progress_of[1], 1.05 * progress_of[0]);
  EXPECT_LT(slip_of[1], slip_of[0]);

  Scenario parked = on_slope(10.0, "dry_sand");
  parked.world.soil->multi_pass = true;
  parked.timeline.clear();
  parked.duration = 11.0;
  const ScenarioResult r = run("parked on 10 deg of dry sand, multi-pass", parked);
  ASSERT_TRUE(r.completed) << r.error;
  EXPECT_LT(std::hypot(r.final_x - parked.spawn.x, r.final_y - parked.spawn.y), 0.01);
}

// A terrain the project has never seen, generated:
// 45 m x 45 m at 5 cm, rolling ground (three octaves of sines at odd angles, 1.5 m of relief),
// a ridge, a pit and 40 boulders (20-40 cm), written as a float TIFF and read back as any user's
// file would be. The CC8 drives a loop across it for 20 s.
class UnseenHeightmap : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_unseen_dem_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

physics::Heightmap generated_dem() {
  physics::Heightmap map;
  map.size_x = map.size_y = 45.0;
  map.rows = map.cols = 901;
  map.heights.resize(map.rows * map.cols);
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;  // fixed: the same field every run
  auto uniform = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  struct Boulder {
    double x, y, r, h;
  };
  std::vector<Boulder> boulders;
  for (int i = 0; i < 40; ++i) boulders.push_back({-20 + 40 * uniform(), -20 + 40 * uniform(), 0.2 + 0.2 * uniform(), 0.05 + 0.2 * uniform()});
  for (std::size_t r = 0; r < map.rows; ++r) {
    for (std::size_t c = 0; c < map.cols; ++c) {
      const double x = -22.5 + 0.05 * static_cast<double>(c), y = -22.5 + 0.05 * static_cast<double>(r);
      double h = 0.45 * std::sin(0.21 * x + 0.13 * y) + 0.25 * std::sin(0.47 * x - 0.31 * y + 1.0) +
                 0.08 * std::sin(1.3 * x + 0.9 * y + 2.0);
      h += 0.6 * std::exp(-std::pow((x - 0.4 * y - 8.0) / 2.5, 2));          // a ridge
      h -= 0.5 * std::exp(-(std::pow(x + 6.0, 2) + std::pow(y - 7.0, 2)) / 6.0);  // a pit
      for (const Boulder& b : boulders) {
        const double d2 = (std::pow(x - b.x, 2) + std::pow(y - b.y, 2)) / (b.r * b.r);
        if (d2 < 1.0) h += b.h * std::sqrt(1.0 - d2);
      }
      map.heights[r * map.cols + c] = static_cast<float>(h);
    }
  }
  map.source = "generated DEM";
  return map;
}

TEST_F(UnseenHeightmap, TheCc8DrivesAcrossItWithoutFallingThroughOrBlowingUp) {
  const fs::path file = dir_ / "unseen_dem.tif";
  physics::save_heightmap_tiff(generated_dem(), file);
  for (const char* soil : {"", "lete_sand"}) {
    Scenario s = shipped("soil_slope_climb");
    s.world = WorldConfig{};
    s.world.name = file.string();
    if (*soil) s.world.soil = physics::find_soil(soil);
    s.spawn = {-15.0, -12.0, 0.05, 0.0, 0.0, 0.4};
    s.settle_on_ground = true;
    s.duration = 20.0;
    s.timeline = {};
    TimelineEvent e;
    e.at = 0.5;
    e.controller = "rover_drive_controller";
    e.kind = TimelineEvent::Kind::Twist;
    e.twist.linear.x = 0.45;
    e.twist.angular.z = 0.05;
    s.timeline.push_back(e);
    s.checks = {};
    const ScenarioResult r = run(std::string("generated DEM, ") + (*soil ? soil : "rigid"), s);
    ASSERT_TRUE(r.completed) << r.error;  // no divergence, did not leave or fall off the field
    EXPECT_TRUE(r.events.empty());
    EXPECT_GT(r.distance, 4.0) << "it drove";
    EXPECT_LT(r.max_tilt, 40.0 * M_PI / 180.0) << "it stayed on its wheels";
    // Above the ground under it: its base (wheel axles 9 cm up) never below the terrain.
    const physics::Heightmap map = physics::load_heightmap(file.string(), {});
    const double ix = (r.final_x + 22.5) / 0.05, iy = (r.final_y + 22.5) / 0.05;
    const double ground = map.at(static_cast<std::size_t>(std::lround(iy)), static_cast<std::size_t>(std::lround(ix)));
    std::printf("[ figures  ] base %.3f m above the ground under it\n", r.final_z - ground);
    EXPECT_GT(r.final_z - ground, -0.05);
    EXPECT_LT(r.final_z - ground, 0.5);
  }
}

// A real DEM the project was not built on: Olinda, Brazil (UTM 25S), 111 x 111 float samples about
// 90 m apart, -1..88 m: coastal plain, sea (flat at 0 m) and a dissected plateau. Read as it is,
// its GeoTIFF footprint is about 10 km; laid onto 45 m x 45 m with its relief rescaled to 1.5 m
// (z_min/z_max, as Gazebo's <size> does for a DEM) it is a rough yard of 41 cm cells with steps
// of up to ~20 cm between cells. The CC8 drives 60 s of a route across the plain to the shore.
TEST_F(UnseenHeightmap, TheCc8DrivesARealPublicDemLaidOntoAYard) {
  const fs::path dem = fs::path(MECHSIM_SOURCE_DIR) / "build/test-data/olinda_dem_utm25s.tif";
  if (!fs::exists(dem)) {
    GTEST_SKIP() << dem.string() << " is absent: scripts/fetch-test-data.sh fetches it from Debian's r-cran-stars "
                 << "(scripts/test.sh runs it)";
  }
  const physics::Heightmap as_is = physics::load_heightmap(dem);
  EXPECT_EQ(as_is.cols, 111u);
  EXPECT_EQ(as_is.rows, 111u);
  EXPECT_NEAR(as_is.size_x, 10000.0, 500.0) << "the GeoTIFF pixel scale read";
  EXPECT_NEAR(*std::min_element(as_is.heights.begin(), as_is.heights.end()), -1.0, 0.5);
  EXPECT_NEAR(*std::max_element(as_is.heights.begin(), as_is.heights.end()), 88.0, 0.5);

  const fs::path robots = fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8";
  for (const char* soil : {"", "lete_sand"}) {
    const fs::path file = dir_ / (std::string("olinda_") + (*soil ? soil : "rigid") + ".yaml");
    std::ofstream(file) << "name: cc8_olinda_dem\n"
                        << "robot: {description: " << (robots / "urdf/cc8.urdf.xacro").string()
                        << ", packages: {mechsim_cc8: " << robots.string() << "}}\n"
                        << "world: {name: " << dem.string() << ", size_x: 45, size_y: 45, z_min: 0, z_max: 1.5"
                        << (*soil ? std::string(", soil: ") + soil : std::string()) << "}\n"
                        << "spawn: {x: -12, y: -17, yaw: 0.5}\n"
                        << "controllers: {file: " << (robots / "config/controllers.yaml").string()
                        << ", namespace: cc8, start: [joint_state_controller, rover_drive_controller]}\n"
                        << "duration: 60\n"
                        << "timeline:\n"
                        << "  - at: 0.5\n"
                        << "    controller: rover_drive_controller\n"
                        << "    route: {waypoints: [[-6, -13], [0, -9], [6, -8], [10, -12], [16, -14]], speed: 0.45,\n"
                        << "            tolerance: 0.4, lookahead: 1.0, max_yaw_rate: 0.5}\n";
    const ScenarioResult r = run(std::string("Olinda DEM, ") + (*soil ? soil : "rigid"), load_scenario(file.string()));
    ASSERT_TRUE(r.completed) << r.error;  // no divergence, did not leave or fall off the field
    EXPECT_TRUE(r.events.empty());
    EXPECT_GT(r.distance, *soil ? 12.0 : 20.0) << "it drove across the plain";
    EXPECT_LT(r.max_tilt, 35.0 * M_PI / 180.0) << "it stayed on its wheels";
    // Above the ground under it (the map as the world holds it: rescaled and 45 m across).
    physics::HeightmapOptions yard;
    yard.size_x = yard.size_y = 45.0;
    yard.z_min = 0.0;
    yard.z_max = 1.5;
    const physics::Heightmap map = physics::load_heightmap(dem, yard);
    const auto ix = static_cast<std::size_t>(std::lround((r.final_x + 22.5) / map.cell_x()));
    const auto iy = static_cast<std::size_t>(std::lround((r.final_y + 22.5) / map.cell_y()));
    const double ground = map.at(iy, ix);
    std::printf("[ figures  ] base %.3f m above the ground under it\n", r.final_z - ground);
    EXPECT_GT(r.final_z - ground, -0.05);
    EXPECT_LT(r.final_z - ground, 0.5);
  }
}

}  // namespace
}  // namespace mechsim::sim
