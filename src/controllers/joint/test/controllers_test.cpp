// Control laws of the built-in controllers, each closing its loop on the unit-mass joints of
// test_robot.hpp at 1 kHz.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/angles.hpp"
#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control {
namespace {

using description::JointLimits;
using description::JointType;
using testing::JointSpec;
using testing::make_robot;
using testing::run;

struct Rig {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  double time = 0.0;

  Rig(std::vector<JointSpec> joints, const std::string& yaml) : robot(make_robot(joints)) {
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml),
                                                  builtin_controller_registry());
  }
  void start(const std::string& name) {
    auto r = manager->load_controller(name);
    ASSERT_TRUE(r.ok) << r.error;
    auto s = manager->switch_controllers({name}, {}, SwitchStrictness::Strict);
    ASSERT_TRUE(s.ok) << s.error;
    tick(1);
    ASSERT_EQ(manager->controller_info(name)->state, ControllerLifecycle::Running);
  }
  void tick(int n) { time = run(*manager, *robot, time, n); }
  template <class P>
  P& port(const std::string& controller, const std::string& name) {
    auto* p = manager->controller(controller)->port_as<P>(name);
    EXPECT_NE(p, nullptr) << controller << "/" << name;
    return *p;
  }
  mechanism::JointState& joint(const std::string& name) { return robot->joint(name); }
};

std::vector<JointSpec> one(JointSpec spec) { return {std::move(spec)}; }

TEST(EffortJointPositionController, ConvergesOnAUnitMass) {
  Rig rig(one({"j"}), "c: {type: effort_controllers/JointPositionController, joint: j, pid: {p: 100, d: 20}}");
  rig.start("c");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(1.2));
  rig.tick(2000);
  EXPECT_NEAR(rig.joint("j").position, 1.2, 1e-3);
  EXPECT_NEAR(rig.joint("j").velocity, 0.0, 1e-2);
  auto state = rig.port<StatePort<JointControllerState>>("c", "state").read();
  EXPECT_DOUBLE_EQ(state.set_point, 1.2);
  EXPECT_NEAR(state.process_value, 1.2, 1e-3);
  EXPECT_NEAR(state.error, state.set_point - state.process_value, 1e-12);
  EXPECT_DOUBLE_EQ(state.time_step, 0.001);
  EXPECT_DOUBLE_EQ(state.gains.p, 100.0);
  EXPECT_GT(rig.port<StatePort<JointControllerState>>("c", "state").sequence(), 1000u);
}

TEST(EffortJointPositionController, StartsHoldingTheCurrentPosition) {
  Rig rig(one({"j"}), "c: {type: effort_controllers/JointPositionController, joint: j, pid: {p: 100, d: 20}}");
  rig.robot->state.actuators[0].position = 0.7;  // the encoder reads 0.7 before the start
  rig.start("c");
  rig.tick(500);
  EXPECT_NEAR(rig.joint("j").position, 0.7, 1e-9);
  EXPECT_DOUBLE_EQ(rig.port<StatePort<JointControllerState>>("c", "state").read().set_point, 0.7);
}

TEST(EffortJointPositionController, RespectsPositionLimits) {
  Rig rig(one({"j", JointType::Revolute, JointLimits{-0.5, 0.5, 100.0, 10.0}}),
          "c: {type: effort_controllers/JointPositionController, joint: j, pid: {p: 100, d: 20}}");
  rig.start("c");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(2.0));
  rig.tick(2000);
  EXPECT_NEAR(rig.joint("j").position, 0.5, 1e-3);
  EXPECT_DOUBLE_EQ(rig.port<StatePort<JointControllerState>>("c", "state").read().set_point, 0.5);
}

TEST(EffortJointPositionController, TakesTheShortWayRoundOnContinuousJoints) {
  Rig rig(one({"w", JointType::Continuous}), "c: {type: effort_controllers/JointPositionController, joint: w, pid: {p: 100, d: 20}}");
  rig.robot->state.actuators[0].position = -3.0;
  rig.start("c");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(3.0));
  rig.tick(1);
  EXPECT_LT(rig.joint("w").commanded_effort, 0.0);  // -3 -> 3 the short way is -0.28 rad, through -pi
  rig.tick(2000);
  const double travelled = rig.joint("w").position - (-3.0);
  EXPECT_NEAR(travelled, 6.0 - 2.0 * std::numbers::pi, 1e-3);
  EXPECT_NEAR(shortest_angular_distance(rig.joint("w").position, 3.0), 0.0, 1e-3);
}

