// The replay a report keeps for `mechsim view` (sim/replay_recorder.hpp): frames at replay_rate
// and at the last tick, each link's world pose as the physics had it (checked against the
// joint angles of joints.csv at the same instants), the robot's visuals and the world beside
// them, a manifest with the format version; replay_rate 0 records nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "sim/replay_recorder.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

// A base on the ground and an arm on a hinge about y driven to 0.8 rad; visuals of each kind of
// primitive, one coloured by <material>, one by Gazebo's material.
constexpr const char* kArm = R"(<robot name="arm">
  <link name="base">
    <inertial><mass value="5"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><box size="0.4 0.4 0.1"/></geometry><material name="red"><color rgba="1 0 0 1"/></material></visual>
    <collision><geometry><box size="0.4 0.4 0.1"/></geometry></collision>
  </link>
  <gazebo reference="arm"><material>Gazebo/Blue</material></gazebo>
  <joint name="hinge" type="revolute">
    <parent link="base"/><child link="arm"/><origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="50" velocity="5"/>
  </joint>
  <link name="arm">
    <inertial><origin xyz="0 0 0.25"/><mass value="0.5"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><origin xyz="0 0 0.25"/><geometry><cylinder radius="0.03" length="0.5"/></geometry></visual>
    <visual><origin xyz="0 0 0.5"/><geometry><sphere radius="0.05"/></geometry></visual>
  </link>
  <transmission name="t"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="m"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
</robot>)";

constexpr const char* kControllers = R"(c:
  hinge_controller:
    type: effort_controllers/JointPositionController
    joint: hinge
    pid: {p: 200.0, d: 5.0, i: 0.0}
)";

struct Q {
  double w, x, y, z;
};
Q mul(const Q& a, const Q& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
Q conj(const Q& q) { return {q.w, -q.x, -q.y, -q.z}; }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

// poses.bin of a replay folder whose manifest says `frames` frames of `stride` floats.
std::vector<float> read_poses(const fs::path& replay, std::size_t frames, std::size_t stride) {
  std::vector<float> poses(frames * stride);
  std::ifstream(replay / "poses.bin", std::ios::binary).read(reinterpret_cast<char*>(poses.data()),
                                                             static_cast<std::streamsize>(poses.size() * sizeof(float)));
  return poses;
}

class ReplayRecorderTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_replay_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "arm.urdf") << kArm;
    std::ofstream(dir_ / "controllers.yaml") << kControllers;
  }
  void TearDown() override { fs::remove_all(dir_); }
  ScenarioResult run(const std::string& extra) {
    std::ofstream(dir_ / "s.yaml") << "name: arm_replay\nrobot: {description: arm.urdf}\n"
                                   << "controllers: {file: controllers.yaml, namespace: c, start: [hinge_controller]}\n"
                                   << "spawn: {z: 0.05}\nduration: 1.0\nrecord_rate: 20\n" << extra
                                   << "timeline:\n  - {at: 0.1, controller: hinge_controller, command: 0.8}\n";
    RunOptions options;
    options.output_dir = (dir_ / "out").string();
    options.plots = false;
    return run_scenario(load_scenario((dir_ / "s.yaml").string()), options);
  }
  fs::path dir_;
};

