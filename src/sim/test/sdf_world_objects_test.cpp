// The objects of a Gazebo SDF world in mechsim's physics: pr2_gazebo's own scan.world (a sphere,
// a box, a cylinder and a cup mesh on a box for ground) becomes a world whose sphere, box and
// cylinder stand where the file puts them, at their sizes (found by ray casts from above); the
// cup's mesh, whose file the shared data lacks, is listed as not simulated. A static model's mesh
// (here an OBJ block of our own) stands where and as large as the file says, and holds objects up;
// a moving model's mesh falls, turns over and comes to rest at its size; a moving model of several
// links moves on its joints.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "physics/physics.hpp"
#include "physics/transform.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCube = R"(<robot name="cube"><link name="base"><inertial><mass value="1"/>
  <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link></robot>)";

TEST(SdfWorldObjects, Pr2ScanWorldsSphereBoxAndCylinderStandWhereTheFileSays) {
  const fs::path file = fs::path(MECHSIM_SHARED_DIR) / "robots/pr2_simulator/pr2_gazebo/test/sensors/scan.world";
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found at " << file;
  WorldConfig config;
  config.name = file.string();
  const World world = make_world(config);
  for (const char* m : {"gplane", "sphere1_model", "box1_model", "cylinder1_model"}) {
    EXPECT_NE(std::find(world.sdf_models.begin(), world.sdf_models.end(), m), world.sdf_models.end()) << m;
  }
  EXPECT_TRUE(std::any_of(world.not_simulated.begin(), world.not_simulated.end(),
                          [](const std::string& n) { return n.find("model 'cup1_model'") != std::string::npos; }));
  ASSERT_EQ(world.spec.boxes.size(), 4u);  // the ground is gplane, a 51.3 m box whose top is z = 0

  physics::BuildOptions options;
  options.world = world.spec;
  options.spawn.x = -2.0;  // out of the way
  const auto model = physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
  physics::Physics p(model);
  // The sphere: centre (2.5, -0.5, 0.5064), radius 0.5; the cylinder: centre (2, 0.8, 1), radius
  // 0.3, length 2, upright.
  EXPECT_NEAR(p.ground_height(2.5, -0.5), 1.0064, 1e-6);
  EXPECT_NEAR(p.ground_height(2.5 + 0.3, -0.5), 0.5064 + std::sqrt(0.25 - 0.09), 1e-6);
  EXPECT_NEAR(p.ground_height(2.0, 0.8), 2.0, 1e-6);
  EXPECT_NEAR(p.ground_height(2.0 + 0.29, 0.8), 2.0, 1e-6);
  EXPECT_NEAR(p.ground_height(2.0 + 0.31, 0.8), 0.0, 1e-6);
}

