// MuJoCo's per-instance arena (contacts, constraint rows): sized from the model, written into the
// MJCF, grown exactly when a step needs more (the step is recomputed: the same physics as a large
// enough arena), or failing clearly; never dropping contacts silently.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "physics/mujoco_internal.hpp"
#include "physics/physics_error.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using description::Pose;

// 27 free 0.1 m boxes in a 3 x 3 x 3 pile around the origin, just apart, with the test robot
// (a free 0.1 m cube) dropped on top: about a hundred contacts once they settle.
BuildOptions pile_options() {
  BuildOptions o;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        WorldBox b;
        char name[16];
        std::snprintf(name, sizeof name, "b%d%d%d", i, j, k);
        b.name = name;
        b.pose.position = {0.102 * (i - 1), 0.102 * (j - 1), 0.051 + 0.102 * k};
        b.size = {0.1, 0.1, 0.1};
        b.fixed = false;
        b.mass = 0.5;
        o.world.boxes.push_back(b);
      }
  o.spawn.z = 0.40;
  return o;
}

// Everything observable of a step: the robot's pose and every contact's bodies and position.
struct Frame {
  Pose base;
  std::vector<Contact> contacts;
};

std::vector<Frame> run(Physics& p, int steps) {
  std::vector<Frame> frames;
  for (int i = 0; i < steps; ++i) {
    const StepStatus s = p.step();
    EXPECT_TRUE(s.ok()) << s.message();
    if (!s.ok()) break;
    Frame f;
    f.base = p.base_pose();
    p.contacts(f.contacts);
    frames.push_back(std::move(f));
  }
  return frames;
}

void expect_identical(const std::vector<Frame>& a, const std::vector<Frame>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(std::memcmp(&a[i].base, &b[i].base, sizeof(Pose)), 0) << "robot pose differs at step " << i + 1;
    ASSERT_EQ(a[i].contacts.size(), b[i].contacts.size()) << "contact count differs at step " << i + 1;
    for (std::size_t c = 0; c < a[i].contacts.size(); ++c) {
      const Contact &x = a[i].contacts[c], &y = b[i].contacts[c];
      ASSERT_EQ(x.link_a, y.link_a);
      ASSERT_EQ(x.link_b, y.link_b);
      ASSERT_EQ(std::memcmp(&x.position, &y.position, sizeof(x.position)), 0) << "contact " << c << " at step " << i + 1;
      ASSERT_EQ(x.normal_force, y.normal_force) << "contact " << c << " at step " << i + 1;
    }
  }
}

TEST(PhysicsArena, EstimateCountsTheSupportAndEveryOtherPair) {
  // A free cube on the ground plane rests on its one geom: 4 contacts of 3 rows (elliptic cone,
  // condim 3), then a quarter more and the floor (8 contacts, 16 rows).
  auto cube = test::build(test::box_urdf());
  EXPECT_EQ(cube->arena().candidate_pairs, 1);
  EXPECT_EQ(cube->arena().contacts, 4);
  EXPECT_EQ(cube->arena().contact_rows, 12);
  EXPECT_EQ(cube->arena().size, (ArenaSize{4 + 1 + 8, 12 + 3 + 16}));
  // The limited pendulum's sphere can touch the ground (1 contact); its limit adds a row.
  auto pendulum = test::build(test::pendulum_urdf(1.0, 1.0, 1e-3, R"(<limit lower="-1" upper="1" effort="5" velocity="5"/>)", "revolute"));
  EXPECT_EQ(pendulum->arena().contacts, 1);
  EXPECT_EQ(pendulum->arena().other_rows, 1);
  // On a height field of 5 cm cells the cube rests on the cells under it: 3 x 3.
  BuildOptions o;
  o.world.kind = WorldSpec::Kind::Heightmap;
  Heightmap h;
  h.rows = h.cols = 41;
  h.size_x = h.size_y = 2.0;
  h.heights.assign(41 * 41, 0.0f);
  h.heights[5] = 0.01f;
  o.world.terrain = h;
  o.world.ground_plane = false;
  o.spawn.z = 0.2;
  EXPECT_EQ(test::build(test::box_urdf(), o)->arena().contacts, 9);
  // 27 free boxes and the cube: each rests on the ground (4 contacts each) and every other pair
  // that can touch counts one contact, at most 8 per geom (28 geoms: 112).
  auto pile = test::build(test::box_urdf(), pile_options());
  EXPECT_EQ(pile->arena().contacts, 28 * 4 + 112);
  EXPECT_FALSE(pile->arena().from_options);
}

