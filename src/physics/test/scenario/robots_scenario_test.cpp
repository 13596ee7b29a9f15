// The shipped robots in MuJoCo: the CC8 and the PR2 reference descriptions build, and the CC8
// dropped onto the empty world comes to rest on its six wheels.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>

#include "description/urdf/urdf_parser.hpp"
#include "physics/physics.hpp"
#include "physics/soil.hpp"

namespace mechsim::physics {
namespace {

const std::string kShared = MECHSIM_SHARED_DIR;

bool shared_present() { return std::filesystem::is_directory(kShared + "/robots/reference"); }

description::RobotModel load(const std::string& name) {
  description::UrdfOptions o;
  o.lenient = true;  // the reference files are what users have; mass/inertia quirks are warnings
  o.packages["cc8_description"] = kShared + "/robots/cc8_description";
  o.packages["pr2_description"] = kShared + "/robots/pr2_description";
  return description::parse_urdf_file(kShared + "/robots/reference/" + name, o);
}

double roll_of(const description::Quat& q) { return std::atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y)); }
double pitch_of(const description::Quat& q) { return std::asin(std::clamp(2 * (q.w * q.y - q.z * q.x), -1.0, 1.0)); }

TEST(RobotsScenario, Cc8BuildsWithItsJointsAndDifferential) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  auto model = PhysicsModel::build(load("cc8.urdf"));
  for (const char* j : {"rocker_joint_L", "rocker_joint_R", "bogie_joint_L", "bogie_joint_R", "steering_FL",
                        "steering_RR", "wheel_joint_FL", "wheel_joint_ML", "wheel_joint_RR"})
    EXPECT_TRUE(model->joint_index(j).has_value()) << j;
  EXPECT_EQ(model->joints().size(), 14u);
  EXPECT_FALSE(model->fixed_to_world());
  ASSERT_TRUE(model->differential().has_value());
  EXPECT_EQ(model->differential()->plugin, "rocker_differential");
  EXPECT_DOUBLE_EQ(model->differential()->force_constant, 1000.0);
  EXPECT_THAT(model->mjcf(), ::testing::HasSubstr("joint1=\"rocker_joint_R\" joint2=\"rocker_joint_L\""));
  for (const std::string& w : model->warnings()) std::printf("cc8 warning: %s\n", w.c_str());
}

// Dropped from 5 cm onto the empty world, after 4 s the CC8 stands still on its six wheels
// (each wheel touches the ground; nothing else does), level within 3 degrees.
double expect_cc8_rests_on_six_wheels(DifferentialMode mode, const std::optional<Heightmap>& terrain = {}) {
  BuildOptions o;
  o.spawn.z = 0.05;
  o.differential = mode;
  std::string ground = "ground";
  if (terrain) {
    o.world.kind = WorldSpec::Kind::Heightmap;
    o.world.terrain = terrain;
    o.spawn.z += 0.3;
    ground = "terrain";
  }
  auto model = PhysicsModel::build(load("cc8.urdf"), o);
  Physics p(model);
  if (terrain) {
    // Free wheels creep (~3 cm/s) on MuJoCo 2.2.2 cylinder-hfield contacts; park the rover as
    // its wheel controllers would, with zero-velocity servos.
    for (const char* w : {"wheel_joint_FL", "wheel_joint_FR", "wheel_joint_ML", "wheel_joint_MR", "wheel_joint_RL",
                          "wheel_joint_RR"})
      p.set_mode(*model->joint_index(w), JointMode::Velocity);
  }
  while (p.time() < 4.0) {
    const StepStatus s = p.step();
    EXPECT_TRUE(s.ok()) << s.message() << " at t = " << p.time();
    if (!s.ok()) return 0.0;
  }
  std::vector<Contact> contacts;
  p.contacts(contacts);
  std::set<std::string> on_ground;
  for (const Contact& c : contacts) {
    if (c.link_a == ground) on_ground.insert(std::string(c.link_b));
    if (c.link_b == ground) on_ground.insert(std::string(c.link_a));
  }
  EXPECT_EQ(on_ground, (std::set<std::string>{"wheel_FL_1", "wheel_FR_1", "wheel_ML_1", "wheel_MR_1", "wheel_RL_1",
                                             "wheel_RR_1"}));
  const Twist v = p.base_twist();
  EXPECT_LT(std::hypot(v.linear.x, v.linear.y, v.linear.z), 0.01);
  const auto X = p.base_pose();
  EXPECT_LT(std::fabs(roll_of(X.orientation)), 0.05);
  EXPECT_LT(std::fabs(pitch_of(X.orientation)), 0.05);
  std::printf("cc8 at rest (%s, %s): base z %.4f m, roll %.4f, pitch %.4f rad\n",
              mode == DifferentialMode::PluginLaw ? "plugin law" : "mimic", ground.c_str(), X.position.z,
              roll_of(X.orientation), pitch_of(X.orientation));
  return X.position.z;
}

