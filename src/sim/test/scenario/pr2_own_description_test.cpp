// mechsim's own PR2 description (robots/pr2/urdf/pr2.urdf.xacro, primitive collision shapes)
// under the PR2's default controller set (robots/pr2/config/controllers.yaml, namespace pr2):
// it loads, every default controller starts, and the robot stands for 2 s on the empty world
// without falling, sinking or tipping. Where the shared data is present, its standing height is
// compared with the real description's (same wheels, so the same height).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "description/robot_loader.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/pose_math.hpp"
#include "sim/simulation.hpp"
#include "sim/test/scenario/pr2_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kDefaultSet = {"r_arm_controller",     "l_arm_controller",     "head_traj_controller",
                                              "torso_controller",     "base_controller",      "base_odometry",
                                              "r_gripper_controller", "l_gripper_controller", "laser_tilt_controller"};

std::unique_ptr<Simulation> make_simulation(description::RobotModel robot) {
  const control::Params root =
      control::Params::from_yaml_file((fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2/config/controllers.yaml").string());
  SimulationOptions options;
  options.spawn.z = 0.01;
  options.integrator = pr2_test_integrator();
  auto sim = std::make_unique<Simulation>(std::move(robot), make_world({}), root.child("pr2"), options);
  sim->load_and_start(kDefaultSet);
  return sim;
}

struct Stance {
  double min_z = std::numeric_limits<double>::infinity();
  double max_z = -std::numeric_limits<double>::infinity();
  double final_z = 0.0;
  double max_tilt = 0.0;
  double max_xy = 0.0;  // horizontal drift from the spawn point (m)
};

// Runs `seconds` and records the base (root link, base_footprint) pose after the first 0.2 s of
// settling onto the wheels.
Stance stand(Simulation& sim, double seconds) {
  Stance s;
  const description::Pose p0 = sim.physics().base_pose();
  sim.add_observer([&](const Simulation& sm) {
    if (sm.time() < 0.2) return;
    const description::Pose p = sm.physics().base_pose();
    s.min_z = std::min(s.min_z, p.position.z);
    s.max_z = std::max(s.max_z, p.position.z);
    s.final_z = p.position.z;
    s.max_tilt = std::max(s.max_tilt, tilt_of(p.orientation));
    s.max_xy = std::max(s.max_xy, std::hypot(p.position.x - p0.position.x, p.position.y - p0.position.y));
  });
  const TickResult r = sim.run_for(seconds);
  EXPECT_TRUE(r) << r.error;
  return s;
}

description::RobotModel load_own_pr2(const std::string& variant = "pr2") {
  description::LoadOptions load;
  load.packages["mechsim_pr2"] = (fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2").string();
  load.lenient = false;
  const fs::path file = fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2/urdf" / (variant + ".urdf.xacro");
  return description::load_robot(file.string(), load).model;
}

TEST(Pr2OwnDescription, StandsTwoSecondsUnderTheDefaultControllers) {
  auto sim = make_simulation(load_own_pr2());
  const Stance s = stand(*sim, 2.0);
  std::cout << "[ figures  ] mechsim PR2 over 2 s: base_footprint z " << s.min_z << " .. " << s.max_z
            << " m, max tilt " << s.max_tilt << " rad, drift " << s.max_xy << " m\n";
  // On its wheels: the footprint stays within 2 cm of the floor (it neither sinks nor jumps),
  // the base stays level and in place.
  EXPECT_GT(s.min_z, -0.02);
  EXPECT_LT(s.max_z, 0.02);
  EXPECT_LT(s.max_tilt, 0.02);
  EXPECT_LT(s.max_xy, 0.05);
  std::size_t running = 0;
  for (const control::ControllerInfo& info : sim->controllers().list_controllers()) {
    if (std::find(kDefaultSet.begin(), kDefaultSet.end(), info.name) == kDefaultSet.end()) continue;
    EXPECT_EQ(info.state, control::ControllerLifecycle::Running) << info.name << ": " << info.failure;
    ++running;
  }
  EXPECT_EQ(running, kDefaultSet.size());
  // The torso holds near where its controller found it (its trajectory controller holds the
  // start position); the arms do not fall (gravity is off on them, as on the real PR2).
  const auto torso = sim->physics().model().joint_index("torso_lift_joint");
  ASSERT_TRUE(torso);
  EXPECT_LT(std::abs(sim->physics().position(*torso)), 0.02);
}

// Every variant builds into the physics and rests level on its casters with no controller
// running (the one-armed PR2 SE carries its arm on one side).
TEST(Pr2OwnDescription, EveryVariantRestsLevelWithoutControllers) {
  for (const char* variant : {"pr2", "pr2_no_arms", "pr2_no_kinect", "pr2_one_arm"}) {
    SCOPED_TRACE(variant);
    SimulationOptions options;
    options.spawn.z = 0.01;
    options.integrator = pr2_test_integrator();
    Simulation sim(load_own_pr2(variant), make_world({}), control::Params{}, options);
    const Stance s = stand(sim, 1.0);
    std::cout << "[ figures  ] " << variant << " without controllers, 1 s: base_footprint z " << s.min_z << " .. "
              << s.max_z << " m, max tilt " << s.max_tilt << " rad\n";
    EXPECT_GT(s.min_z, -0.02);
    EXPECT_LT(s.max_z, 0.02);
    EXPECT_LT(s.max_tilt, 0.02);
    EXPECT_LT(s.max_xy, 0.05);
  }
}

TEST(Pr2OwnDescription, StandsAsHighAsTheRealDescription) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  auto own = make_simulation(load_own_pr2());
  const Stance a = stand(*own, 1.0);
  auto real = make_pr2_simulation(kDefaultSet);
  const Stance b = stand(*real, 1.0);
  std::cout << "[ figures  ] standing base_footprint z after 1 s: mechsim PR2 " << a.final_z << " m, real PR2 "
            << b.final_z << " m\n";
  EXPECT_NEAR(a.final_z, b.final_z, 0.002);
}

}  // namespace
}  // namespace mechsim::sim