// Free cylinders and spheres fall and rest on the ground at their own size.
// pr2_gazebo's scan.world gives its objects' collisions laser_retro values (the PR2's Hokuyos
// report them as intensities): each world object's geom carries its collision's, the ground none.
TEST(SdfWorldObjects, Pr2ScanWorldsObjectsCarryTheirLaserRetro) {
  const fs::path file = fs::path(MECHSIM_SHARED_DIR) / "robots/pr2_simulator/pr2_gazebo/test/sensors/scan.world";
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found at " << file;
  WorldConfig config;
  config.name = file.string();
  const World world = make_world(config);
  physics::BuildOptions options;
  options.world = world.spec;
  options.spawn.x = -2.0;
  const auto model = physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
  std::map<std::string, double> retro;
  for (int g = 0; g < model->geom_count(); ++g) {
    const std::string name(model->geom_name(g));
    if (name.rfind("box:", 0) == 0) retro[name.substr(4, name.find("::") - 4)] = model->geom_laser_retro(g);
  }
  EXPECT_EQ(retro, (std::map<std::string, double>{
                       {"gplane", 0.0}, {"sphere1_model", 3000.0}, {"box1_model", 500.0}, {"cylinder1_model", 1000.0}}));
  // A ray from the side hits the sphere and reports its retro.
  physics::Physics p(model);
  const physics::RayFilter filter = physics::make_ray_filter(*model, -1, physics::RayTargets::Collision);
  const description::Vec3 dir{1.0, 0.0, 0.0};
  double range = 0.0;
  int hit = -1;
  p.cast_rays(filter, {0.0, -0.5, 0.5064}, &dir, 1, 0.0, 10.0, &range, &hit);
  EXPECT_NEAR(range, 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(model->geom_laser_retro(hit), 3000.0);
}

TEST(SdfWorldObjects, FreeCylindersAndSpheresRestAtTheirSize) {
  physics::BuildOptions options;
  physics::WorldBox ball, drum;
  ball.name = "ball";
  ball.shape = physics::WorldBox::Shape::Sphere;
  ball.size = {0.2, 0.2, 0.2};
  ball.pose.position = {1.0, 0.0, 0.5};
  ball.fixed = false;
  drum.name = "drum";
  drum.shape = physics::WorldBox::Shape::Cylinder;
  drum.size = {0.3, 0.3, 0.4};
  drum.pose.position = {-1.0, 0.0, 0.6};
  drum.fixed = false;
  drum.mass = 5.0;
  options.world.boxes = {ball, drum};
  const auto model = physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
  physics::Physics p(model);
  while (p.time() < 2.0) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.ground_height(1.0, 0.0), 0.2, 3e-3);    // the ball's top
  EXPECT_NEAR(p.ground_height(-1.0, 0.0), 0.4, 3e-3);   // the drum's top, still upright
  EXPECT_NEAR(p.ground_height(-1.0, 0.14), 0.4, 3e-3);  // flat across its face
}

// A unit cube with a corner at its origin (its frame is not its centre), as an OBJ file.
constexpr const char* kCubeObj = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
)";

constexpr const char* kMeshWorld = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <world name="meshes">
    <model name="ground"><static>true</static>
      <link name="l"><collision name="c"><geometry><plane><normal>0 0 1</normal><size>20 20</size></plane></geometry></collision></link>
    </model>
    <model name="block"><static>true</static><pose>3 0 0 0 0 1.5707963267948966</pose>
      <link name="body"><collision name="c"><geometry><mesh><uri>block.obj</uri><scale>2 1 0.5</scale></mesh></geometry></collision></link>
    </model>
    <model name="lost"><static>true</static><pose>-3 0 0 0 0 0</pose>
      <link name="body"><collision name="c"><geometry><mesh><uri>model://nowhere/mesh.stl</uri></mesh></geometry></collision></link>
    </model>
  </world>
</sdf>
)";

// A world file of the test's own in a scratch folder (removed however the test ends), beside the
// OBJ block its meshes name; and the cube robot built into it, out of the objects' way.
class SdfWorldFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_sdf_world_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "block.obj") << kCubeObj;
  }
  void TearDown() override { fs::remove_all(dir_); }
  World load(const char* sdf) {
    std::ofstream(dir_ / "test.world") << sdf;
    WorldConfig config;
    config.name = (dir_ / "test.world").string();
    return make_world(config);
  }
  static std::shared_ptr<const physics::PhysicsModel> build(const physics::WorldSpec& world) {
    physics::BuildOptions options;
    options.world = world;
    options.spawn.x = -6.0;  // out of the way
    auto model = physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
    for (const std::string& w : model->warnings()) ADD_FAILURE() << "warning: " << w;
    return model;
  }
  fs::path dir_;
};