TEST(RobotsScenario, Cc8ComesToRestOnSixWheelsWithTheMimicConstraint) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  expect_cc8_rests_on_six_wheels(DifferentialMode::MimicConstraint);
}

TEST(RobotsScenario, Cc8ComesToRestOnSixWheelsWithTheDifferentialPlugin) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  expect_cc8_rests_on_six_wheels(DifferentialMode::PluginLaw);
}

// On a heightmap plateau 0.3 m up, the parked rover rests as on the plane, 0.3 m higher (5 mm).
TEST(RobotsScenario, Cc8RestsOnHeightmapTerrainAtTheGridsHeight) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  Heightmap h;
  h.rows = h.cols = 41;
  h.size_x = h.size_y = 8.0;
  h.source = "plateau";
  h.heights.assign(h.rows * h.cols, 0.3f);
  h.heights[0] = 0.0f;  // a low corner, far from the rover
  const double on_terrain = expect_cc8_rests_on_six_wheels(DifferentialMode::MimicConstraint, h);
  const double on_plane = expect_cc8_rests_on_six_wheels(DifferentialMode::MimicConstraint);
  EXPECT_NEAR(on_terrain - on_plane, 0.3, 0.005);
}

// Two CC8 instances driven by the same wheel efforts (plugin law, contacts, servos) stay
// bit-identical at every step.
TEST(RobotsScenario, Cc8TrajectoriesAreBitIdentical) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  BuildOptions o;
  o.spawn.z = 0.05;
  o.differential = DifferentialMode::PluginLaw;
  auto model = PhysicsModel::build(load("cc8.urdf"), o);
  Physics a(model), b(model);
  const std::size_t steer = *model->joint_index("steering_FL");
  a.set_mode(steer, JointMode::Position, {50.0, 2.0});
  b.set_mode(steer, JointMode::Position, {50.0, 2.0});
  for (int i = 0; i < 2000; ++i) {
    for (const char* w : {"wheel_joint_FL", "wheel_joint_ML", "wheel_joint_RL"}) {
      a.set_effort(*model->joint_index(w), 2.0);
      b.set_effort(*model->joint_index(w), 2.0);
    }
    a.set_position_command(steer, 0.3 * std::sin(0.002 * i));
    b.set_position_command(steer, 0.3 * std::sin(0.002 * i));
    ASSERT_TRUE(a.step().ok());
    ASSERT_TRUE(b.step().ok());
    for (std::size_t j = 0; j < a.joint_count(); ++j) {
      const double qa = a.position(j), qb = b.position(j);
      ASSERT_EQ(std::memcmp(&qa, &qb, sizeof qa), 0) << model->joints()[j].name << " at step " << i;
    }
    const auto Xa = a.base_pose(), Xb = b.base_pose();
    ASSERT_EQ(std::memcmp(&Xa, &Xb, sizeof Xa), 0) << "base at step " << i;
  }
  EXPECT_GT(std::fabs(a.base_pose().position.x) + std::fabs(a.base_pose().position.y), 0.05);  // it drove
}

// Two CC8s in one MuJoCo model: the first as the robot, the second an actuated world model
// "rover2" 4 m to its left (physics_options.hpp, WorldModel::actuated).
std::shared_ptr<const PhysicsModel> two_cc8s(const description::Pose& X_W_rover2, BuildOptions o = {}) {
  o.spawn.z = 0.05;
  WorldModel second;
  second.name = "rover2";
  second.robot = std::make_shared<const description::RobotModel>(load("cc8.urdf"));
  second.pose = X_W_rover2;
  second.actuated = true;
  o.world.models.push_back(second);
  return PhysicsModel::build(load("cc8.urdf"), o);
}

const char* const kCc8Wheels[] = {"wheel_joint_FL", "wheel_joint_FR", "wheel_joint_ML",
                                  "wheel_joint_MR", "wheel_joint_RL", "wheel_joint_RR"};