TEST_F(ReplayRecorderTest, FramesHoldEachLinksWorldPoseAtTheirTime) {
  const ScenarioResult r = run("replay_rate: 20\n");
  ASSERT_TRUE(r.completed) << r.error;
  const fs::path replay = dir_ / "out" / "replay";
  const nlohmann::json manifest = read_json(replay / "manifest.json");
  EXPECT_EQ(manifest["format"], kReplayFormatName);
  EXPECT_EQ(manifest["version"], kReplayFormatVersion);
  EXPECT_EQ(manifest["links"], (nlohmann::json{"base", "arm"}));
  const std::size_t stride = manifest["poses"]["stride"];
  ASSERT_EQ(stride, 1u + 7u * 2u);
  // Ticks 0, 50, ..., 950 and the last one (999).
  ASSERT_EQ(manifest["frames"], 21u);
  ASSERT_EQ(fs::file_size(replay / "poses.bin"), 21u * stride * sizeof(float));
  std::vector<float> poses(21 * stride);
  std::ifstream(replay / "poses.bin", std::ios::binary).read(reinterpret_cast<char*>(poses.data()), static_cast<std::streamsize>(poses.size() * sizeof(float)));
  for (std::size_t k = 0; k < 20; ++k) EXPECT_NEAR(poses[k * stride], 0.05 * static_cast<double>(k), 1e-6);
  EXPECT_NEAR(poses[20 * stride], 0.999, 1e-6);

  // joints.csv at the same instants (record_rate 20).
  std::ifstream joints(dir_ / "out" / "joints.csv");
  std::string line;
  std::getline(joints, line);
  std::size_t row = 0;
  double moved = 0.0;
  while (std::getline(joints, line) && row < 21) {
    std::stringstream cells(line);
    std::string t, q;
    std::getline(cells, t, ',');
    std::getline(cells, q, ',');
    const float* f = &poses[row * stride];
    ASSERT_NEAR(f[0], std::stod(t), 1e-6) << "row " << row;
    const float* base = f + 1;
    const float* arm = f + 8;
    // The arm's pose in the base's frame (the base rocks on the ground as the arm swings): a
    // rotation about y by the hinge angle, its origin 0.3 m up the base's z.
    const Q qb{base[3], base[4], base[5], base[6]}, qa{arm[3], arm[4], arm[5], arm[6]};
    const Q rel = mul(conj(qb), qa);
    const double pitch = 2.0 * std::atan2(rel.y, rel.w);
    EXPECT_NEAR(pitch, std::stod(q), 2e-3) << "t = " << t;
    EXPECT_NEAR(std::hypot(rel.x, rel.z), 0.0, 1e-3) << "t = " << t;
    const Q d{0.0, arm[0] - base[0], arm[1] - base[1], arm[2] - base[2]};
    const Q local = mul(mul(conj(qb), d), qb);
    EXPECT_NEAR(local.x, 0.0, 1e-3) << "t = " << t;
    EXPECT_NEAR(local.y, 0.0, 1e-3) << "t = " << t;
    EXPECT_NEAR(local.z, 0.3, 1e-3) << "t = " << t;
    moved = std::max(moved, std::abs(pitch));
    ++row;
  }
  EXPECT_EQ(row, 21u);
  EXPECT_GT(moved, 0.6) << "rad: the arm swung towards 0.8 rad";

  const nlohmann::json robot = read_json(replay / "robot.json");
  ASSERT_EQ(robot["links"].size(), 2u);
  EXPECT_EQ(robot["links"][0]["visuals"][0]["type"], "box");
  EXPECT_EQ(robot["links"][0]["visuals"][0]["rgba"], (nlohmann::json{1.0, 0.0, 0.0, 1.0}));
  EXPECT_EQ(robot["links"][1]["visuals"][0]["type"], "cylinder");
  EXPECT_EQ(robot["links"][1]["visuals"][1]["type"], "sphere");
  EXPECT_DOUBLE_EQ(robot["links"][1]["visuals"][0]["rgba"][2].get<double>(), 0.85) << "Gazebo/Blue";
  const nlohmann::json world = read_json(replay / "world.json");
  EXPECT_TRUE(world["ground_plane"].get<bool>());
  EXPECT_FALSE(world.contains("heightfield"));
  std::ifstream urdf(replay / "robot.urdf");
  std::stringstream urdf_text;
  urdf_text << urdf.rdbuf();
  EXPECT_NE(urdf_text.str().find("<joint name=\"hinge\""), std::string::npos);
}