TEST_F(SdfWorldFile, AStaticModelsMeshStandsWhereTheFileSaysAndHoldsObjectsUp) {
  World world = load(kMeshWorld);
  ASSERT_EQ(world.spec.boxes.size(), 1u);
  const physics::WorldBox& block = world.spec.boxes[0];
  EXPECT_EQ(block.shape, physics::WorldBox::Shape::Mesh);
  EXPECT_NEAR(block.size.x, 2.0, 1e-9);
  EXPECT_NEAR(block.size.y, 1.0, 1e-9);
  EXPECT_NEAR(block.size.z, 0.5, 1e-9);
  EXPECT_TRUE(block.fixed);
  EXPECT_NE(std::find(world.sdf_models.begin(), world.sdf_models.end(), "block"), world.sdf_models.end());
  EXPECT_EQ(std::find(world.sdf_models.begin(), world.sdf_models.end(), "lost"), world.sdf_models.end());
  EXPECT_TRUE(std::any_of(world.not_simulated.begin(), world.not_simulated.end(), [](const std::string& n) {
    return n.find("model 'lost'") != std::string::npos && n.find("model://nowhere/mesh.stl") != std::string::npos;
  })) << ::testing::PrintToString(world.not_simulated);

  // The block turned by 90 deg about z at (3, 0): it spans x 2..3 and y 0..2 (its corner at the
  // model's origin), 0.5 m high. A ball dropped on it rests on its top.
  physics::WorldBox ball;
  ball.name = "ball";
  ball.shape = physics::WorldBox::Shape::Sphere;
  ball.size = {0.2, 0.2, 0.2};
  ball.pose.position = {2.5, 1.0, 1.5};
  ball.fixed = false;
  world.spec.boxes.push_back(ball);
  const auto model = build(world.spec);
  physics::Physics p(model);
  EXPECT_NEAR(p.ground_height(2.2, 0.3), 0.5, 1e-6);
  EXPECT_NEAR(p.ground_height(2.9, 1.9), 0.5, 1e-6);
  EXPECT_NEAR(p.ground_height(3.1, 1.0), 0.0, 1e-6);  // beside it
  EXPECT_NEAR(p.ground_height(2.5, 2.1), 0.0, 1e-6);
  while (p.time() < 1.5) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.ground_height(2.5, 1.0), 0.7, 3e-3);  // the ball's top, resting on the block
}

constexpr const char* kMovingMeshWorld = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <world name="moving">
    <model name="ground"><static>true</static>
      <link name="l"><collision name="c"><geometry><plane><normal>0 0 1</normal><size>20 20</size></plane></geometry></collision></link>
    </model>
    <model name="crate"><pose>2 -1 0.6 0 0 0.3</pose>
      <link name="body"><inertial><mass>5</mass></inertial>
        <collision name="c"><geometry><mesh><uri>block.obj</uri><scale>1 0.8 0.4</scale></mesh></geometry></collision></link>
    </model>
    <model name="tipping"><pose>-2 1 0.8 0 1.2 0</pose>
      <link name="body"><collision name="c"><geometry><mesh><uri>block.obj</uri><scale>0.3 0.3 1</scale></mesh></geometry></collision></link>
    </model>
    <model name="two_shapes"><pose>0 4 1 0 0 0</pose>
      <link name="body">
        <collision name="a"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
        <collision name="b"><pose>0 0 0.3 0 0 0</pose><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
      </link>
    </model>
  </world>
</sdf>
)";

