// The PR2 base controller and odometry loaded by the controller manager on a 12-joint test
// mechanism: acceleration limit per tick, caster targets, wheels scaled by the caster error,
// the flip, the timeout, NaN rejection, init errors naming parameter paths, and the geometry
// filled from the reference PR2 URDF.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/drive/pr2_base_controller.hpp"
#include "controllers/drive/pr2_base_params.hpp"
#include "controllers/drive/pr2_odometry.hpp"
#include "controllers/drive/test/pr2_base_test_util.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;
using testing::kPr2WheelRadius;
constexpr double kPi = std::numbers::pi;

struct Fixture {
  std::unique_ptr<testing::TestRobot> robot = testing::make_pr2_base_robot();
  std::unique_ptr<ControllerManager> manager;
  Pr2BaseController* base = nullptr;

  explicit Fixture(const std::string& extra = "") {
    manager = std::make_unique<ControllerManager>(robot->model, robot->state,
                                                  Params::from_yaml_string(testing::pr2_base_yaml(extra)).child("base"),
                                                  builtin_controller_registry());
    const ControlResult r = manager->load_controller("base_controller");
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(manager->switch_controllers({"base_controller"}, {}, SwitchStrictness::Strict).ok);
    base = dynamic_cast<Pr2BaseController*>(manager->controller("base_controller"));
  }
  // Ticks without physics (the joints stay where the test puts them).
  double tick(double time, int n = 1) {
    for (int i = 0; i < n; ++i, time += 0.001) manager->update(time, 0.001);
    return time;
  }
  JointGroupControllerState state() const { return base->state_port().read(); }
};

TEST(Pr2BaseController, AccelerationLimitsTheCommandPerTick) {
  Fixture f;
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{0.3, 0.0, 0.0}, {0.0, 0.0, 2.0}}));
  t = f.tick(t);
  Pr2BaseStatus st = f.base->status_port().read();
  EXPECT_NEAR(st.applied.vx, 0.2 * 0.001, 1e-12);    // max_translational_acceleration/x default 0.2
  EXPECT_NEAR(st.applied.wz, 10.0 * 0.001, 1e-12);   // max_rotational_acceleration default 10
  t = f.tick(t, 99);
  st = f.base->status_port().read();
  EXPECT_NEAR(st.applied.vx, 0.2 * 0.1, 1e-9);
  EXPECT_NEAR(st.applied.wz, 1.0, 1e-9);
  EXPECT_FALSE(st.timed_out);
}

TEST(Pr2BaseController, VelocityLimitScalesTheTranslation) {
  Fixture f("    max_translational_acceleration: {x: 1000.0, y: 1000.0}\n");
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{3.0, 4.0, 0.0}, {}}));  // |v| = 5 m/s, limit 0.5
  f.tick(t, 2);
  const Pr2BaseStatus st = f.base->status_port().read();
  EXPECT_NEAR(st.applied.vx, 0.3, 1e-9);
  EXPECT_NEAR(st.applied.vy, 0.4, 1e-9);
}

TEST(Pr2BaseController, SidewaysCommandTurnsEveryCasterToNinetyDegrees) {
  Fixture f;
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{0.0, 0.2, 0.0}, {}}));
  f.tick(t, 10);
  const auto s = f.state();
  for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(s.joints[c].set_point, kPi / 2.0, 1e-12) << s.joint_names[c];
  // Casters still at 0: the wheels, perpendicular to the motion, must not drive.
  for (std::size_t w = 4; w < 12; ++w) EXPECT_NEAR(s.joints[w].set_point, 0.0, 1e-12) << s.joint_names[w];
  EXPECT_NEAR(f.base->status_port().read().max_caster_error, kPi / 2.0, 1e-12);
}

TEST(Pr2BaseController, WheelsScaleWithTheCasterError) {
  Fixture f("    max_translational_acceleration: {x: 1000.0, y: 1000.0}\n");
  for (const char* c : {"fl", "fr", "bl", "br"}) f.robot->joint(std::string(c) + "_caster_rotation_joint").position = 0.5;
  mechanism::propagate_joint_to_actuator_position(f.robot->model, f.robot->state);  // what the encoders read
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{0.3, 0.0, 0.0}, {}}));
  f.tick(t, 2);
  const auto s = f.state();
  for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(s.joints[c].set_point, 0.0, 1e-12);
  // Each wheel rolls the component of 0.3 m/s along where its caster points.
  for (std::size_t w = 4; w < 12; ++w) EXPECT_NEAR(s.joints[w].set_point, 0.3 * std::cos(0.5) / kPr2WheelRadius, 1e-9);
  // The caster PIDs push towards 0 (effort = p * error, p = 20, d on the error change).
  EXPECT_LT(s.joints[0].command, 0.0);
}