// A binary STL tetrahedron (4 facets) as a mesh file.
std::string tetrahedron_stl() {
  std::string bytes(80, '\0');
  const std::uint32_t n = 4;
  bytes.append(reinterpret_cast<const char*>(&n), 4);
  const float v[4][3] = {{0, 0, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}, {0, 0, 0.1f}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    const float normal[3] = {0, 0, 0};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    for (int k : f) bytes.append(reinterpret_cast<const char*>(v[k]), 12);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST_F(ReplayRecorderTest, MeshesAreCopiedBesideTheRobot) {
  fs::create_directories(dir_ / "pkg" / "meshes");
  const std::string stl = tetrahedron_stl();
  std::ofstream(dir_ / "pkg" / "meshes" / "tet.stl", std::ios::binary) << stl;
  std::ofstream(dir_ / "mesh.urdf") << R"(<robot name="m"><link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><mesh filename="package://pkg/meshes/tet.stl" scale="2 2 2"/></geometry></visual>
    <visual><geometry><mesh filename="package://pkg/meshes/missing.stl"/></geometry></visual>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link></robot>)";
  std::ofstream(dir_ / "m.yaml") << "robot: {description: mesh.urdf, packages: {pkg: pkg}, lenient: true}\nspawn: {z: 0.1}\nduration: 0.1\n";
  RunOptions options;
  options.output_dir = (dir_ / "out").string();
  options.plots = false;
  const ScenarioResult r = run_scenario(load_scenario((dir_ / "m.yaml").string()), options);
  ASSERT_TRUE(r.completed) << r.error;
  const nlohmann::json robot = read_json(dir_ / "out" / "replay" / "robot.json");
  ASSERT_EQ(robot["links"][0]["visuals"].size(), 1u) << robot.dump();
  const nlohmann::json& mesh = robot["links"][0]["visuals"][0];
  EXPECT_EQ(mesh["type"], "mesh");
  EXPECT_EQ(mesh["scale"], (nlohmann::json{2.0, 2.0, 2.0}));
  std::ifstream copied(dir_ / "out" / "replay" / mesh["file"].get<std::string>(), std::ios::binary);
  std::stringstream bytes;
  bytes << copied.rdbuf();
  EXPECT_EQ(bytes.str(), stl) << "a binary STL is kept as it is";
  ASSERT_EQ(robot["warnings"].size(), 1u);
  EXPECT_NE(robot["warnings"][0].get<std::string>().find("missing.stl"), std::string::npos) << robot["warnings"][0];
}

// A static SDF model's mesh is a world object of the replay: its file beside the robot's meshes,
// its scale and pose, drawn by the page like a robot mesh.
TEST_F(ReplayRecorderTest, AStaticSdfModelsMeshIsCopiedForTheWorld) {
  const std::string stl = tetrahedron_stl();
  std::ofstream(dir_ / "rock.stl", std::ios::binary) << stl;
  std::ofstream(dir_ / "rocks.world") << R"(<?xml version="1.0"?><sdf version="1.6"><world name="w">
    <model name="ground"><static>true</static><link name="l"><collision name="c"><geometry><plane><normal>0 0 1</normal>
      <size>20 20</size></plane></geometry></collision></link></model>
    <model name="rock"><static>true</static><pose>2 1 0 0 0 0</pose><link name="l"><collision name="c"><geometry>
      <mesh><uri>rock.stl</uri><scale>3 3 3</scale></mesh></geometry></collision></link></model>
  </world></sdf>)";
  const ScenarioResult r = run("world: {name: rocks.world}\n");
  ASSERT_TRUE(r.completed) << r.error;
  const nlohmann::json world = read_json(dir_ / "out" / "replay" / "world.json");
  ASSERT_EQ(world["boxes"].size(), 1u) << world.dump();
  const nlohmann::json& rock = world["boxes"][0];
  EXPECT_EQ(rock["shape"], "mesh");
  EXPECT_EQ(rock["scale"], (nlohmann::json{3.0, 3.0, 3.0}));
  EXPECT_EQ(rock["pose"]["p"], (nlohmann::json{2.0, 1.0, 0.0}));
  std::ifstream copied(dir_ / "out" / "replay" / rock["file"].get<std::string>(), std::ios::binary);
  std::stringstream bytes;
  bytes << copied.rdbuf();
  EXPECT_EQ(bytes.str(), stl);
}

