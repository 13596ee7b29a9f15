// Scenario files: what is read, and bad input named by file and parameter path.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "sim/scenario.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

// The test's name as one folder name: a parameterized test is "Name/3", which made a folder
// "Name" holding "3", and only "3" was removed.
std::string test_folder_name() {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

class ScenarioFile : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_scenario_" + std::to_string(::getpid()) +
                                        "_" + test_folder_name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "robot.urdf") << "<robot name='r'><link name='a'/></robot>\n";
    std::ofstream(dir_ / "controllers.yaml") << "r:\n  c: {type: joint_state_controller/JointStateController, publish_rate: 50}\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& body) {
    const fs::path file = dir_ / "s.yaml";
    std::ofstream(file) << "robot: {description: robot.urdf}\ncontrollers: {file: controllers.yaml, namespace: r, start: [c]}\n" << body;
    return file.string();
  }
  fs::path dir_;
};

TEST_F(ScenarioFile, ReadsEverythingWithPathsRelativeToTheFile) {
  const Scenario s = load_scenario(write(R"(name: demo
duration: 12.5
period: 0.002
spawn: {x: 1, y: -2, z: 0.1, yaw: 1.5}
world: {name: mars_yard_2024, seed: 7}
timeline:
  - {at: 2.0, controller: c, twist: {vx: 0.5, wz: 0.1}}
  - {at: 1.0, controller: c, command: 0.3}
  - {at: 3.0, controller: c, route: {waypoints: [[1, 2], [3, 4]], speed: 0.7}}
checks:
  - {reach: {x: 1, y: 2, within: 0.5, by: 10}}
  - {final_heading: {yaw_deg: 90, within_deg: 5}}
  - {direction: {deg: 45, within_deg: 3}}
)"));
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.description, (dir_ / "robot.urdf").lexically_normal().string());
  EXPECT_EQ(s.controllers_file, (dir_ / "controllers.yaml").lexically_normal().string());
  EXPECT_EQ(s.controllers_namespace, "r");
  EXPECT_DOUBLE_EQ(s.duration, 12.5);
  EXPECT_DOUBLE_EQ(s.period, 0.002);
  EXPECT_DOUBLE_EQ(s.spawn.y, -2.0);
  EXPECT_DOUBLE_EQ(s.spawn.yaw, 1.5);
  EXPECT_EQ(s.world.name, "mars_yard_2024");
  EXPECT_EQ(s.world.seed, 7u);
  ASSERT_EQ(s.timeline.size(), 3u);
  EXPECT_EQ(s.timeline[0].kind, TimelineEvent::Kind::Scalar);  // sorted by time
  EXPECT_EQ(s.timeline[1].kind, TimelineEvent::Kind::Twist);
  EXPECT_DOUBLE_EQ(s.timeline[1].twist.linear.x, 0.5);
  EXPECT_DOUBLE_EQ(s.timeline[1].twist.angular.z, 0.1);
  EXPECT_EQ(s.timeline[2].kind, TimelineEvent::Kind::Route);
  ASSERT_EQ(s.timeline[2].route.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(s.timeline[2].route.waypoints[1][0], 3.0);
  EXPECT_DOUBLE_EQ(s.timeline[2].route.speed, 0.7);
  ASSERT_EQ(s.checks.size(), 3u);
  EXPECT_EQ(s.checks[0].kind, Check::Kind::Reach);
  EXPECT_NEAR(s.checks[1].yaw, M_PI / 2, 1e-12);
  EXPECT_EQ(s.checks[2].kind, Check::Kind::Direction);
  EXPECT_EQ(s.integrator, physics::BuildOptions{}.integrator);  // the project default when absent
}

// Objects of any mesh a user has: its file relative to the scenario, its scale, its bounds read.
TEST_F(ScenarioFile, ReadsMeshObjects) {
  std::ofstream(dir_ / "wedge.obj") << "v 0 0 0\nv 2 0 0\nv 0 1 0\nv 0 0 0.5\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const Scenario s = load_scenario(write(
      "duration: 1\nworld:\n  boxes:\n    - {name: w, shape: mesh, mesh: wedge.obj, scale: [1, 2, 3], x: 1, fixed: false, mass: 4}\n"));
  ASSERT_EQ(s.boxes.size(), 1u);
  const physics::WorldBox& w = s.boxes[0];
  EXPECT_EQ(w.shape, physics::WorldBox::Shape::Mesh);
  EXPECT_EQ(w.mesh_path, (dir_ / "wedge.obj").lexically_normal().string());
  EXPECT_DOUBLE_EQ(w.size.x, 2.0);
  EXPECT_DOUBLE_EQ(w.size.y, 2.0);
  EXPECT_DOUBLE_EQ(w.size.z, 1.5);
  EXPECT_DOUBLE_EQ(w.mesh_scale.z, 3.0);
  EXPECT_FALSE(w.fixed);
  EXPECT_DOUBLE_EQ(w.mass, 4.0);
}