TEST(Angles, ShortestAngularDistance) {
  EXPECT_NEAR(shortest_angular_distance(0.0, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(shortest_angular_distance(-3.0, 3.0), 6.0 - 2.0 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(shortest_angular_distance(3.0, -3.0), 2.0 * std::numbers::pi - 6.0, 1e-12);
  EXPECT_NEAR(shortest_angular_distance(0.0, 7.0), 7.0 - 2.0 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(normalize_angle(std::numbers::pi), std::numbers::pi, 1e-12);
  EXPECT_NEAR(normalize_angle(-std::numbers::pi), std::numbers::pi, 1e-12);
}

TEST(EffortJointVelocityController, ConvergesToTheCommandedVelocity) {
  Rig rig(one({"j", JointType::Continuous}), "c: {type: effort_controllers/JointVelocityController, joint: j, pid: {p: 20}}");
  rig.start("c");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(1.5));
  rig.tick(1000);
  EXPECT_NEAR(rig.joint("j").velocity, 1.5, 1e-3);
  auto state = rig.port<StatePort<JointControllerState>>("c", "state").read();
  EXPECT_DOUBLE_EQ(state.set_point, 1.5);
  EXPECT_NEAR(state.process_value, 1.5, 1e-3);
}

TEST(EffortJointEffortController, AppliesTheCommandedEffort) {
  Rig rig(one({"j", JointType::Prismatic, JointLimits{-100, 100, 50, 100}}),
          "c: {type: effort_controllers/JointEffortController, joint: j}");
  rig.start("c");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(2.0));
  rig.tick(1000);  // 1 s at 2 N on 1 kg
  EXPECT_NEAR(rig.joint("j").velocity, 2.0, 5e-3);
  EXPECT_NEAR(rig.joint("j").position, 1.0, 5e-3);
  // The effort limit (50 N) holds whatever is commanded.
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(500.0));
  rig.tick(1);
  EXPECT_DOUBLE_EQ(rig.robot->state.actuators[0].commanded_effort, 50.0);
}

TEST(PositionJointPositionController, ForwardsToThePositionInterface) {
  Rig rig(one({"j"}), "c: {type: position_controllers/JointPositionController, joint: j}");
  rig.robot->state.actuators[0].position = 0.3;
  rig.start("c");
  EXPECT_NEAR(rig.joint("j").position, 0.3, 1e-12);  // started at the current position: no jump
  EXPECT_EQ(rig.joint("j").command_mode, HardwareInterface::Position);
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(-1.0));
  rig.tick(300);  // the velocity limit (10 rad/s) lets it travel 1.3 rad in 0.13 s
  EXPECT_NEAR(rig.joint("j").position, -1.0, 1e-9);
  auto state = rig.port<StatePort<JointControllerState>>("c", "state").read();
  EXPECT_DOUBLE_EQ(state.set_point, -1.0);
  EXPECT_DOUBLE_EQ(state.command, -1.0);
}

TEST(VelocityJointVelocityController, ForwardsToTheVelocityInterface) {
  Rig rig(one({"j", JointType::Continuous}), "c: {type: velocity_controllers/JointVelocityController, joint: j}");
  rig.start("c");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(0.5));
  rig.tick(1000);
  EXPECT_EQ(rig.joint("j").command_mode, HardwareInterface::Velocity);
  EXPECT_NEAR(rig.joint("j").velocity, 0.5, 1e-12);
  EXPECT_NEAR(rig.joint("j").position, 0.5, 2e-3);
  ASSERT_TRUE(rig.port<ScalarCommandPort>("c", "command").write(50.0));  // above the 10 rad/s limit
  rig.tick(2);
  EXPECT_DOUBLE_EQ(rig.joint("j").velocity, 10.0);
}

std::vector<JointSpec> three() { return {JointSpec{"a"}, JointSpec{"b"}, JointSpec{"c"}}; }

TEST(GroupControllers, EffortGroupAppliesOneEffortPerJoint) {
  Rig rig(three(), "g: {type: effort_controllers/JointGroupEffortController, joints: [a, c]}");
  rig.start("g");
  auto& port = rig.port<ArrayCommandPort>("g", "command");
  EXPECT_EQ(port.size(), 2u);
  std::string error;
  EXPECT_FALSE(port.write(std::vector<double>{1.0}, &error));
  EXPECT_THAT(error, ::testing::HasSubstr("dimension of command (1) does not match number of joints (2)"));
  EXPECT_FALSE(port.write(std::vector<double>{1.0, NAN}));
  EXPECT_EQ(port.count(), 2u);
  ASSERT_TRUE(port.write(std::vector<double>{1.0, -2.0}));
  rig.tick(1000);
  EXPECT_NEAR(rig.joint("a").velocity, 1.0, 5e-3);
  EXPECT_NEAR(rig.joint("b").velocity, 0.0, 1e-12);
  EXPECT_NEAR(rig.joint("c").velocity, -2.0, 5e-3);
  auto state = rig.port<StatePort<JointGroupControllerState>>("g", "state").read();
  EXPECT_EQ(state.joint_names, (std::vector<std::string>{"a", "c"}));
  EXPECT_DOUBLE_EQ(state.joints[1].command, -2.0);
}

