// Scenario tests of the whole tick with the real CC8 description (../shared): standing, the
// rocker differential, and the Mars Yard 2022 elevation model.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "control/params.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "physics/heightmap_io.hpp"
#include "sim/simulation.hpp"
#include "sim/test/scenario/scenario_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

TEST(Cc8Scenario, StandsOnSixWheelsWithItsControllersHolding) {
  const fs::path shared = MECHSIM_SHARED_DIR;
  if (!fs::exists(shared / "robots/reference/cc8.urdf")) GTEST_SKIP() << "shared data absent: " << shared;
  SimulationOptions options;
  options.integrator = cc8_test_integrator();
  options.spawn.z = 0.02;
  Simulation sim(load_shared_cc8(shared), make_world({}), cc8_controller_params(shared), options);
  sim.load_and_start(cc8_controller_names());

  ASSERT_TRUE(sim.run_for(2.0)) << "settling";
  double z_min = 1e9, z_max = -1e9, max_tilt = 0.0;
  sim.add_observer([&](const Simulation& s) {
    const description::Pose X_WB = s.physics().base_pose();
    z_min = std::min(z_min, X_WB.position.z);
    z_max = std::max(z_max, X_WB.position.z);
    max_tilt = std::max(max_tilt, tilt_of(X_WB.orientation));
  });
  const TickResult r = sim.run_for(10.0);
  ASSERT_TRUE(r) << r.error;
  EXPECT_NEAR(sim.time(), 12.0, 1e-9);
  std::cout << "[ figures  ] base z in [" << z_min << ", " << z_max << "] m, max tilt " << max_tilt
            << " rad, wheels in contact " << count_wheel_contacts(sim) << "\n";
  // base_footprint sits on the ground: wheel centres 0.09 m up, wheel radius 0.09 m.
  EXPECT_LT(z_max - z_min, 0.01) << "base height varied from " << z_min << " to " << z_max;
  EXPECT_NEAR(z_min, 0.0, 0.03);
  EXPECT_LT(max_tilt, 0.05);
  EXPECT_EQ(count_wheel_contacts(sim), 6);
  for (const control::ControllerInfo& info : sim.controllers().list_controllers()) {
    EXPECT_EQ(info.state, control::ControllerLifecycle::Running) << info.name << ": " << info.failure;
  }
  // The steering stayed where the controllers hold it (0 rad) within 0.05 rad.
  for (const char* steering : {"steering_FL", "steering_FR", "steering_RL", "steering_RR"}) {
    const auto j = sim.physics().model().joint_index(steering);
    ASSERT_TRUE(j);
    EXPECT_NEAR(sim.physics().position(*j), 0.0, 0.05) << steering;
  }
}

// A 12 cm step under the left front wheel: the left rocker turns, the right one turns the other
// way through the differential, and the body pitches by the mean of the two rockers' pitches.
TEST(Cc8Scenario, RockerDifferentialPitchesTheBodyByTheMeanOfTheRockers) {
  const fs::path shared = MECHSIM_SHARED_DIR;
  if (!fs::exists(shared / "robots/reference/cc8.urdf")) GTEST_SKIP() << "shared data absent: " << shared;
  for (const physics::DifferentialMode mode :
       {physics::DifferentialMode::MimicConstraint, physics::DifferentialMode::PluginLaw}) {
    SCOPED_TRACE(mode == physics::DifferentialMode::MimicConstraint ? "mimic constraint" : "plugin law");
    World world;
    world.name = "step under the left front wheel";
    world.spec.kind = physics::WorldSpec::Kind::Heightmap;
    world.spec.ground_plane = false;
    // 4 m x 4 m at 2 cm; the front-left wheel (x ~ 0.50, y ~ 0.41) stands on a 0.12 m block.
    world.spec.terrain = step_terrain(4.0, 0.02, [](double x, double y) {
      return (x > 0.35 && x < 0.75 && y > 0.25 && y < 0.60) ? 0.12 : 0.0;
    });
    SimulationOptions options;
  options.integrator = cc8_test_integrator();
    options.integrator = cc8_test_integrator();
    options.spawn.z = 0.15;
    options.differential = mode;
    Simulation sim(load_shared_cc8(shared), world, cc8_controller_params(shared), options);
    sim.load_and_start(cc8_controller_names());
    const TickResult r = sim.run_for(5.0);
    ASSERT_TRUE(r) << r.error;

    const double body = pitch_of(sim.physics().base_pose().orientation);
    const double left = pitch_of(link_pose(sim, "rocker_L_1").orientation);
    const double right = pitch_of(link_pose(sim, "rocker_R_1").orientation);
    std::cout << "[ figures  ] body pitch " << body << " rad, rockers " << left << " / " << right << " rad\n";
    EXPECT_GT(std::abs(left - right), 0.05) << "the rockers did not articulate: left " << left << " right " << right;
    EXPECT_NEAR(body, 0.5 * (left + right), 0.01) << "left " << left << " right " << right;
    EXPECT_GT(std::abs(body), 0.01) << "a raised wheel must pitch the body";
  }
}

TEST(Cc8Scenario, StaysUprightOnTheMarsYard2022ElevationModel) {
  const fs::path shared = MECHSIM_SHARED_DIR;
  const fs::path tif = shared / "terrain/marsyard2022_heightmap.tif";
  if (!fs::exists(tif) || !fs::exists(shared / "robots/reference/cc8.urdf")) {
    GTEST_SKIP() << "shared data absent: " << shared;
  }
  WorldConfig config;
  config.name = tif.string();
  const World world = make_world(config);
  SimulationOptions options;
  options.integrator = cc8_test_integrator();
  options.spawn.z = 0.1;
  Simulation sim(load_shared_cc8(shared), world, cc8_controller_params(shared), options);
  sim.load_and_start(cc8_controller_names());
  double max_tilt = 0.0;
  sim.add_observer([&](const Simulation& s) { max_tilt = std::max(max_tilt, tilt_of(s.physics().base_pose().orientation)); });
  const TickResult r = sim.run_for(10.0);
  ASSERT_TRUE(r) << r.error;
  std::cout << "[ figures  ] max tilt " << max_tilt << " rad, wheels in contact " << count_wheel_contacts(sim)
            << ", base at " << sim.physics().base_pose().position.z << " m\n";
  EXPECT_LT(max_tilt, 0.6) << "tilted " << max_tilt << " rad";
  EXPECT_GE(count_wheel_contacts(sim), 4);
}

}  // namespace
}  // namespace mechsim::sim