// A free object of the world (a scenario box that is not fixed) moves in the replay: its pose
// follows the links' in every frame, where it starts in world.json at first, falling, then at
// rest on the ground (0.1 m up: half its 0.2 m edge).
TEST_F(ReplayRecorderTest, FreeObjectsMoveInTheFrames) {
  const ScenarioResult r = run("world: {boxes: [{name: crate, size: [0.2, 0.2, 0.2], x: 2, z: 1.5, fixed: false, mass: 1},"
                               " {name: wall, size: [0.2, 2, 1], x: -2, z: 0.5}]}\n");
  ASSERT_TRUE(r.completed) << r.error;
  const fs::path replay = dir_ / "out" / "replay";
  const nlohmann::json manifest = read_json(replay / "manifest.json");
  ASSERT_EQ(manifest["objects"], (nlohmann::json{"crate"})) << "the fixed wall is not an object";
  const std::size_t stride = manifest["poses"]["stride"];
  ASSERT_EQ(stride, 1u + 7u * (2u + 1u));
  const std::size_t frames = manifest["frames"];
  const std::vector<float> poses = read_poses(replay, frames, stride);
  const auto crate_z = [&](std::size_t k) { return poses[k * stride + 1 + 7 * 2 + 2]; };
  const auto crate_x = [&](std::size_t k) { return poses[k * stride + 1 + 7 * 2]; };
  EXPECT_NEAR(crate_z(0), 1.5 - 0.5 * 9.81 * poses[0] * poses[0], 1e-3) << "falling from where it starts";
  EXPECT_NEAR(crate_x(0), 2.0, 1e-6);
  EXPECT_NEAR(crate_z(frames - 1), 0.1, 2e-3) << "at rest on the ground";
  EXPECT_NEAR(crate_x(frames - 1), 2.0, 1e-3);
}

// Another robot of the scenario (others:) is drawn as the first is: its links, under its prefix,
// in robot.json with their visuals and in the frames, where the physics has them (2 m to the side).
TEST_F(ReplayRecorderTest, OtherRobotsAreDrawnAndMoveInTheFrames) {
  const ScenarioResult r = run("others:\n  - {name: arm2, spawn: {y: 2, z: 0.05}}\n");
  ASSERT_TRUE(r.completed) << r.error;
  const fs::path replay = dir_ / "out" / "replay";
  const nlohmann::json manifest = read_json(replay / "manifest.json");
  ASSERT_EQ(manifest["links"], (nlohmann::json{"base", "arm", "arm2::base", "arm2::arm"}));
  const nlohmann::json robot = read_json(replay / "robot.json");
  ASSERT_EQ(robot["links"].size(), 4u);
  EXPECT_EQ(robot["links"][2]["name"], "arm2::base");
  EXPECT_EQ(robot["links"][3]["name"], "arm2::arm");
  EXPECT_EQ(robot["links"][3]["visuals"], robot["links"][1]["visuals"]) << "the same arm, drawn the same";
  const std::size_t stride = manifest["poses"]["stride"];
  ASSERT_EQ(stride, 1u + 7u * 4u);
  const std::size_t frames = manifest["frames"];
  const std::vector<float> poses = read_poses(replay, frames, stride);
  const float* last = &poses[(frames - 1) * stride];
  EXPECT_NEAR(last[1 + 7 * 2 + 1] - last[1 + 1], 2.0, 1e-3) << "the second base, 2 m along y from the first";
  EXPECT_NEAR(last[1 + 7 * 3 + 2], last[1 + 7 * 1 + 2], 1e-3) << "its arm at the first arm's height";
}