TEST(GroupControllers, PositionGroupStartsAtCurrentPositionsAndTracks) {
  Rig rig(three(), "g: {type: position_controllers/JointGroupPositionController, joints: [a, b, c]}");
  rig.robot->state.actuators[1].position = 0.25;
  rig.start("g");
  EXPECT_NEAR(rig.joint("b").position, 0.25, 1e-12);
  ASSERT_TRUE(rig.port<ArrayCommandPort>("g", "command").write(std::vector<double>{0.1, 0.2, 0.3}));
  rig.tick(100);
  EXPECT_NEAR(rig.joint("a").position, 0.1, 1e-9);
  EXPECT_NEAR(rig.joint("b").position, 0.2, 1e-9);
  EXPECT_NEAR(rig.joint("c").position, 0.3, 1e-9);
}

TEST(GroupControllers, VelocityGroupForwardsVelocities) {
  Rig rig(three(), "g: {type: velocity_controllers/JointGroupVelocityController, joints: [b, a]}");
  rig.start("g");
  ASSERT_TRUE(rig.port<ArrayCommandPort>("g", "command").write(std::vector<double>{0.4, -0.2}));
  rig.tick(10);
  EXPECT_DOUBLE_EQ(rig.joint("b").velocity, 0.4);
  EXPECT_DOUBLE_EQ(rig.joint("a").velocity, -0.2);
  EXPECT_DOUBLE_EQ(rig.joint("c").velocity, 0.0);
}

TEST(GroupControllers, EffortGroupPositionUsesOnePidPerJoint) {
  Rig rig(three(), R"(g:
  type: effort_controllers/JointGroupPositionController
  joints: [a, b]
  a: {pid: {p: 100, d: 20}}
  b: {pid: {p: 400, d: 40}}
)");
  rig.start("g");
  ASSERT_TRUE(rig.port<ArrayCommandPort>("g", "command").write(std::vector<double>{1.0, -0.5}));
  rig.tick(2000);
  EXPECT_NEAR(rig.joint("a").position, 1.0, 1e-3);
  EXPECT_NEAR(rig.joint("b").position, -0.5, 1e-3);
  auto state = rig.port<StatePort<JointGroupControllerState>>("g", "state").read();
  EXPECT_DOUBLE_EQ(state.joints[1].gains.p, 400.0);
  // Gains change at run time through the gains port.
  auto* gains = rig.manager->controller("g")->port_as<PidGainsPort>("gains/a");
  ASSERT_NE(gains, nullptr);
  PidGains g = gains->latest();
  g.p = 50.0;
  ASSERT_TRUE(gains->write(g));
  rig.tick(1);
  EXPECT_DOUBLE_EQ(rig.port<StatePort<JointGroupControllerState>>("g", "state").read().joints[0].gains.p, 50.0);
}

TEST(GroupControllers, EffortGroupPositionNeedsAPidPerJoint) {
  Rig rig(three(), "g: {type: effort_controllers/JointGroupPositionController, joints: [a, b], a: {pid: {p: 1}}}");
  auto r = rig.manager->load_controller("g");
  EXPECT_FALSE(r.ok);
  EXPECT_THAT(r.error, ::testing::HasSubstr("No p gain specified for pid. Namespace: /g/b/pid"));
}

TEST(Pr2Controllers, PositionAndVelocityReadJointAndPid) {
  Rig rig({JointSpec{"p"}, JointSpec{"v", JointType::Continuous}}, R"(
pos: {type: robot_mechanism_controllers/JointPositionController, joint: p, pid: {p: 100, d: 20}}
vel: {type: robot_mechanism_controllers/JointVelocityController, joint: v, pid: {p: 20}}
eff: {type: robot_mechanism_controllers/JointEffortController, joint: v}
)");
  rig.start("pos");
  rig.start("vel");
  ASSERT_TRUE(rig.port<ScalarCommandPort>("pos", "command").write(-0.8));
  ASSERT_TRUE(rig.port<ScalarCommandPort>("vel", "command").write(2.0));
  rig.tick(2000);
  EXPECT_NEAR(rig.joint("p").position, -0.8, 1e-3);
  EXPECT_NEAR(rig.joint("v").velocity, 2.0, 1e-3);
  // PR2 state messages report error = process value - set point.
  ASSERT_TRUE(rig.port<ScalarCommandPort>("pos", "command").write(0.0));
  rig.tick(1);
  auto state = rig.port<StatePort<JointControllerState>>("pos", "state").read();
  EXPECT_NEAR(state.error, state.process_value - state.set_point, 1e-12);
  EXPECT_LT(state.error, 0.0);
  ASSERT_TRUE(rig.manager->load_controller("eff").ok);
}