// Each rover's wheels as velocity motors (Gazebo's joint motors) at `speed` rad/s, its steering
// held straight.
void drive(Physics& p, const std::string& prefix, double speed) {
  for (const char* s : {"steering_FL", "steering_FR", "steering_RL", "steering_RR"}) {
    const std::size_t j = *p.model().joint_index(prefix + s);
    if (p.mode(j) != JointMode::Position) p.set_mode(j, JointMode::Position, {200.0, 10.0});
    p.set_position_command(j, 0.0);
  }
  for (const char* w : kCc8Wheels) {
    const std::size_t j = *p.model().joint_index(prefix + w);
    if (p.mode(j) != JointMode::Velocity) p.set_mode(j, JointMode::Velocity, {0.0, 0.0, true});
    p.set_velocity_command(j, speed);
  }
}

// The second rover is built as the first: its joints and links are in the tables under its
// prefix, with actuators; it comes to rest on its own six wheels as the first does (its links do
// not collide with each other), and the two drive apart as their own commands say.
TEST(RobotsScenario, TwoCc8sInOneModelRestAndDriveAsTheirOwnCommandsSay) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  auto model = two_cc8s({{0.0, 4.0, 0.05}, {1, 0, 0, 0}});
  ASSERT_EQ(model->joints().size(), 28u);
  for (const char* w : kCc8Wheels) {
    const auto j = model->joint_index(std::string("rover2::") + w);
    ASSERT_TRUE(j.has_value()) << w;
    EXPECT_TRUE(model->joints()[*j].actuated);
    EXPECT_TRUE(model->joints()[*j].urdf_one_dof);
  }
  const auto base1 = model->link_index("base_link"), base2 = model->link_index("rover2::base_link");
  ASSERT_TRUE(base1 && base2);
  EXPECT_THAT(model->mjcf(), ::testing::HasSubstr("joint1=\"rover2::rocker_joint_R\" joint2=\"rover2::rocker_joint_L\""));

  Physics p(model);
  drive(p, "", 0.0);
  drive(p, "rover2::", 0.0);
  while (p.time() < 3.0) ASSERT_TRUE(p.step().ok()) << "t = " << p.time();
  std::vector<Contact> contacts;
  p.contacts(contacts);
  std::set<std::string> on_ground;
  for (const Contact& c : contacts) {
    EXPECT_TRUE(c.link_a == "ground" || c.link_b == "ground") << c.link_a << " touches " << c.link_b;
    on_ground.insert(std::string(c.link_a == "ground" ? c.link_b : c.link_a));
  }
  std::set<std::string> wheels;
  for (const char* prefix : {"", "rover2::"})
    for (const char* w : {"wheel_FL_1", "wheel_FR_1", "wheel_ML_1", "wheel_MR_1", "wheel_RL_1", "wheel_RR_1"})
      wheels.insert(std::string(prefix) + w);
  EXPECT_EQ(on_ground, wheels);
  const description::Pose rest1 = p.link_pose(*base1), rest2 = p.link_pose(*base2);
  EXPECT_NEAR(rest1.position.z, rest2.position.z, 1e-4);
  EXPECT_NEAR(rest2.position.y - rest1.position.y, 4.0, 1e-3);
  EXPECT_LT(std::hypot(p.link_twist(*base2).linear.x, p.link_twist(*base2).linear.y), 0.01);

  drive(p, "", 3.0);
  drive(p, "rover2::", -3.0);
  while (p.time() < 6.0) ASSERT_TRUE(p.step().ok()) << "t = " << p.time();
  const double d1 = p.link_pose(*base1).position.x - rest1.position.x;
  const double d2 = p.link_pose(*base2).position.x - rest2.position.x;
  std::printf("two CC8s: first %.3f m, second %.3f m along x in 3 s\n", d1, d2);
  EXPECT_GT(std::fabs(d1), 0.3);
  EXPECT_NEAR(d2, -d1, 0.05 * std::fabs(d1));
  EXPECT_NEAR(p.link_pose(*base2).position.y - p.link_pose(*base1).position.y, 4.0, 0.05);
}

// On soil both rovers' wheels sink (the CC8's wheels as cylinders, not point contacts): the
// second's wheels are in the model's wheel list under its prefix, and each sinks as the first
// rover's same wheel does.
TEST(RobotsScenario, TwoCc8sInOneModelBothSinkIntoTheSoil) {
  if (!shared_present()) GTEST_SKIP() << "shared data absent: " << kShared;
  BuildOptions o;
  o.contact.point_contact_wheels = false;
  auto model = two_cc8s({{0.0, 4.0, 0.05}, {1, 0, 0, 0}}, o);
  ASSERT_EQ(model->wheels().size(), 12u);
  EXPECT_EQ(model->wheels()[6].link, "rover2::wheel_FL_1");
  EXPECT_EQ(model->joints()[model->wheels()[6].joint].name, "rover2::wheel_joint_FL");
  Physics p(model);
  p.set_soil(*find_soil("dry_sand"));
  drive(p, "", 0.0);
  drive(p, "rover2::", 0.0);
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok()) << "t = " << p.time();
  const std::vector<WheelSoilReading>& r = p.wheel_soil();
  ASSERT_EQ(r.size(), 12u);
  for (std::size_t w = 0; w < 6; ++w) {
    SCOPED_TRACE(model->wheels()[w].link);
    EXPECT_TRUE(r[w].contact);
    EXPECT_TRUE(r[w + 6].contact);
    EXPECT_GT(r[w].sinkage, 0.001);
    EXPECT_NEAR(r[w + 6].sinkage, r[w].sinkage, 0.1 * r[w].sinkage);
  }
  std::printf("two CC8s on dry sand: front-left wheels sink %.1f and %.1f mm\n", 1e3 * r[0].sinkage, 1e3 * r[6].sinkage);
}