TEST(Pr2BaseController, ACasterPointingBackwardsStaysAndItsWheelsReverse) {
  Fixture f("    max_translational_acceleration: {x: 1000.0, y: 1000.0}\n");
  f.robot->joint("fl_caster_rotation_joint").position = kPi - 0.1;
  mechanism::propagate_joint_to_actuator_position(f.robot->model, f.robot->state);
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{0.3, 0.0, 0.0}, {}}));
  f.tick(t, 2);
  const auto s = f.state();
  EXPECT_NEAR(std::abs(s.joints[0].set_point), kPi, 1e-12);  // flipped: 0.1 rad to go, not pi - 0.1
  EXPECT_NEAR(s.joints[0].error, 0.1, 1e-9);
  EXPECT_NEAR(s.joints[4].set_point, 0.3 * std::cos(kPi - 0.1) / kPr2WheelRadius, 1e-9);  // fl_l reversed
  EXPECT_LT(s.joints[4].set_point, 0.0);
  EXPECT_EQ(f.base->status_port().read().reversed_casters, 1);
}

TEST(Pr2BaseController, TimeoutStopsTheBase) {
  Fixture f("    max_translational_acceleration: {x: 1.0, y: 1.0}\n");
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{0.3, 0.0, 0.0}, {}}));
  t = f.tick(t, 150);
  EXPECT_FALSE(f.base->status_port().read().timed_out);
  EXPECT_NEAR(f.base->status_port().read().applied.vx, 0.15, 1e-9);
  t = f.tick(t, 100);  // 0.25 s after the command: past the 0.2 s timeout
  Pr2BaseStatus st = f.base->status_port().read();
  EXPECT_TRUE(st.timed_out);
  // It rose to 0.2 m/s until the timeout (0.201 s), then braked at 1 m/s^2 for ~49 ticks.
  EXPECT_NEAR(st.applied.vx, 0.2 - 0.049, 0.0015);
  f.tick(t, 200);
  st = f.base->status_port().read();
  EXPECT_EQ(st.applied.vx, 0.0);
  for (std::size_t w = 4; w < 12; ++w) EXPECT_EQ(f.state().joints[w].set_point, 0.0);
  // A new command (even the same) lifts the timeout.
  ASSERT_TRUE(f.base->command_port().write({{0.3, 0.0, 0.0}, {}}));
  f.tick(t + 0.2, 1);
  EXPECT_FALSE(f.base->status_port().read().timed_out);
}

TEST(Pr2BaseController, RejectsNonFiniteCommands) {
  Fixture f;
  double t = f.tick(0.0);
  ASSERT_TRUE(f.base->command_port().write({{0.1, 0.0, 0.0}, {}}));
  std::string error;
  EXPECT_FALSE(f.base->command_port().write({{NAN, 0.0, 0.0}, {}}, &error));
  EXPECT_EQ(f.base->command_port().count(), 1u);
  f.tick(t, 5);
  for (const auto& j : f.state().joints) EXPECT_TRUE(std::isfinite(j.command));
  EXPECT_DOUBLE_EQ(f.base->status_port().read().command.linear.x, 0.1);
}