// Moving (non-static) one-link models of a mesh are free objects: a crate dropped 0.6 m lands flat
// at its height (0.4 m); a tall block (0.3 x 0.3 x 1 m) dropped tilted 69 deg falls over onto
// its long side (0.3 m high). A moving link of two shapes stays one body (a passive model).
TEST_F(SdfWorldFile, AMovingModelsMeshFallsAndRestsAtItsSize) {
  const World world = load(kMovingMeshWorld);
  ASSERT_EQ(world.spec.boxes.size(), 2u);
  for (const physics::WorldBox& b : world.spec.boxes) {
    EXPECT_EQ(b.shape, physics::WorldBox::Shape::Mesh) << b.name;
    EXPECT_FALSE(b.fixed) << b.name;
  }
  EXPECT_DOUBLE_EQ(world.spec.boxes[0].mass, 5.0);
  // The link of two shapes is one passive body, not two objects that would fall apart.
  ASSERT_EQ(world.spec.models.size(), 1u);
  EXPECT_EQ(world.spec.models[0].name, "two_shapes");

  const auto model = build(world.spec);
  physics::Physics p(model);
  EXPECT_NEAR(p.ground_height(2.4, -0.6), 1.0, 1e-6) << "the crate's top before it falls";
  while (p.time() < 3.0) ASSERT_TRUE(p.step().ok());
  // The crate (1 x 0.8 m footprint from its corner at (2, -1), turned 0.3 rad): its middle.
  const double cx = 2.0 + 0.5 * std::cos(0.3) - 0.4 * std::sin(0.3), cy = -1.0 + 0.5 * std::sin(0.3) + 0.4 * std::cos(0.3);
  EXPECT_NEAR(p.ground_height(cx, cy), 0.4, 5e-3);
  // The tall block lies on its side: nothing of it higher than 0.3 m (+ a little settling).
  double top = 0.0;
  for (double x = -3.5; x <= 0.0; x += 0.05)
    for (double y = 0.5; y <= 1.8; y += 0.05) top = std::max(top, p.ground_height(x, y));
  EXPECT_NEAR(top, 0.3, 5e-3) << "fell over onto a long side";
  // two_shapes (a 0.2 m box with a 0.1 m sphere 0.3 m above its centre) landed on the box with the
  // sphere still on top: its top 0.1 + 0.3 + 0.1 m up.
  EXPECT_NEAR(p.ground_height(0.0, 4.0), 0.5, 5e-3);
}

constexpr const char* kArticulatedWorld = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <world name="articulated">
    <model name="ground"><static>true</static>
      <link name="l"><collision name="c"><geometry><plane><normal>0 0 1</normal><size>20 20</size></plane></geometry></collision></link>
    </model>
    <model name="swing"><pose>1 0 1.2 0 0 0</pose>
      <joint name="hinge" type="revolute"><parent>world</parent><child>arm</child>
        <axis><xyz>0 1 0</xyz><dynamics><damping>0.8</damping></dynamics></axis></joint>
      <link name="arm"><pose>0 0 0 0 0.6 0</pose>
        <inertial><pose>0 0 -0.6 0 0 0</pose><mass>2</mass>
          <inertia><ixx>0.002</ixx><iyy>0.002</iyy><izz>0.002</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
        <collision name="bob"><pose>0 0 -0.6 0 0 0</pose><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
      </link>
    </model>
    <model name="dumbbell"><pose>-1 0 0.8 0.4 0 0</pose>
      <link name="a"><inertial><mass>1</mass><inertia><ixx>0.004</ixx><iyy>0.004</iyy><izz>0.004</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
        <collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link>
      <link name="b"><pose>0 0.5 0 0 0 0</pose><inertial><mass>1</mass><inertia><ixx>0.004</ixx><iyy>0.004</iyy><izz>0.004</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
        <collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link>
      <joint name="bar" type="fixed"><parent>a</parent><child>b</child></joint>
    </model>
  </world>
</sdf>
)";