TEST(PhysicsArena, TheMjcfCarriesTheArenaAndTheStackMuJoCoWouldGiveIt) {
  BuildOptions o = pile_options();
  o.arena = ArenaSize{50, 300};
  auto model = test::build(test::box_urdf(), o);
  EXPECT_TRUE(model->arena().from_options);
  EXPECT_NE(model->mjcf().find(R"(<size njmax="300" nconmax="50"/>)"), std::string::npos);
  // MuJoCo's compiler, given the written document, sizes everything as the model has it.
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  ASSERT_EQ(mj_makeEmptyFileVFS(&vfs, "m.xml", static_cast<int>(model->mjcf().size())), 0);
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "m.xml")], model->mjcf().data(), model->mjcf().size());
  char error[1000] = "";
  mjModel* direct = mj_loadXML("m.xml", &vfs, error, sizeof error);
  ASSERT_NE(direct, nullptr) << error;
  const mjModel* ours = model->impl().model;
  EXPECT_EQ(ours->njmax, direct->njmax);
  EXPECT_EQ(ours->nconmax, direct->nconmax);
  EXPECT_EQ(ours->nstack, direct->nstack);
  mj_deleteModel(direct);
  mj_deleteVFS(&vfs);
}

TEST(PhysicsArena, GrowsAndRecomputesTheStepExactlyAsALargeArena) {
  BuildOptions small = pile_options();
  small.arena = ArenaSize{8, 24};
  BuildOptions large = pile_options();
  large.arena = ArenaSize{2000, 4000};
  Physics grown(test::build(test::box_urdf(), small));
  Physics big(test::build(test::box_urdf(), large));
  Physics estimated(test::build(test::box_urdf(), pile_options()));
  const std::vector<Frame> a = run(grown, 1500), b = run(big, 1500), c = run(estimated, 1500);
  expect_identical(a, b);
  expect_identical(c, b);
  ASSERT_GT(b.back().contacts.size(), 80u);  // the pile has settled on dozens of contacts

  const ArenaUse use = grown.arena_use();
  EXPECT_GE(use.growths, 3);
  EXPECT_GE(use.size.contacts, static_cast<int>(b.back().contacts.size()));
  EXPECT_LE(use.peak.contacts, use.size.contacts);
  ASSERT_EQ(grown.notices().size(), static_cast<std::size_t>(use.growths));
  EXPECT_EQ(grown.notices()[0].kind, PhysicsNotice::Kind::ArenaGrown);
  EXPECT_NE(grown.notices()[0].text.find("contact list was full (8 contacts)"), std::string::npos) << grown.notices()[0].text;
  EXPECT_EQ(big.arena_use().growths, 0);
  EXPECT_TRUE(big.notices().empty());

  // A reset keeps the grown arena and starts the same trajectory again.
  grown.reset();
  EXPECT_EQ(grown.arena_use().size, use.size);
  expect_identical(run(grown, 300), std::vector<Frame>(b.begin(), b.begin() + 300));
  EXPECT_EQ(grown.arena_use().growths, use.growths);
}

TEST(PhysicsArena, FailPolicyStopsTheStepAndNamesWhatWasFull) {
  BuildOptions o = pile_options();
  o.arena = ArenaSize{8, 400};
  o.arena_overflow = ArenaOverflow::Fail;
  Physics p(test::build(test::box_urdf(), o));
  StepStatus s;
  while (s.ok() && p.time() < 1.0) s = p.step();
  ASSERT_EQ(s.code, StepCode::ArenaFull);
  EXPECT_EQ(s.element, "contacts");
  EXPECT_EQ(s.value, 8.0);
  EXPECT_NE(s.message().find("more than 8 contacts"), std::string::npos) << s.message();
  const double t = p.time();
  EXPECT_EQ(p.step().code, StepCode::ArenaFull);  // the state stayed before the step
  EXPECT_EQ(p.time(), t);
  EXPECT_EQ(p.arena_use().growths, 0);
}

TEST(PhysicsArena, GrowthStopsAtTheMaximum) {
  BuildOptions o = pile_options();
  o.arena = ArenaSize{8, 400};
  o.max_arena = ArenaSize{16, 400};
  Physics p(test::build(test::box_urdf(), o));
  StepStatus s;
  while (s.ok() && p.time() < 1.0) s = p.step();
  ASSERT_EQ(s.code, StepCode::ArenaFull);
  EXPECT_EQ(s.value, 16.0);
  EXPECT_EQ(p.arena_use().growths, 1);
  EXPECT_EQ(p.arena_use().size.contacts, 16);
}

TEST(PhysicsArena, BadArenaOptionsAreBuildErrors) {
  BuildOptions o;
  o.arena = ArenaSize{0, 10};
  EXPECT_THROW(test::build(test::box_urdf(), o), PhysicsError);
  o.arena = ArenaSize{10, 9000};  // beyond max_arena
  EXPECT_THROW(test::build(test::box_urdf(), o), PhysicsError);
  o.arena.reset();
  o.max_arena = ArenaSize{100, kMaxArenaConstraints + 1};
  EXPECT_THROW(test::build(test::box_urdf(), o), PhysicsError);
}

}  // namespace
}  // namespace mechsim::physics