TEST(Pr2BaseController, InitErrorsNameTheParameterPath) {
  auto robot = testing::make_pr2_base_robot();
  const auto load = [&](const std::string& yaml) {
    ControllerManager m(robot->model, robot->state, Params::from_yaml_string(yaml).child("base"),
                        builtin_controller_registry());
    return m.load_controller("base_controller").error;
  };
  std::string yaml = testing::pr2_base_yaml();
  std::string bad = yaml;
  bad.replace(bad.find("    wheel_radius: 0.074792\n"), 27, "");
  EXPECT_THAT(load(bad), HasSubstr("/base/base_controller/wheel_radius"));
  bad = yaml;
  bad.replace(bad.find("fl_caster_rotation_joint"), 24, "nope_joint");
  EXPECT_THAT(load(bad), HasSubstr("/base/base_controller/caster_joints[0]"));
  bad = yaml;
  bad.replace(bad.find("    caster_pid: {p: 20.0, d: 1.0}\n"), 34, "");
  EXPECT_THAT(load(bad), HasSubstr("/base/base_controller/caster_pid"));
  bad = yaml;
  bad.replace(bad.find("      fl_caster_l_wheel_joint: 0.049\n"), 36, "");
  EXPECT_THAT(load(bad), HasSubstr("/base/base_controller/wheel_offsets/fl_caster_l_wheel_joint"));
  EXPECT_THAT(load(testing::pr2_base_yaml("    max_rotational_velocity: -1\n")),
              HasSubstr("/base/base_controller/max_rotational_velocity"));
}

TEST(Pr2BaseController, ClosedLoopOnTheTestPlantConvergesAndOdometryAgrees) {
  // Every joint a unit inertia (no ground): the casters must settle at their headings and the
  // wheels at their speeds, and the odometry running beside must read the commanded twist.
  auto robot = testing::make_pr2_base_robot();
  std::string yaml = testing::pr2_base_yaml("    max_translational_acceleration: {x: 1.0, y: 1.0}\n    timeout: 0\n");
  yaml.replace(yaml.find("caster_pid: {p: 20.0, d: 1.0}"), 29, "caster_pid: {p: 100.0, d: 20.0}");
  ControllerManager m(robot->model, robot->state, Params::from_yaml_string(yaml).child("base"),
                      builtin_controller_registry());
  ASSERT_TRUE(m.load_controller("base_controller").ok);
  ASSERT_TRUE(m.load_controller("odometry").ok);
  ASSERT_TRUE(m.switch_controllers({"base_controller", "odometry"}, {}, SwitchStrictness::Strict).ok);
  auto* base = dynamic_cast<Pr2BaseController*>(m.controller("base_controller"));
  auto* odom = dynamic_cast<Pr2OdometryController*>(m.controller("odometry"));
  double t = testing::run(m, *robot, 0.0, 1);
  ASSERT_TRUE(base->command_port().write({{0.1, 0.2, 0.0}, {}}));
  t = testing::run(m, *robot, t, 8000);
  const auto s = base->state_port().read();
  const double heading = std::atan2(0.2, 0.1);
  for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(s.joints[c].process_value, heading, 1e-3) << s.joint_names[c];
  const double wheel = std::hypot(0.1, 0.2) / kPr2WheelRadius;
  for (std::size_t w = 4; w < 12; ++w) EXPECT_NEAR(s.joints[w].process_value, wheel, 0.01) << s.joint_names[w];
  const OdometrySnapshot o = odom->odometry_port().read();
  EXPECT_NEAR(o.linear.x, 0.1, 1e-3);
  EXPECT_NEAR(o.linear.y, 0.2, 1e-3);
  EXPECT_NEAR(o.angular.z, 0.0, 1e-3);
  EXPECT_LT(o.residual, 1e-3);
}