// Moving models of several links are passive articulated objects: a pendulum hinged to the world
// and released 0.6 rad from the vertical swings down and, damped, comes to hang under its hinge;
// a dumbbell (two spheres on a fixed joint) dropped tilted lands level on both spheres.
TEST_F(SdfWorldFile, AnArticulatedModelMovesOnItsJoints) {
  const World world = load(kArticulatedWorld);
  ASSERT_EQ(world.spec.models.size(), 2u) << ::testing::PrintToString(world.not_simulated);
  EXPECT_EQ(world.spec.models[0].name, "swing");
  EXPECT_EQ(world.spec.models[1].name, "dumbbell");
  for (const char* m : {"swing", "dumbbell"})
    EXPECT_NE(std::find(world.sdf_models.begin(), world.sdf_models.end(), m), world.sdf_models.end()) << m;

  const auto model = build(world.spec);
  EXPECT_FALSE(model->joint_index("swing::hinge")) << "a passive joint is not the robot's";
  physics::Physics p(model);
  // The bob (radius 0.1) starts 0.6 m from the hinge (1, 0, 1.2) along the arm turned 0.6 rad
  // about y: at x = 1 - 0.6 sin 0.6, z = 1.2 - 0.6 cos 0.6; nothing is under the hinge yet.
  const double bob_x = 1.0 - 0.6 * std::sin(0.6), bob_z = 1.2 - 0.6 * std::cos(0.6);
  EXPECT_NEAR(p.ground_height(bob_x, 0.0), bob_z + 0.1, 1e-6);
  EXPECT_NEAR(p.ground_height(1.0, 0.0), 0.0, 1e-6);
  double lowest_swing = 1e9;  // where the bob passes under the hinge, its top is 0.6 m + its radius below
  while (p.time() < 8.0) {
    ASSERT_TRUE(p.step().ok());
    lowest_swing = std::min(lowest_swing, std::abs(p.ground_height(1.0, 0.0) - (1.2 - 0.6 + 0.1)));
  }
  EXPECT_LT(lowest_swing, 1e-3) << "it swung through the bottom";
  EXPECT_NEAR(p.ground_height(1.0, 0.0), 1.2 - 0.6 + 0.1, 2e-3) << "it hangs under its hinge";
  EXPECT_NEAR(p.ground_height(bob_x, 0.0), 0.0, 1e-6) << "no longer where it started";
  // The dumbbell: both spheres on the ground, level (tops at 0.2 m), the bar still 0.5 m long.
  double top_a = 0.0, top_b = 0.0;
  for (double y = -1.0; y <= 1.5; y += 0.01) {
    for (double x = -1.6; x <= -0.4; x += 0.01) {
      const double h = p.ground_height(x, y);
      (y < 0.25 ? top_a : top_b) = std::max(y < 0.25 ? top_a : top_b, h);
    }
  }
  EXPECT_NEAR(top_a, 0.2, 3e-3);
  EXPECT_NEAR(top_b, 0.2, 3e-3);
}

// The pose of an SDF model now (what /gazebo/model_states reports): X_WB X_BM for a moving one,
// the SDF's pose for a static one.
description::Pose model_pose(const World& world, const physics::Physics& p, const std::string& name) {
  for (const World::ModelFrame& f : world.sdf_model_frames) {
    if (f.name != name) continue;
    if (f.body.empty()) return f.pose;
    const int body = p.model().body_index(f.body);
    EXPECT_GE(body, 1) << name << ": no body '" << f.body << "'";
    return body >= 1 ? physics::compose(p.body_pose(body), f.X_BM) : f.pose;
  }
  ADD_FAILURE() << "no model frame '" << name << "'";
  return {};
}

void expect_pose_near(const description::Pose& a, const description::Pose& b, double tolerance, const std::string& what) {
  EXPECT_NEAR(a.position.x, b.position.x, tolerance) << what;
  EXPECT_NEAR(a.position.y, b.position.y, tolerance) << what;
  EXPECT_NEAR(a.position.z, b.position.z, tolerance) << what;
  // Same rotation: |<qa, qb>| = 1.
  const double dot = a.orientation.w * b.orientation.w + a.orientation.x * b.orientation.x +
                     a.orientation.y * b.orientation.y + a.orientation.z * b.orientation.z;
  EXPECT_NEAR(std::abs(dot), 1.0, tolerance) << what;
}