// A passive model of an SDF world (a box and an upright cylinder 0.5 m apart on a fixed joint, a
// body each, welded) is drawn from world.json's bodies and moved by the frames: each body starts
// where the file puts it and lands (both 0.2 m tall: their centres 0.1 m up).
TEST_F(ReplayRecorderTest, PassiveModelsBodiesAreDrawnAndMoveInTheFrames) {
  std::ofstream(dir_ / "pair.world") << R"(<?xml version="1.0"?><sdf version="1.6"><world name="w">
    <model name="ground"><static>true</static><link name="l"><collision name="c"><geometry><plane><normal>0 0 1</normal>
      <size>20 20</size></plane></geometry></collision></link></model>
    <model name="pair"><pose>2 0 0.8 0 0 0</pose>
      <link name="a"><inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link>
      <link name="b"><pose>0 0.5 0 0 0 0</pose><inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
        <collision name="c"><geometry><cylinder><radius>0.1</radius><length>0.2</length></cylinder></geometry></collision></link>
      <joint name="weld" type="fixed"><parent>a</parent><child>b</child></joint>
    </model>
  </world></sdf>)";
  const ScenarioResult r = run("world: {name: pair.world}\n");
  ASSERT_TRUE(r.completed) << r.error;
  const fs::path replay = dir_ / "out" / "replay";
  const nlohmann::json world = read_json(replay / "world.json");
  ASSERT_EQ(world["bodies"].size(), 2u) << world.dump();
  EXPECT_EQ(world["bodies"][0]["name"], "pair::a");
  EXPECT_EQ(world["bodies"][1]["name"], "pair::b");
  ASSERT_EQ(world["bodies"][0]["shapes"].size(), 1u);
  ASSERT_EQ(world["bodies"][1]["shapes"].size(), 1u);
  EXPECT_EQ(world["bodies"][0]["shapes"][0]["shape"], "box");
  EXPECT_EQ(world["bodies"][0]["shapes"][0]["size"], (nlohmann::json{0.2, 0.2, 0.2}));
  EXPECT_EQ(world["bodies"][1]["shapes"][0]["shape"], "cylinder");
  EXPECT_EQ(world["bodies"][1]["shapes"][0]["size"], (nlohmann::json{0.2, 0.2, 0.2}));
  const nlohmann::json manifest = read_json(replay / "manifest.json");
  ASSERT_EQ(manifest["objects"], (nlohmann::json{"pair::a", "pair::b"}));
  const std::size_t stride = manifest["poses"]["stride"];
  ASSERT_EQ(stride, 1u + 7u * (2u + 2u));
  const std::size_t frames = manifest["frames"];
  const std::vector<float> poses = read_poses(replay, frames, stride);
  for (std::size_t i = 0; i < 2; ++i) {
    const float* first = &poses[1 + 7 * (2 + i)];
    const float* last = &poses[(frames - 1) * stride + 1 + 7 * (2 + i)];
    EXPECT_NEAR(first[0], 2.0, 1e-6);
    EXPECT_NEAR(first[1], 0.5 * static_cast<double>(i), 1e-6);
    EXPECT_NEAR(first[2], 0.8 - 0.5 * 9.81 * poses[0] * poses[0], 1e-3);
    EXPECT_NEAR(last[2], 0.1, 3e-3) << "landed";
  }
}

TEST_F(ReplayRecorderTest, RateZeroRecordsNoReplay) {
  const ScenarioResult r = run("replay_rate: 0\n");
  ASSERT_TRUE(r.completed) << r.error;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "replay"));
}

TEST_F(ReplayRecorderTest, NegativeRateIsABadScenario) {
  try {
    run("replay_rate: -1\n");
    FAIL() << "expected ScenarioError";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("replay_rate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mechsim::sim
