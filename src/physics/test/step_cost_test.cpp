// physics::StepCost: the cheaper ways to the same MuJoCo step compute what the step computed before.
// Listed collision pairs are exactly MuJoCo's own (the same contacts in the same order, so the
// same trajectory to the bit); xfrc_applied gathered over the tree gives mj_applyFT's joint forces;
// all ways together follow the step as before within rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "physics/collision_pairs.hpp"
#include "physics/mujoco_internal.hpp"
#include "physics/physics_data.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

std::string pr2_file() { return test::shared_dir() + "/robots/reference/pr2.urdf"; }

BuildOptions with(StepCost cost) {
  BuildOptions o;
  o.spawn.z = 0.02;
  o.step_cost = cost;
  return o;
}

bool mentions_listed_pairs(const PhysicsModel& m) {
  return std::any_of(m.warnings().begin(), m.warnings().end(),
                     [](const std::string& w) { return w.find("listed collision pairs") != std::string::npos; });
}

// A floating three-link chain whose links collide with each other (selfCollide) and a few free
// boxes dropped on it: robot-robot, robot-object and object-object pairs, welded and hinged links.
std::string self_colliding_chain() {
  std::string s = R"(<robot name="chain">
  <link name="base">
    <inertial><mass value="2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.4 0.2 0.1"/></geometry></collision>
    <visual><geometry><box size="0.4 0.2 0.1"/></geometry></visual>
  </link>
  <link name="plate">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.02"/></geometry></collision>
  </link>
  <joint name="weld" type="fixed"><parent link="base"/><child link="plate"/><origin xyz="0.1 0 0.06"/></joint>)";
  const char* parents[] = {"base", "l1", "l2"};
  for (int i = 1; i <= 3; ++i) {
    const std::string l = "l" + std::to_string(i);
    s += R"(
  <link name=")" + l + R"(">
    <inertial><origin xyz="0.15 0 0"/><mass value="0.5"/><inertia ixx="0.001" iyy="0.004" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0.15 0 0"/><geometry><box size="0.3 0.05 0.05"/></geometry></collision>
  </link>
  <joint name="j)" + std::to_string(i) + R"(" type="revolute"><parent link=")" + parents[i - 1] + R"("/><child link=")" + l +
         R"("/><origin xyz=")" + (i == 1 ? "0.2 0 0.1" : "0.3 0 0") + R"(" rpy="0 0 2.2"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="5"/></joint>
  <gazebo reference=")" + l + R"("><selfCollide>true</selfCollide></gazebo>)";
  }
  return s + "\n</robot>";
}

BuildOptions boxes_over_chain(StepCost cost) {
  BuildOptions o = with(cost);
  o.spawn.z = 0.1;
  for (int i = 0; i < 3; ++i) {
    WorldBox b;
    b.name = "b" + std::to_string(i);
    b.fixed = false;
    b.mass = 0.3;
    b.size = {0.08, 0.08, 0.08};
    b.pose.position = {0.1 * i, 0.05, 0.4 + 0.15 * i};
    o.world.boxes.push_back(b);
  }
  return o;
}

// Steps both instances `steps` times with the same joint efforts; the largest difference of any
// body's position (m) or orientation (quaternion component), and whether every step's contacts matched (count, geoms, order).
struct Compared {
  double max_pose_difference = 0.0;
  bool same_contacts = true;
  std::size_t most_contacts = 0;
};

Compared run_both(Physics& a, Physics& b, int steps, double effort) {
  Compared out;
  std::vector<Contact> ca, cb;
  const std::size_t nj = a.model().joints().size();
  for (int k = 0; k < steps; ++k) {
    for (std::size_t j = 0; j < nj; ++j) {
      const double e = effort * std::sin(0.01 * k + static_cast<double>(j));
      a.set_effort(j, e);
      b.set_effort(j, e);
    }
    EXPECT_TRUE(a.step().ok());
    EXPECT_TRUE(b.step().ok());
    a.contacts(ca);
    b.contacts(cb);
    out.most_contacts = std::max(out.most_contacts, ca.size());
    if (ca.size() != cb.size()) out.same_contacts = false;
    for (std::size_t i = 0; i < std::min(ca.size(), cb.size()); ++i)
      if (ca[i].geom_a != cb[i].geom_a || ca[i].geom_b != cb[i].geom_b) out.same_contacts = false;
  }
  // Every body's pose (the robot's links, the free objects).
  for (int body = 1; body < a.model().body_count(); ++body) {
    const description::Pose pa = a.body_pose(body), pb = b.body_pose(body);
    for (double d : {pa.position.x - pb.position.x, pa.position.y - pb.position.y, pa.position.z - pb.position.z,
                     pa.orientation.w - pb.orientation.w, pa.orientation.x - pb.orientation.x,
                     pa.orientation.y - pb.orientation.y, pa.orientation.z - pb.orientation.z})
      out.max_pose_difference = std::max(out.max_pose_difference, std::abs(d));
  }
  return out;
}

TEST(StepCost, ThePr2TestsItsGroundPairsWithoutTheBroadPhase) {
  if (!test::shared_dir_present()) GTEST_SKIP() << "shared data absent: " << test::shared_dir();
  const auto model = PhysicsModel::build(test::parse_file(pr2_file()), with({}));
  // No link self-collides: each collision geom against the ground plane, nothing else.
  int collision_geoms = 0;
  for (int g = 0; g < model->geom_count(); ++g)
    if (model->geom_name(g).find("/collision/") != std::string_view::npos) ++collision_geoms;
  EXPECT_EQ(model->listed_pairs(), collision_geoms);
  EXPECT_GT(collision_geoms, 40);
  EXPECT_FALSE(mentions_listed_pairs(*model));
  EXPECT_NE(model->mjcf().find("collision=\"predefined\""), std::string::npos);
  EXPECT_NE(model->mjcf().find("jacobian=\"sparse\""), std::string::npos);
  const auto before = PhysicsModel::build(test::parse_file(pr2_file()), with(StepCost::before()));
  EXPECT_EQ(before->listed_pairs(), 0);
  EXPECT_EQ(before->mjcf().find("<pair"), std::string::npos);
}