TEST(JointStateControllerTest, PublishesSnapshotsAtItsRate) {
  Rig rig(three(), R"(
js: {type: joint_state_controller/JointStateController, publish_rate: 50}
v: {type: velocity_controllers/JointGroupVelocityController, joints: [a, b, c]}
)");
  rig.start("js");
  rig.start("v");
  auto& port = rig.port<StatePort<JointStateSnapshot>>("js", "joint_states");
  ASSERT_TRUE(rig.port<ArrayCommandPort>("v", "command").write(std::vector<double>{1.0, 2.0, 3.0}));
  const auto before = port.sequence();
  rig.tick(1000);
  EXPECT_NEAR(static_cast<double>(port.sequence() - before), 50.0, 1.0);
  auto snap = port.read();
  EXPECT_EQ(snap.names, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_DOUBLE_EQ(snap.velocity[2], 3.0);
  EXPECT_NEAR(snap.position[1], 2.0 * snap.stamp, 0.01);
  EXPECT_LE(snap.stamp, rig.time);
  EXPECT_GT(snap.stamp, rig.time - 0.021);
  // It claims nothing: it runs beside the controllers of every joint.
  EXPECT_TRUE(rig.manager->controller_info("js")->claims.empty());
}

TEST(JointStateControllerTest, RequiresAPositiveRate) {
  Rig rig(three(), "a: {type: joint_state_controller/JointStateController}\nb: {type: joint_state_controller/JointStateController, publish_rate: -1}");
  EXPECT_THAT(rig.manager->load_controller("a").error, ::testing::HasSubstr("parameter /a/publish_rate not set"));
  EXPECT_THAT(rig.manager->load_controller("b").error, ::testing::HasSubstr("/b/publish_rate must be a positive"));
}

TEST(Controllers, MissingInterfaceOrJointParametersAreClearErrors) {
  std::vector<JointSpec> joints{JointSpec{"e"}};
  joints[0].interfaces = {HardwareInterface::Effort};
  Rig rig(joints, R"(
p: {type: position_controllers/JointPositionController, joint: e}
n: {type: effort_controllers/JointEffortController}
g: {type: velocity_controllers/JointGroupVelocityController, joints: []}
d: {type: velocity_controllers/JointGroupVelocityController, joints: [e, e]}
u: {type: effort_controllers/JointGroupEffortController, joints: [e, x]}
)");
  EXPECT_THAT(rig.manager->load_controller("p").error,
              ::testing::HasSubstr("joint 'e' (parameter /p/joint) has no hardware_interface::PositionJointInterface"));
  EXPECT_THAT(rig.manager->load_controller("n").error, ::testing::HasSubstr("parameter /n/joint not found"));
  EXPECT_THAT(rig.manager->load_controller("g").error, ::testing::HasSubstr("/g/joints: the list of joint names is empty"));
  EXPECT_THAT(rig.manager->load_controller("d").error, ::testing::HasSubstr("joint 'e' is listed twice"));
  EXPECT_THAT(rig.manager->load_controller("u").error, ::testing::HasSubstr("unknown joint 'x' (parameter /u/joints[1])"));
}

TEST(Ports, TwistPortRejectsNonFiniteComponents) {
  TwistCommandPort port("cmd_vel");
  Twist t;
  t.linear.x = 0.5;
  t.angular.z = -0.1;
  EXPECT_TRUE(port.write(t));
  Twist bad = t;
  bad.angular.y = NAN;
  std::string error;
  EXPECT_FALSE(port.write(bad, &error));
  EXPECT_THAT(error, ::testing::HasSubstr("non-finite twist"));
  EXPECT_EQ(port.count(), 1u);
  EXPECT_DOUBLE_EQ(port.read_from_rt().linear.x, 0.5);
  EXPECT_DOUBLE_EQ(port.read_from_rt().angular.z, -0.1);
}

}  // namespace
}  // namespace mechsim::control
