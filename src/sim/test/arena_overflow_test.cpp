// Many free boxes piled on mechsim's CC8: however full MuJoCo's contact and constraint arena
// gets, no contact is dropped silently. The arena grows (each growth reported with its tick, and
// the physics exactly that of a large enough arena) or, when told to, the run stops with an
// error naming the tick and the count.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "control/params.hpp"
#include "description/robot_loader.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

// 48 free 0.12 m boxes of 0.4 kg in four layers of 3 x 4 over the CC8's chassis.
World pile_world() {
  World world = make_world({});
  for (int layer = 0; layer < 4; ++layer)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) {
        physics::WorldBox b;
        char name[32];
        std::snprintf(name, sizeof name, "box_%d_%d_%d", layer, i, j);
        b.name = name;
        b.pose.position = {0.13 * (i - 1), 0.13 * (j - 1.5), 0.45 + 0.13 * layer};
        b.size = {0.12, 0.12, 0.12};
        b.mass = 0.4;
        b.fixed = false;
        world.spec.boxes.push_back(b);
      }
  return world;
}

std::unique_ptr<Simulation> cc8_under_boxes(const SimulationOptions& options) {
  const fs::path root = MECHSIM_SOURCE_DIR;
  description::LoadOptions load;
  load.packages["mechsim_cc8"] = (root / "robots/cc8").string();
  description::RobotModel robot = description::load_robot((root / "robots/cc8/urdf/cc8.urdf.xacro").string(), load).model;
  control::Params params = control::Params::from_yaml_file((root / "robots/cc8/config/controllers.yaml").string()).child("cc8");
  auto sim = std::make_unique<Simulation>(std::move(robot), pile_world(), params, options);
  sim->load_and_start({"joint_state_controller", "rover_drive_controller"});
  return sim;
}

SimulationOptions with_arena(std::optional<physics::ArenaSize> arena, physics::ArenaOverflow overflow) {
  SimulationOptions o;
  o.spawn.z = 0.02;
  o.arena = arena;
  o.arena_overflow = overflow;
  return o;
}

TEST(ArenaOverflow, BoxesPiledOnTheCc8GrowTheArenaWithTheSamePhysicsAsALargeOne) {
  auto grown = cc8_under_boxes(with_arena(physics::ArenaSize{16, 48}, physics::ArenaOverflow::Grow));
  auto large = cc8_under_boxes(with_arena(physics::ArenaSize{3000, 6000}, physics::ArenaOverflow::Grow));
  auto estimated = cc8_under_boxes(with_arena(std::nullopt, physics::ArenaOverflow::Grow));
  for (int tick = 0; tick < 1000; ++tick) {
    for (Simulation* s : {grown.get(), large.get(), estimated.get()}) {
      const TickResult r = s->step();
      ASSERT_TRUE(r) << r.error;
    }
    const description::Pose a = grown->physics().base_pose(), b = large->physics().base_pose(),
                            c = estimated->physics().base_pose();
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "the grown arena's CC8 left the large arena's at tick " << tick + 1;
    ASSERT_EQ(std::memcmp(&c, &b, sizeof c), 0) << "the estimated arena's CC8 left the large arena's at tick " << tick + 1;
  }
  const physics::ArenaUse use = large->physics().arena_use();
  std::printf("[ figures  ] pile on the CC8: at most %d contacts, %d constraint rows in a tick; estimated arena %d, %d "
              "(grew %d times)\n",
              use.peak.contacts, use.peak.constraints, estimated->physics().arena_use().size.contacts,
              estimated->physics().arena_use().size.constraints, estimated->physics().arena_use().growths);
  EXPECT_GT(use.peak.contacts, 100);  // the boxes rest on the rover and on each other

  // Every growth of the small arena is a warning naming its tick (the boxes on the chassis fill
  // it at spawn already) and what was full.
  const std::vector<std::string> warnings = grown->physics_warnings();
  ASSERT_GE(warnings.size(), 3u);
  EXPECT_EQ(warnings.size(), static_cast<std::size_t>(grown->physics().arena_use().growths));
  EXPECT_NE(warnings[0].find("MuJoCo's contact list was full (16 contacts)"), std::string::npos) << warnings[0];
  int during_run = 0;
  for (const std::string& w : warnings) {
    std::printf("[ warning  ] %s\n", w.c_str());
    EXPECT_TRUE(w.rfind("spawn (t = 0 s): MuJoCo's ", 0) == 0 || w.rfind("tick ", 0) == 0) << w;
    during_run += w.rfind("tick ", 0) == 0 ? 1 : 0;
  }
  EXPECT_GE(during_run, 1);
  EXPECT_TRUE(large->physics_warnings().empty());
  // The estimate either held the pile or grew, and said so.
  EXPECT_EQ(estimated->physics_warnings().size(), static_cast<std::size_t>(estimated->physics().arena_use().growths));
}

TEST(ArenaOverflow, WithoutGrowthTheRunStopsNamingTheTickAndTheCount) {
  auto sim = cc8_under_boxes(with_arena(physics::ArenaSize{40, 2000}, physics::ArenaOverflow::Fail));
  const TickResult r = sim->run_for(1.5);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error.find("physics failed at tick "), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("needs more than 40 contacts"), std::string::npos) << r.error;
  EXPECT_TRUE(sim->paused());  // stopped, as after a divergence
  EXPECT_EQ(sim->divergences(), 1u);
}

}  // namespace
}  // namespace mechsim::sim