// Every simulated model of an SDF world has a frame, in sdf_models' order; a moving model's frame
// follows the body that carries it: where the SDF puts it at the start, where it came to rest
// after (the crate on the ground, still turned 0.3 rad; the dumbbell level on its spheres). A
// model hinged to the world (the swing) keeps its frame where the file puts it.
TEST_F(SdfWorldFile, ModelFramesFollowTheMovingModels) {
  for (const char* sdf : {kMovingMeshWorld, kArticulatedWorld}) {
    const World world = load(sdf);
    ASSERT_EQ(world.sdf_model_frames.size(), world.sdf_models.size());
    for (std::size_t i = 0; i < world.sdf_models.size(); ++i) EXPECT_EQ(world.sdf_model_frames[i].name, world.sdf_models[i]);
    const auto model = build(world.spec);
    physics::Physics p(model);
    for (const World::ModelFrame& f : world.sdf_model_frames) {
      expect_pose_near(model_pose(world, p, f.name), f.pose, 1e-9, f.name + " at the start");
    }
    while (p.time() < 3.0) ASSERT_TRUE(p.step().ok());
    if (sdf == kMovingMeshWorld) {
      EXPECT_TRUE(world.sdf_model_frames[0].body.empty()) << "the ground is static";
      description::Pose rest;
      rest.position = {2.0, -1.0, 0.0};  // the block's corner (the model's origin) on the ground
      rest.orientation = physics::quat_from_rpy(0.0, 0.0, 0.3);
      expect_pose_near(model_pose(world, p, "crate"), rest, 5e-3, "crate at rest");
    } else {
      const description::Pose swing = model_pose(world, p, "swing");
      expect_pose_near(swing, world.sdf_model_frames[1].pose, 1e-12, "swing (hinged to the world)");
      const description::Pose dumbbell = model_pose(world, p, "dumbbell");
      EXPECT_NEAR(dumbbell.position.z, 0.1, 3e-3) << "sphere a's centre, on the ground";
      // Level: the bar (the model's y axis) horizontal.
      const description::Vec3 bar = physics::rotate(dumbbell.orientation, {0.0, 1.0, 0.0});
      EXPECT_NEAR(bar.z, 0.0, 1e-2);
    }
  }
}

// A robot fixed to the world beside a free object: the robot's root state and base pose are its
// own (it has no free joint; the object's is not the robot's), and setting the base moves nothing.
TEST(SdfWorldObjects, AFixedRobotsRootIsNotAFreeObjectsJoint) {
  physics::BuildOptions options;
  physics::WorldBox crate;
  crate.name = "crate";
  crate.size = {0.2, 0.2, 0.2};
  crate.pose.position = {1.0, 0.0, 0.1};
  crate.fixed = false;
  crate.mass = 1.0;
  options.world.boxes = {crate};
  const auto model = physics::PhysicsModel::build(
      description::parse_urdf_string(R"(<robot name="post"><link name="world"/>
        <joint name="fix" type="fixed"><parent link="world"/><child link="base"/><origin xyz="-1 0 0.5"/></joint>
        <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
        <collision><geometry><box size="0.1 0.1 1"/></geometry></collision></link></robot>)",
                                     "post.urdf", {}),
      options);
  physics::Physics p(model);
  description::Pose X;
  physics::Twist V;
  EXPECT_FALSE(p.root_state(X, V)) << "a fixed robot has no floating root";
  description::Pose moved;
  moved.position = {5.0, 5.0, 5.0};
  p.set_base_pose(moved);
  const int body = model->body_index("box:crate");
  ASSERT_GE(body, 1);
  EXPECT_NEAR(p.body_pose(body).position.x, 1.0, 1e-12) << "the crate stays";
  // The crate itself can be moved.
  EXPECT_TRUE(p.set_free_body_state(body, moved, {}));
  EXPECT_NEAR(p.body_pose(body).position.z, 5.0, 1e-12);
  EXPECT_FALSE(p.set_free_body_state(0, moved, {})) << "the world body";
}

TEST(SdfWorldObjects, ARoundObjectOfUnequalWidthsIsABuildErrorNamingIt) {
  physics::BuildOptions options;
  physics::WorldBox egg;
  egg.name = "egg";
  egg.shape = physics::WorldBox::Shape::Sphere;
  egg.size = {0.2, 0.3, 0.2};
  options.world.boxes = {egg};
  try {
    physics::PhysicsModel::build(description::parse_urdf_string(kCube, "cube.urdf", {}), options);
    FAIL() << "built";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("world box 'egg': a cylinder's or sphere's size must be equal"));
  }
}

}  // namespace
}  // namespace mechsim::sim