TEST(Pr2Odometry, IntegratesTheWheelsOfTheTestBase) {
  auto robot = testing::make_pr2_base_robot();
  ControllerManager m(robot->model, robot->state, Params::from_yaml_string(testing::pr2_base_yaml()).child("base"),
                      builtin_controller_registry());
  ASSERT_TRUE(m.load_controller("odometry").ok);
  ASSERT_TRUE(m.switch_controllers({"odometry"}, {}, SwitchStrictness::Strict).ok);
  auto* odom = dynamic_cast<Pr2OdometryController*>(m.controller("odometry"));
  ASSERT_NE(odom, nullptr);
  // Casters at 0, every wheel at 0.5 m/s: 1 m ahead in 2 s.
  for (std::size_t i = 0; i < robot->model.joints.size(); ++i) {
    if (robot->model.joints[i].name.find("wheel") != std::string::npos) robot->state.joints[i].velocity = 0.5 / kPr2WheelRadius;
  }
  mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
  double t = 0.0;
  for (int i = 0; i < 2000; ++i, t += 0.001) m.update(t, 0.001);
  OdometrySnapshot o = odom->odometry_port().read();
  EXPECT_TRUE(o.valid);
  EXPECT_NEAR(o.x, 1.0, 1e-6);
  EXPECT_NEAR(o.y, 0.0, 1e-9);
  EXPECT_NEAR(o.linear.x, 0.5, 1e-9);
  EXPECT_EQ(o.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_footprint");
  EXPECT_NEAR(o.pose_covariance[0], 0.002 * 0.002, 1e-15);
  odom->reset_odometry();
  m.update(t, 0.001);
  EXPECT_NEAR(odom->odometry_port().read().x, 0.0005, 1e-9);
}

TEST(Pr2Odometry, InitErrorsNameTheParameterPath) {
  auto robot = testing::make_pr2_base_robot();
  const auto load = [&](const std::string& extra) {
    const std::string yaml = "base:\n  odometry:\n    type: pr2_mechanism_controllers/Pr2Odometry\n" +
                             testing::pr2_base_geometry_yaml(4) + extra;
    ControllerManager m(robot->model, robot->state, Params::from_yaml_string(yaml).child("base"),
                        builtin_controller_registry());
    return m.load_controller("odometry").error;
  };
  EXPECT_EQ(load(""), "");
  EXPECT_THAT(load("    ils_weight_type: Huber\n"), HasSubstr("/base/odometry/ils_weight_type"));
  EXPECT_THAT(load("    ils_max_iterations: -2\n"), HasSubstr("/base/odometry/ils_max_iterations"));
  EXPECT_THAT(load("    wheel_radius_multiplier: 0\n"), HasSubstr("/base/odometry/wheel_radius_multiplier"));
  EXPECT_THAT(load("    caster_axis_signs: {fl_caster_rotation_joint: 2}\n"),
              HasSubstr("/base/odometry/caster_axis_signs/fl_caster_rotation_joint"));
}

std::optional<description::RobotModel> reference_pr2() {
  const std::filesystem::path path = std::filesystem::path(MECHSIM_SHARED_DIR) / "robots" / "reference" / "pr2.urdf";
  if (!std::filesystem::exists(path)) return std::nullopt;
  description::UrdfOptions options;
  options.lenient = true;
  return description::parse_urdf_file(path.string(), options);
}

TEST(Pr2BaseParams, FillsTheGeometryFromTheReferencePr2AndLoadsOnItsMechanism) {
  const auto robot = reference_pr2();
  if (!robot) GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/robots/reference/pr2.urdf";
  const Params ns = Params::from_yaml_string(R"(pr2:
  base_controller:
    type: pr2_mechanism_controllers/Pr2BaseController2
    caster_names: fl_caster_rotation_link fr_caster_rotation_link bl_caster_rotation_link br_caster_rotation_link
    caster_pid: {p: 8.0}
    wheel_pid: {p: 4.0}
    fl_caster_l_wheel_joint: {p: 5.0}
  odometry:
    type: pr2_mechanism_controllers/Pr2Odometry
    caster_joints: [fl_caster_rotation_joint, fr_caster_rotation_joint, bl_caster_rotation_joint, br_caster_rotation_joint]
)").child("pr2");
  EXPECT_EQ(fill_pr2_base_geometry_all(ns, *robot), 2);
  const Params p = ns.child("base_controller");
  EXPECT_EQ(p.get<std::vector<std::string>>("caster_joints").at(0), "fl_caster_rotation_joint");
  EXPECT_EQ(p.get<std::vector<std::string>>("wheel_joints").size(), 8u);
  EXPECT_DOUBLE_EQ(p.get<double>("wheel_radius"), 0.074792);
  EXPECT_NEAR(p.get<std::vector<double>>("caster_positions/fl_caster_rotation_joint").at(0), 0.2246, 1e-9);
  EXPECT_NEAR(p.get<std::vector<double>>("caster_positions/br_caster_rotation_joint").at(1), -0.2246, 1e-9);
  EXPECT_NEAR(p.get<double>("wheel_offsets/fl_caster_l_wheel_joint"), 0.049, 1e-9);
  EXPECT_NEAR(p.get<double>("wheel_offsets/br_caster_r_wheel_joint"), -0.049, 1e-9);
  EXPECT_EQ(p.get<std::string>("wheel_casters/bl_caster_r_wheel_joint"), "bl_caster_rotation_joint");
  EXPECT_EQ(p.get<double>("wheel_axis_signs/fr_caster_l_wheel_joint"), 1.0);
  EXPECT_EQ(fill_pr2_base_geometry(p, *robot), 0);
  EXPECT_EQ(ns.child("odometry").get<std::vector<std::string>>("wheel_joints"),
            (std::vector<std::string>{"fl_caster_l_wheel_joint", "fl_caster_r_wheel_joint", "fr_caster_l_wheel_joint",
                                      "fr_caster_r_wheel_joint", "bl_caster_l_wheel_joint", "bl_caster_r_wheel_joint",
                                      "br_caster_l_wheel_joint", "br_caster_r_wheel_joint"}));

  const mechanism::MechanismModel model = mechanism::build_mechanism(*robot);
  mechanism::MechanismState state = mechanism::make_state(model);
  ControllerManager manager(model, state, ns, builtin_controller_registry());
  for (const char* name : {"base_controller", "odometry"}) {
    const ControlResult r = manager.load_controller(name);
    ASSERT_TRUE(r.ok) << r.error;
  }
  ASSERT_TRUE(manager.switch_controllers({"base_controller", "odometry"}, {}, SwitchStrictness::Strict).ok);
  Controller* base = manager.controller("base_controller");
  EXPECT_EQ(base->port_as<PidGainsPort>("gains/fl_caster_l_wheel_joint")->latest().p, 5.0);  // per-joint gains
  EXPECT_EQ(base->port_as<PidGainsPort>("gains/fr_caster_l_wheel_joint")->latest().p, 4.0);
  EXPECT_EQ(base->port_as<PidGainsPort>("gains/br_caster_rotation_joint")->latest().p, 8.0);
  double t = 0.0;
  for (int i = 0; i < 10; ++i, t += 0.001) manager.update(t, 0.001);
  EXPECT_EQ(manager.controller_info("base_controller")->statistics.failures, 0u);
}

TEST(Pr2BaseParams, GripperAndLaserLoadOnTheReferencePr2Mechanism) {
  const auto robot = reference_pr2();
  if (!robot) GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/robots/reference/pr2.urdf";
  const Params ns = Params::from_yaml_string(R"(pr2:
  r_gripper_controller:
    type: pr2_mechanism_controllers/Pr2GripperController
    joint: r_gripper_joint
    pid: {p: 10000.0, d: 1000.0}
  laser_tilt_controller:
    type: pr2_mechanism_controllers/LaserScannerTrajController
    joint: laser_tilt_mount_joint
    pid: {p: 8.0, d: 0.4}
    profile: linear
    period: 2.0
    amplitude: 0.6
    offset: 0.3
)").child("pr2");
  const mechanism::MechanismModel model = mechanism::build_mechanism(*robot);
  mechanism::MechanismState state = mechanism::make_state(model);
  ControllerManager manager(model, state, ns, builtin_controller_registry());
  for (const char* name : {"r_gripper_controller", "laser_tilt_controller"}) {
    const ControlResult r = manager.load_controller(name);
    ASSERT_TRUE(r.ok) << r.error;
  }
  ASSERT_TRUE(manager.switch_controllers({"r_gripper_controller", "laser_tilt_controller"}, {}, SwitchStrictness::Strict).ok);
  double t = 0.0;
  for (int i = 0; i < 10; ++i, t += 0.001) manager.update(t, 0.001);
  EXPECT_EQ(manager.controller_info("r_gripper_controller")->statistics.failures, 0u);
  auto* laser = manager.controller("laser_tilt_controller")->port_as<StatePort<JointControllerState>>("state");
  EXPECT_NEAR(laser->read().set_point, 0.3 - 0.6 + 4.0 * 0.6 * 0.009 / 2.0, 1e-9);
}

TEST(Pr2BaseParams, UnknownCasterLinkNamesTheParameter) {
  const auto robot = reference_pr2();
  if (!robot) GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/robots/reference/pr2.urdf";
  const Params p = Params::from_yaml_string("b:\n  caster_names: [fl_caster_rotation_link, nowhere_link]\n").child("b");
  try {
    fill_pr2_base_geometry(p, *robot);
    FAIL() << "no error";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/b/caster_names[1]"));
    EXPECT_THAT(e.what(), HasSubstr("nowhere_link"));
  }
}

}  // namespace
}  // namespace mechsim::control