TEST(StepCost, ListedPairsGiveTheBroadPhasesContactsInItsOrder) {
  StepCost pairs_only = StepCost::before();
  pairs_only.listed_pairs = true;
  const auto listed = test::build(self_colliding_chain(), boxes_over_chain(pairs_only));
  const auto broad = test::build(self_colliding_chain(), boxes_over_chain(StepCost::before()));
  ASSERT_GT(listed->listed_pairs(), 0);
  EXPECT_FALSE(mentions_listed_pairs(*listed));
  // Listed: robot-ground, box-ground, box-box, box-robot and the self-colliding links' pairs
  // (not l1-base, l1-l2, l2-l3: parent and child; base and plate are one welded body).
  Physics a(listed), b(broad);
  const Compared c = run_both(a, b, 1500, 2.0);
  std::cout << "[ figures  ] chain and boxes: " << listed->listed_pairs() << " listed pairs, at most " << c.most_contacts
            << " contacts a step\n";
  EXPECT_GT(c.most_contacts, 4u);  // the boxes landed on the chain and on each other
  EXPECT_TRUE(c.same_contacts);
  EXPECT_EQ(c.max_pose_difference, 0.0);  // the same contacts in the same order: the same step
}

TEST(StepCost, ThePr2StepsAsBeforeWithEveryWayOn) {
  if (!test::shared_dir_present()) GTEST_SKIP() << "shared data absent: " << test::shared_dir();
  const description::RobotModel robot = test::parse_file(pr2_file());
  Physics a(PhysicsModel::build(robot, with({}))), b(PhysicsModel::build(robot, with(StepCost::before())));
  ASSERT_FALSE(a.model().gravity_off_bodies().empty());  // the arms: tree forces at work
  const Compared c = run_both(a, b, 1000, 0.5);
  std::cout << "[ figures  ] PR2 over 1 s, every way on against the step as before: largest pose difference "
            << c.max_pose_difference << "\n";
  EXPECT_TRUE(c.same_contacts);
  EXPECT_GE(c.most_contacts, 8u);  // its eight wheels
  EXPECT_LT(c.max_pose_difference, 1e-9);  // rounding only (sparse algebra, sums in another order)
}

TEST(StepCost, TreeForcesAreMuJoCosApplyFT) {
  if (!test::shared_dir_present()) GTEST_SKIP() << "shared data absent: " << test::shared_dir();
  const auto model = PhysicsModel::build(test::parse_file(pr2_file()), with({}));
  const mjModel* m = model->impl().model;
  mjData* d = mj_makeData(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < m->nq; ++i) d->qpos[i] = m->qpos0[i] + 0.3 * u(rng);
  mj_normalizeQuat(m, d->qpos);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  for (int i = 0; i < 6 * m->nbody; ++i) d->xfrc_applied[i] = 10.0 * u(rng);
  std::vector<mjtNum> expected(static_cast<std::size_t>(m->nv), 0.0), got(static_cast<std::size_t>(m->nv), 0.0);
  std::vector<mjtNum> scratch(6 * static_cast<std::size_t>(m->nbody));
  for (int b = 1; b < m->nbody; ++b)
    mj_applyFT(m, d, d->xfrc_applied + 6 * b, d->xfrc_applied + 6 * b + 3, d->xipos + 3 * b, b, expected.data());
  detail::add_tree_forces(m, d, got.data(), scratch.data());
  for (int v = 0; v < m->nv; ++v) EXPECT_NEAR(got[v], expected[v], 1e-9 * (1.0 + std::abs(expected[v]))) << "dof " << v;
  mj_deleteData(d);
}

TEST(StepCost, ManyPairsOfMovingBodiesKeepTheBroadPhase) {
  BuildOptions o = with({});
  for (int i = 0; i < 50; ++i) {  // 1225 box-box pairs, each tested every step if listed
    WorldBox b;
    b.name = "b" + std::to_string(i);
    b.fixed = false;
    b.pose.position = {0.3 * (i % 10), 0.3 * (i / 10), 0.5};
    o.world.boxes.push_back(b);
  }
  const auto model = test::build(test::box_urdf(), o);
  EXPECT_EQ(model->listed_pairs(), 0);
  EXPECT_FALSE(mentions_listed_pairs(*model));  // too many is a choice, not a fault
  EXPECT_EQ(model->mjcf().find("<pair"), std::string::npos);
}

TEST(StepCost, TheCheckNamesAPairThatIsNotMuJoCos) {
  const auto model = test::build(self_colliding_chain(), boxes_over_chain({}));
  ASSERT_GT(model->listed_pairs(), 1);
  mjModel* m = mj_copyModel(nullptr, model->impl().model);
  EXPECT_EQ(check_listed_pairs(*m), "");
  m->pair_friction[0] *= 2.0;
  EXPECT_NE(check_listed_pairs(*m).find("friction differs"), std::string::npos) << check_listed_pairs(*m);
  m->pair_friction[0] /= 2.0;
  m->pair_geom2[0] = m->pair_geom2[1];
  m->pair_geom1[0] = m->pair_geom1[1];
  EXPECT_NE(check_listed_pairs(*m).find("listed twice"), std::string::npos) << check_listed_pairs(*m);
  mj_deleteModel(m);
}

}  // namespace
}  // namespace mechsim::physics