// The second rover dropped onto the first from 30 cm lands on it (the CC8's collision shapes are
// its wheels and its camera: on the first rover's wheels) and stays there, instead of falling
// through to the ground; the first carries it on its own wheels.
TEST(RobotsScenario, TwoCc8sInOneModelCollideWithEachOther) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  auto model = two_cc8s({{0.0, 0.0, 0.35}, {1, 0, 0, 0}});
  Physics p(model);
  const std::size_t base1 = *model->link_index("base_link"), base2 = *model->link_index("rover2::base_link");
  drive(p, "", 0.0);
  drive(p, "rover2::", 0.0);
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok()) << "t = " << p.time();
  std::vector<Contact> contacts;
  p.contacts(contacts);
  std::set<std::string> first_touches_second, second_on_ground;
  for (const Contact& c : contacts) {
    const bool a2 = c.link_a.rfind("rover2::", 0) == 0, b2 = c.link_b.rfind("rover2::", 0) == 0;
    if (a2 != b2 && c.link_a != "ground" && c.link_b != "ground")
      first_touches_second.insert(std::string(a2 ? c.link_b : c.link_a));
    if ((a2 && c.link_b == "ground") || (b2 && c.link_a == "ground")) second_on_ground.insert("x");
  }
  const double z1 = p.link_pose(base1).position.z, z2 = p.link_pose(base2).position.z;
  std::printf("second CC8 dropped on the first: bases at z %.3f and %.3f m, %zu links of the first touch it\n", z1,
              z2, first_touches_second.size());
  EXPECT_FALSE(first_touches_second.empty());
  EXPECT_TRUE(second_on_ground.empty());
  EXPECT_GT(z2 - z1, 0.1);
}

TEST(RobotsScenario, Pr2BuildsWithItsDaeMeshesAndSteps) {
  if (!shared_present()) GTEST_SKIP() << "shared data folder absent: " << kShared;
  BuildOptions o;
  o.spawn.z = 0.02;
  auto model = PhysicsModel::build(load("pr2.urdf"), o);
  for (const std::string& w : model->warnings()) std::printf("pr2 warning: %s\n", w.c_str());
  for (const char* j : {"torso_lift_joint", "r_shoulder_pan_joint", "l_wrist_roll_joint", "head_tilt_joint",
                        "fl_caster_rotation_joint", "r_gripper_l_finger_joint", "r_gripper_r_finger_joint"})
    EXPECT_TRUE(model->joint_index(j).has_value()) << j;
  // Massless gripper "frame" links on the prismatic gripper joints are merged (as Gazebo drops them).
  EXPECT_THAT(model->dropped_joints(), ::testing::UnorderedElementsAre("r_gripper_joint", "l_gripper_joint"));
  EXPECT_THAT(model->mjcf(), ::testing::HasSubstr("/visual/"));
  Physics p(model);
  while (p.time() < 2.0) {
    const StepStatus s = p.step();
    ASSERT_TRUE(s.ok()) << s.message() << " at t = " << p.time();
  }
  // Standing on its eight caster wheels (radius 0.074792 m, axles 0.0793 m above the
  // footprint): the footprint settles 4.5 mm below the ground, within 2 mm; only wheels touch.
  EXPECT_NEAR(p.base_pose().position.z, 0.074792 - 0.0793, 0.002);
  std::vector<Contact> contacts;
  p.contacts(contacts);
  std::set<std::string> on_ground;
  for (const Contact& c : contacts)
    if (c.link_a == "ground") on_ground.insert(std::string(c.link_b));
  EXPECT_EQ(on_ground.size(), 8u);
  for (const std::string& link : on_ground) EXPECT_THAT(link, ::testing::HasSubstr("_wheel_link"));
}

}  // namespace
}  // namespace mechsim::physics
