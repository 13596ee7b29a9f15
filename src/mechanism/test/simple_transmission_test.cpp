#include "mechanism/simple_transmission.hpp"

#include <gtest/gtest.h>

#include "mechanism/build_mechanism.hpp"
#include "mechanism/propagation.hpp"
#include "mechanism_test_util.hpp"

namespace mechsim::mechanism {
namespace {

using description::JointType;
using test::make_joint;
using test::make_robot;

MechanismModel one_simple(double reduction, double offset) {
  MechanismModel m;
  m.joints.push_back(JointInfo{});
  m.joints[0].name = "j";
  m.actuators.push_back(ActuatorInfo{"a", 0});
  m.transmissions.push_back(std::make_unique<SimpleTransmission>("t", "transmission_interface/SimpleTransmission", 0, 0,
                                                                 reduction, offset));
  return m;
}

TEST(SimpleTransmission, KnownValuesActuatorToJoint) {
  const MechanismModel m = one_simple(-47641.53, 0.25);
  MechanismState s = make_state(m);
  s.actuators[0] = ActuatorState{};
  s.actuators[0].position = 100.0;
  s.actuators[0].velocity = -20.0;
  s.actuators[0].last_measured_effort = 0.01;
  propagate_actuator_to_joint_position(m, s);
  // x_j = x_a / n + x_off, v_j = v_a / n, tau_j = n tau_a
  EXPECT_DOUBLE_EQ(s.joints[0].position, 100.0 / -47641.53 + 0.25);
  EXPECT_DOUBLE_EQ(s.joints[0].velocity, -20.0 / -47641.53);
  EXPECT_DOUBLE_EQ(s.joints[0].measured_effort, 0.01 * -47641.53);
}

TEST(SimpleTransmission, KnownValuesJointToActuatorCommands) {
  const MechanismModel m = one_simple(6.0, -0.5);
  MechanismState s = make_state(m);
  s.joints[0].commanded_effort = 3.0;
  s.joints[0].commanded_position = 1.0;
  s.joints[0].commanded_velocity = 2.0;
  s.joints[0].command_mode = HardwareInterface::Position;
  propagate_joint_to_actuator_effort(m, s);
  EXPECT_DOUBLE_EQ(s.actuators[0].commanded_effort, 0.5);
  EXPECT_DOUBLE_EQ(s.actuators[0].commanded_position, 9.0);  // 6 * (1 - (-0.5))
  EXPECT_DOUBLE_EQ(s.actuators[0].commanded_velocity, 12.0);
  EXPECT_EQ(s.actuators[0].command_mode, HardwareInterface::Position);
}

TEST(SimpleTransmission, ForwardThenBackwardIsIdentity) {
  for (double n : {1.0, -1.0, 63.155, -47641.53, 0.01}) {
    const MechanismModel m = one_simple(n, 0.3);
    MechanismState s = make_state(m);
    s.joints[0].position = 0.7;
    s.joints[0].velocity = -1.3;
    s.joints[0].measured_effort = 4.2;
    s.joints[0].commanded_effort = -2.5;
    s.joints[0].commanded_position = 0.11;
    s.joints[0].commanded_velocity = 0.9;
    const JointState before = s.joints[0];
    propagate_joint_to_actuator_position(m, s);
    s.joints[0] = JointState{};
    propagate_actuator_to_joint_position(m, s);
    EXPECT_NEAR(s.joints[0].position, before.position, 1e-12) << n;
    EXPECT_NEAR(s.joints[0].velocity, before.velocity, 1e-12) << n;
    EXPECT_NEAR(s.joints[0].measured_effort, before.measured_effort, 1e-12) << n;
    s.joints[0].commanded_effort = before.commanded_effort;
    s.joints[0].commanded_position = before.commanded_position;
    s.joints[0].commanded_velocity = before.commanded_velocity;
    propagate_joint_to_actuator_effort(m, s);
    s.joints[0].commanded_effort = s.joints[0].commanded_position = s.joints[0].commanded_velocity = 0.0;
    propagate_actuator_to_joint_effort(m, s);
    EXPECT_NEAR(s.joints[0].commanded_effort, before.commanded_effort, 1e-12) << n;
    EXPECT_NEAR(s.joints[0].commanded_position, before.commanded_position, 1e-12) << n;
    EXPECT_NEAR(s.joints[0].commanded_velocity, before.commanded_velocity, 1e-12) << n;
  }
}

TEST(SimpleTransmission, PreservesPower) {
  const MechanismModel m = one_simple(-17.5, 0.1);
  MechanismState s = make_state(m);
  s.actuators[0].position = 2.0;
  s.actuators[0].velocity = 35.0;
  s.actuators[0].last_measured_effort = 0.2;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_NEAR(test::joint_power(m, s, true), test::actuator_power(s, true), 1e-12);
  EXPECT_NE(test::actuator_power(s, true), 0.0);
}

TEST(SimpleTransmission, BuiltFromRosControlFormat) {
  description::RobotModel robot = make_robot({make_joint("wheel", JointType::Continuous)});
  robot.transmissions.push_back(test::ros_simple("wheel_tran", "wheel", "wheel_motor", 2.0));
  robot.transmissions[0].xml.children[0].children.push_back(test::xml("offset", {}, 3, "0.5"));
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.joints.size(), 1u);
  ASSERT_EQ(m.actuators.size(), 1u);
  ASSERT_EQ(m.transmissions.size(), 1u);
  EXPECT_EQ(m.joint_index("wheel"), 0);
  EXPECT_EQ(m.actuator_index("wheel_motor"), 0);
  EXPECT_EQ(m.joint_index("nope"), -1);
  EXPECT_TRUE(m.joints[0].continuous);
  EXPECT_EQ(m.joints[0].interfaces, std::vector<HardwareInterface>{HardwareInterface::Effort});
  const auto* t = dynamic_cast<const SimpleTransmission*>(m.transmissions[0].get());
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->reduction(), 2.0);
  EXPECT_EQ(t->offset(), 0.5);
}

TEST(SimpleTransmission, Pr2SimulatedActuatedJointCarriesScrewTorque) {
  description::RobotModel robot = make_robot(
      {make_joint("torso_lift_joint", JointType::Prismatic), make_joint("screw", JointType::Continuous)});
  description::Transmission t = test::pr2_simple("torso_trans", "torso_lift_joint", "torso_motor", -47641.53, 10);
  t.joints.push_back(description::TransmissionJoint{"screw", "simulated_actuated", {}, std::nullopt});
  t.xml.children.push_back(test::xml("simulated_actuated_joint", {{"name", "screw"}, {"simulated_reduction", "3141.6"}}, 14));
  robot.transmissions.push_back(t);
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.joints.size(), 2u);
  EXPECT_EQ(m.joints[1].role, JointRole::SimulatedActuated);
  EXPECT_TRUE(m.joints[1].interfaces.empty());
  MechanismState s = make_state(m);
  s.actuators[0].commanded_effort = 0.1;
  propagate_actuator_to_joint_effort(m, s);
  EXPECT_DOUBLE_EQ(s.joints[0].commanded_effort, 0.1 * -47641.53);
  EXPECT_DOUBLE_EQ(s.joints[1].commanded_effort, 0.1 * -47641.53 / 3141.6);
}

}  // namespace
}  // namespace mechsim::mechanism