// Multi-pass is the soil model's switch: the named set keeps its name, and it is off by default.
TEST_F(ScenarioFile, ReadsTheSoilsMultiPassSwitch) {
  const Scenario on = load_scenario(write("duration: 1\nworld: {name: slope, soil: {base: dry_sand, multi_pass: true}}\n"));
  ASSERT_TRUE(on.world.soil);
  EXPECT_TRUE(on.world.soil->multi_pass);
  EXPECT_EQ(on.world.soil->name, "dry_sand");
  const Scenario off = load_scenario(write("duration: 1\nworld: {name: slope, soil: dry_sand}\n"));
  ASSERT_TRUE(off.world.soil);
  EXPECT_FALSE(off.world.soil->multi_pass);
}

TEST_F(ScenarioFile, ReadsTheIntegrator) {
  EXPECT_EQ(load_scenario(write("duration: 1\nintegrator: euler\n")).integrator, physics::Integrator::Euler);
  EXPECT_EQ(load_scenario(write("duration: 1\nintegrator: rk4\n")).integrator, physics::Integrator::Rk4);
  EXPECT_EQ(load_scenario(write("duration: 1\nintegrator: implicit\n")).integrator, physics::Integrator::Implicit);
}

TEST_F(ScenarioFile, ReadsTrajectoryAndGripperEventsBoxesInitialJointsAndTheirChecks) {
  const Scenario s = load_scenario(write(R"(duration: 5
world:
  name: empty
  boxes:
    - {name: a, size: [0.1, 0.2, 0.3], x: 1, y: 2, z: 0.5, yaw: 1.5707963267948966, fixed: false, mass: 2}
    - {name: b, size: [1, 1, 1], quat: [2, 0, 0, 0]}
spawn: {z: 0.01, joints: {j1: 0.25, j2: -0.5}}
timeline:
  - at: 0.5
    controller: arm
    trajectory:
      joints: [j1, j2]
      points:
        - {time: 1.0, positions: [0.1, 0.2], velocities: [0, 0]}
        - {time: 2.0, positions: [0.3, 0.4], velocities: [0, 0], accelerations: [0, 0]}
      goal_time_tolerance: 0.6
      goal_tolerance: {all: {position: 0.02, velocity: 0.5}}
      path_tolerance: {j2: {position: 0.1}}
  - {at: 0.0, controller: grip, gripper: {position: 0.08, max_effort: 50}}
  - {at: 0.1, controller: grip, gripper: {position: 0.0}}
checks:
  - {trajectory: {controller: arm, goal: 1, max_rms_error: 0.01, max_error: 0.05, result: GOAL_TOLERANCE_VIOLATED}}
  - {gripper: {controller: grip, reached: true, by: 1.0}}
  - {gripper: {controller: grip, goal: 2, stalled: true, position: 0.04, within: 0.006}}
  - {joint: {name: j1, at: 2.5, position: 0.3, within: 0.01}}
  - {odometry: {max_yaw_error_fraction: 0.03}}
)"));
  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_EQ(s.boxes[0].name, "a");
  EXPECT_DOUBLE_EQ(s.boxes[0].size.y, 0.2);
  EXPECT_DOUBLE_EQ(s.boxes[0].pose.position.z, 0.5);
  EXPECT_NEAR(s.boxes[0].pose.orientation.w, std::sqrt(0.5), 1e-12);  // 90 deg about z
  EXPECT_NEAR(s.boxes[0].pose.orientation.z, std::sqrt(0.5), 1e-12);
  EXPECT_FALSE(s.boxes[0].fixed);
  EXPECT_DOUBLE_EQ(s.boxes[0].mass, 2.0);
  EXPECT_TRUE(s.boxes[1].fixed);
  EXPECT_DOUBLE_EQ(s.boxes[1].pose.orientation.w, 1.0);  // normalised
  const Scenario round = load_scenario(write("duration: 1\nworld: {boxes: [{name: drum, shape: cylinder, radius: 0.2, length: 0.6},"
                                             " {name: ball, shape: sphere, radius: 0.1}]}\n"));
  ASSERT_EQ(round.boxes.size(), 2u);
  EXPECT_EQ(round.boxes[0].shape, physics::WorldBox::Shape::Cylinder);
  EXPECT_DOUBLE_EQ(round.boxes[0].size.x, 0.4);
  EXPECT_DOUBLE_EQ(round.boxes[0].size.z, 0.6);
  EXPECT_EQ(round.boxes[1].shape, physics::WorldBox::Shape::Sphere);
  EXPECT_DOUBLE_EQ(round.boxes[1].size.y, 0.2);
  EXPECT_DOUBLE_EQ(s.initial_joints.at("j2"), -0.5);
  ASSERT_EQ(s.timeline.size(), 3u);
  EXPECT_EQ(s.timeline[0].kind, TimelineEvent::Kind::Gripper);  // sorted by time
  EXPECT_DOUBLE_EQ(s.timeline[0].gripper.max_effort, 50.0);
  EXPECT_DOUBLE_EQ(s.timeline[1].gripper.max_effort, -1.0);  // no limit when absent
  const TimelineEvent& t = s.timeline[2];
  EXPECT_EQ(t.kind, TimelineEvent::Kind::Trajectory);
  EXPECT_NE(t.location.find("s.yaml:"), std::string::npos) << t.location;
  ASSERT_EQ(t.trajectory.trajectory.points.size(), 2u);
  EXPECT_DOUBLE_EQ(t.trajectory.trajectory.points[1].time_from_start, 2.0);
  EXPECT_DOUBLE_EQ(t.trajectory.trajectory.points[1].positions[1], 0.4);
  EXPECT_EQ(t.trajectory.trajectory.points[0].accelerations.size(), 0u);
  EXPECT_EQ(t.trajectory.trajectory.points[1].accelerations.size(), 2u);
  EXPECT_DOUBLE_EQ(t.trajectory.goal_time_tolerance, 0.6);
  ASSERT_EQ(t.trajectory.goal_tolerance.size(), 1u);
  EXPECT_EQ(t.trajectory.goal_tolerance[0].name, "all");
  EXPECT_DOUBLE_EQ(t.trajectory.goal_tolerance[0].velocity, 0.5);
  ASSERT_EQ(t.trajectory.path_tolerance.size(), 1u);
  EXPECT_EQ(t.trajectory.path_tolerance[0].name, "j2");
  ASSERT_EQ(s.checks.size(), 5u);
  EXPECT_EQ(s.checks[0].kind, Check::Kind::Trajectory);
  EXPECT_EQ(s.checks[0].goal, 1u);
  EXPECT_EQ(s.checks[0].result, control::TrajectoryResultCode::GoalToleranceViolated);
  EXPECT_DOUBLE_EQ(*s.checks[0].max_abs_error, 0.05);
  EXPECT_EQ(s.checks[1].kind, Check::Kind::Gripper);
  EXPECT_EQ(s.checks[1].goal, 0u);  // the last
  EXPECT_TRUE(*s.checks[1].reached);
  EXPECT_FALSE(s.checks[1].stalled.has_value());
  EXPECT_DOUBLE_EQ(*s.checks[2].position, 0.04);
  EXPECT_EQ(s.checks[3].kind, Check::Kind::Joint);
  EXPECT_DOUBLE_EQ(*s.checks[3].at, 2.5);
  EXPECT_FALSE(s.checks[4].max_error_fraction.has_value());
  EXPECT_DOUBLE_EQ(*s.checks[4].max_yaw_error_fraction, 0.03);
}

struct BadCase {
  const char* name;
  const char* body;
  const char* expected;  // substring of the message
};

class ScenarioBadInput : public ScenarioFile, public testing::WithParamInterface<BadCase> {};

TEST_P(ScenarioBadInput, IsAClearError) {
  const BadCase& c = GetParam();
  try {
    load_scenario(write(c.body));
    FAIL() << "accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ScenarioBadInput,
    testing::Values(BadCase{"missing_duration", "name: x\n", "/duration"},
                    BadCase{"negative_duration", "duration: -1\n", "/duration"},
                    BadCase{"bad_period", "duration: 1\nperiod: 0\n", "/period"},
                    BadCase{"other_unnamed", "duration: 1\nothers:\n  - {name: ''}\n", "/others[0]/name: a robot's name is its namespace"},
                    BadCase{"other_scoped", "duration: 1\nothers:\n  - {name: 'a::b'}\n", "without '::' or '/'"},
                    BadCase{"other_twice", "duration: 1\nothers:\n  - {name: r}\n  - {name: r}\n", "/others[1]/name: robot 'r' is named twice"},
                    BadCase{"other_typo", "duration: 1\nothers:\n  - {name: r, spawn: {x: 1, yaww: 2}}\n", "unknown key 'yaww'"},
                    BadCase{"event_unknown_robot", "duration: 1\nothers:\n  - {name: r}\ntimeline:\n  - {at: 0, robot: q, controller: c, command: 1}\n",
                            "timeline: robot 'q' is none of the scenario's others"},
                    BadCase{"goal_to_other", "duration: 1\nothers:\n  - {name: r}\ntimeline:\n  - {at: 0, robot: r, controller: c, gripper: {position: 0.01}}\n",
                            "trajectory and gripper goals go to the first robot only"},
                    BadCase{"check_unknown_robot", "duration: 1\nchecks:\n  - {distance: {robot: q, min: 1}}\n",
                            "/checks[0]: robot 'q' is none of the scenario's others"},
                    BadCase{"bad_multi_pass", "duration: 1\nworld: {name: slope, soil: {base: dry_sand, multi_pass: often}}\n",
                            "multi_pass"},
                    BadCase{"bad_integrator", "duration: 1\nintegrator: verlet\n", "/integrator: expected 'implicit', 'euler' or 'rk4', got 'verlet'"},
                    BadCase{"two_commands", "duration: 1\ntimeline:\n  - {at: 0, controller: c, command: 1, twist: {vx: 1}}\n",
                            "exactly one of"},
                    BadCase{"unknown_check", "duration: 1\nchecks:\n  - {fly: {x: 1}}\n", "unknown check 'fly'"},
                    BadCase{"bad_waypoint", "duration: 1\ntimeline:\n  - {at: 0, controller: c, route: {waypoints: [[1, 2, 3]]}}\n",
                            "[x, y]"},
                    BadCase{"negative_time", "duration: 1\ntimeline:\n  - {at: -1, controller: c, command: 1}\n", "/timeline"},
                    BadCase{"malformed", "duration: [1\n", "s.yaml"},
                    BadCase{"trajectory_typo", "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {points: [{time: 1, positions: [0]}], goal_time: 1}}\n",
                            "s.yaml:5: /timeline[0]/trajectory/goal_time: unknown key 'goal_time' (expected one of: joints, points, goal_time_tolerance"},
                    BadCase{"no_points", "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {points: []}}\n",
                            "trajectory/points: expected a non-empty list of points"},
                    BadCase{"times_not_increasing",
                            "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {points: [{time: 1, positions: [0]}, {time: 1, positions: [1]}]}}\n",
                            "points[1]/time: point times must increase"},
                    BadCase{"point_sizes", "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {joints: [a, b], points: [{time: 1, positions: [0]}]}}\n",
                            "points[0]/positions: has 1 values, expected 2 (one per joint)"},
                    BadCase{"velocity_sizes",
                            "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {points: [{time: 1, positions: [0, 1], velocities: [0]}]}}\n",
                            "velocities: has 1 values, expected 2"},
                    BadCase{"accelerations_alone",
                            "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {points: [{time: 1, positions: [0], accelerations: [0]}]}}\n",
                            "accelerations need velocities too"},
                    BadCase{"tolerance_typo",
                            "duration: 1\ntimeline:\n  - {at: 0, controller: c, trajectory: {points: [{time: 1, positions: [0]}], goal_tolerance: {all: {pos: 1}}}}\n",
                            "goal_tolerance/all/pos: unknown key 'pos'"},
                    BadCase{"gripper_negative", "duration: 1\ntimeline:\n  - {at: 0, controller: c, gripper: {position: -0.01}}\n",
                            "gripper/position: must be a gap >= 0 m"},
                    BadCase{"gripper_typo", "duration: 1\ntimeline:\n  - {at: 0, controller: c, gripper: {position: 0.01, effort: 3}}\n",
                            "gripper/effort: unknown key 'effort'"},
                    BadCase{"trajectory_and_command", "duration: 1\ntimeline:\n  - {at: 0, controller: c, command: 1, gripper: {position: 0.01}}\n",
                            "exactly one of command, twist, mode, route, trajectory, gripper"},
                    BadCase{"bad_result", "duration: 1\nchecks:\n  - {trajectory: {controller: c, result: DONE}}\n",
                            "/checks[0]/trajectory/result: unknown result code 'DONE'"},
                    BadCase{"empty_trajectory_check", "duration: 1\nchecks:\n  - {trajectory: {controller: c}}\n",
                            "needs max_rms_error, max_error and/or result"},
                    BadCase{"check_typo", "duration: 1\nchecks:\n  - {trajectory: {controller: c, max_rms: 0.1}}\n",
                            "unknown key 'max_rms'"},
                    BadCase{"goal_zero", "duration: 1\nchecks:\n  - {gripper: {controller: c, goal: 0, reached: true}}\n",
                            "goal: is the 1-based index"},
                    BadCase{"within_alone", "duration: 1\nchecks:\n  - {gripper: {controller: c, reached: true, within: 0.1}}\n",
                            "within: goes with position"},
                    BadCase{"joint_check_no_within", "duration: 1\nchecks:\n  - {joint: {name: j, position: 1}}\n", "within"},
                    BadCase{"odometry_empty", "duration: 1\nchecks:\n  - {odometry: {}}\n", "needs max_error_fraction and/or max_yaw_error_fraction"},
                    BadCase{"box_size", "duration: 1\nworld: {boxes: [{name: a, size: [1, 0, 1]}]}\n", "/world/boxes[0]/size: edge lengths must be > 0 m"},
                    BadCase{"mesh_without_file", "duration: 1\nworld: {boxes: [{name: m, shape: mesh}]}\n", "a mesh needs 'mesh'"},
                    BadCase{"mesh_missing", "duration: 1\nworld: {boxes: [{name: m, shape: mesh, mesh: rock.stl}]}\n",
                            "/world/boxes[0]/mesh: no such file: "},
                    BadCase{"mesh_not_a_mesh", "duration: 1\nworld: {boxes: [{name: m, shape: mesh, mesh: controllers.yaml}]}\n",
                            "/world/boxes[0]/mesh: "},
                    BadCase{"mesh_with_size", "duration: 1\nworld: {boxes: [{name: m, shape: mesh, mesh: a.stl, size: [1, 1, 1]}]}\n",
                            "a mesh takes no 'size'"},
                    BadCase{"box_with_scale", "duration: 1\nworld: {boxes: [{name: b, size: [1, 1, 1], scale: [2, 2, 2]}]}\n",
                            "a box takes no 'scale'"},
                    BadCase{"box_twice", "duration: 1\nworld: {boxes: [{name: a, size: [1, 1, 1]}, {name: a, size: [1, 1, 1]}]}\n",
                            "box 'a' is named twice"},
                    BadCase{"box_quat_and_yaw", "duration: 1\nworld: {boxes: [{name: a, size: [1, 1, 1], yaw: 1, quat: [1, 0, 0, 0]}]}\n",
                            "give quat or roll/pitch/yaw, not both"},
                    BadCase{"box_typo", "duration: 1\nworld: {boxes: [{name: a, size: [1, 1, 1], heigth: 2}]}\n", "unknown key 'heigth'"},
                    BadCase{"box_shape", "duration: 1\nworld: {boxes: [{name: a, shape: cone, radius: 1}]}\n",
                            "/world/boxes[0]/shape: expected box, cylinder, sphere or mesh, got 'cone'"},
                    BadCase{"cylinder_no_length", "duration: 1\nworld: {boxes: [{name: a, shape: cylinder, radius: 1}]}\n",
                            "a cylinder needs 'length'"},
                    BadCase{"sphere_size", "duration: 1\nworld: {boxes: [{name: a, shape: sphere, radius: 1, size: [1, 1, 1]}]}\n",
                            "/world/boxes[0]/size: a sphere takes no 'size'"},
                    BadCase{"sphere_radius", "duration: 1\nworld: {boxes: [{name: a, shape: sphere, radius: -1}]}\n",
                            "/world/boxes[0]/radius: must be > 0 m"},
                    BadCase{"event_typo", "duration: 1\ntimeline:\n  - {at: 0, controller: c, comand: 1}\n", "unknown key 'comand'"},
                    BadCase{"twist_typo", "duration: 1\ntimeline:\n  - {at: 0, controller: c, twist: {vz: 1}}\n", "twist/vz: unknown key 'vz'"},
                    BadCase{"reach_typo", "duration: 1\nchecks:\n  - {reach: {x: 1, y: 2, within: 0.5, by: 10, withn: 1}}\n",
                            "/checks[0]/reach/withn: unknown key 'withn'"},
                    BadCase{"spawn_joints_list", "duration: 1\nspawn: {joints: [1, 2]}\n", "/spawn/joints: expected a map"}),
    [](const testing::TestParamInfo<BadCase>& param) { return std::string(param.param.name); });

TEST(ScenarioFileMissing, NamesTheFile) {
  try {
    load_scenario("/nonexistent/dir/s.yaml");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/s.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace mechsim::sim
