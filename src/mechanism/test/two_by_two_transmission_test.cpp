// DifferentialTransmission, FourBarLinkageTransmission and the PR2 wrist: known values from the
// equations in their headers, round trips, power.
#include <gtest/gtest.h>

#include <cmath>

#include "mechanism/build_mechanism.hpp"
#include "mechanism/differential_transmission.hpp"
#include "mechanism/four_bar_transmission.hpp"
#include "mechanism/pr2_wrist_transmission.hpp"
#include "mechanism/propagation.hpp"
#include "mechanism_test_util.hpp"

namespace mechsim::mechanism {
namespace {

using description::JointType;

template <typename T>
MechanismModel pair_model(std::array<double, 2> na, std::array<double, 2> nj, std::array<double, 2> off) {
  MechanismModel m;
  for (const char* n : {"j1", "j2"}) {
    m.joints.push_back(JointInfo{});
    m.joints.back().name = n;
  }
  m.actuators = {ActuatorInfo{"a1", 0}, ActuatorInfo{"a2", 0}};
  if constexpr (std::is_same_v<T, Pr2WristTransmission>) {
    (void)off;
    m.transmissions.push_back(std::make_unique<T>("t", "pr2_mechanism_model/WristTransmission", std::array{0, 1},
                                                  std::array{0, 1}, na, nj));
  } else {
    m.transmissions.push_back(std::make_unique<T>("t", "ros", std::array{0, 1}, std::array{0, 1}, na, nj, off));
  }
  return m;
}

void set_actuators(MechanismState& s, std::array<double, 2> x, std::array<double, 2> v, std::array<double, 2> tau) {
  for (int i = 0; i < 2; ++i) {
    s.actuators[i].position = x[i];
    s.actuators[i].velocity = v[i];
    s.actuators[i].last_measured_effort = tau[i];
  }
}

TEST(DifferentialTransmission, KnownValues) {
  const MechanismModel m = pair_model<DifferentialTransmission>({2.0, 3.0}, {4.0, 5.0}, {0.1, -0.2});
  MechanismState s = make_state(m);
  set_actuators(s, {1.2, -0.6}, {1.2, -0.6}, {0.5, -1.0});
  propagate_actuator_to_joint_position(m, s);
  // w = (1.2/2, -0.6/3) = (0.6, -0.2); x_j1 = (0.6 - 0.2)/(2*4) + 0.1; x_j2 = (0.6 + 0.2)/(2*5) - 0.2
  EXPECT_NEAR(s.joints[0].position, 0.15, 1e-15);
  EXPECT_NEAR(s.joints[1].position, -0.12, 1e-15);
  EXPECT_NEAR(s.joints[0].velocity, 0.05, 1e-15);
  EXPECT_NEAR(s.joints[1].velocity, 0.08, 1e-15);
  // A = (2*0.5, 3*-1) = (1, -3); tau_j1 = 4 (1 - 3); tau_j2 = 5 (1 + 3)
  EXPECT_NEAR(s.joints[0].measured_effort, -8.0, 1e-14);
  EXPECT_NEAR(s.joints[1].measured_effort, 20.0, 1e-14);
}

TEST(DifferentialTransmission, EqualActuatorMotionMovesOnlyJoint1) {
  const MechanismModel m = pair_model<DifferentialTransmission>({1.0, 1.0}, {1.0, 1.0}, {0.0, 0.0});
  MechanismState s = make_state(m);
  set_actuators(s, {1.0, 1.0}, {0.0, 0.0}, {0.0, 0.0});
  propagate_actuator_to_joint_position(m, s);
  EXPECT_DOUBLE_EQ(s.joints[0].position, 1.0);
  EXPECT_DOUBLE_EQ(s.joints[1].position, 0.0);
}

TEST(FourBarLinkageTransmission, KnownValues) {
  const MechanismModel m = pair_model<FourBarLinkageTransmission>({2.0, 3.0}, {4.0, 5.0}, {0.1, -0.2});
  MechanismState s = make_state(m);
  set_actuators(s, {8.0, 6.0}, {8.0, 6.0}, {0.5, -1.0});
  propagate_actuator_to_joint_position(m, s);
  // x_j1 = 8/(4*2) + 0.1; x_j2 = (6/3 - 8/(4*2))/5 - 0.2
  EXPECT_NEAR(s.joints[0].position, 1.1, 1e-15);
  EXPECT_NEAR(s.joints[1].position, 0.0, 1e-15);
  EXPECT_NEAR(s.joints[0].velocity, 1.0, 1e-15);
  EXPECT_NEAR(s.joints[1].velocity, 0.2, 1e-15);
  // tau_j1 = 4*2*0.5 + 3*(-1); tau_j2 = 5*3*(-1)
  EXPECT_NEAR(s.joints[0].measured_effort, 1.0, 1e-14);
  EXPECT_NEAR(s.joints[1].measured_effort, -15.0, 1e-14);
}

TEST(FourBarLinkageTransmission, Joint1DependsOnActuator1Only) {
  const MechanismModel m = pair_model<FourBarLinkageTransmission>({2.0, 3.0}, {4.0, 5.0}, {0.0, 0.0});
  MechanismState s = make_state(m);
  set_actuators(s, {0.0, 7.0}, {0.0, 0.0}, {0.0, 0.0});
  propagate_actuator_to_joint_position(m, s);
  EXPECT_DOUBLE_EQ(s.joints[0].position, 0.0);
  EXPECT_NEAR(s.joints[1].position, 7.0 / 3.0 / 5.0, 1e-15);
}

TEST(Pr2WristTransmission, KnownValuesWithPr2Reductions) {
  const double n = 624.0 / 35.0 * 54.0 / 16.0;
  const MechanismModel m = pair_model<Pr2WristTransmission>({n, n}, {-1.0, 1.0}, {});
  MechanismState s = make_state(m);
  // u = x_r/n = 0.3, w = x_l/n = -0.1
  set_actuators(s, {0.3 * n, -0.1 * n}, {0.3 * n, -0.1 * n}, {0.2, 0.1});
  propagate_actuator_to_joint_position(m, s);
  // flex = (u - w)/(2 * -1) = -0.2; roll = (-u - w)/(2 * 1) = -0.1
  EXPECT_NEAR(s.joints[0].position, -0.2, 1e-14);
  EXPECT_NEAR(s.joints[1].position, -0.1, 1e-14);
  EXPECT_NEAR(s.joints[0].velocity, -0.2, 1e-14);
  // tau_flex = -1 (n 0.2 - n 0.1); tau_roll = (-n 0.2 - n 0.1)
  EXPECT_NEAR(s.joints[0].measured_effort, -0.1 * n, 1e-12);
  EXPECT_NEAR(s.joints[1].measured_effort, -0.3 * n, 1e-12);
}

TEST(Pr2WristTransmission, MotorsTurningTogetherRollOnly) {
  const double n = 60.0;
  const MechanismModel m = pair_model<Pr2WristTransmission>({n, n}, {-1.0, 1.0}, {});
  MechanismState s = make_state(m);
  set_actuators(s, {-n, -n}, {0.0, 0.0}, {0.0, 0.0});
  propagate_actuator_to_joint_position(m, s);
  EXPECT_NEAR(s.joints[0].position, 0.0, 1e-15);
  EXPECT_NEAR(s.joints[1].position, 1.0, 1e-15);
}

template <typename T>
void expect_round_trips_and_power(std::array<double, 2> na, std::array<double, 2> nj, std::array<double, 2> off) {
  const MechanismModel m = pair_model<T>(na, nj, off);
  MechanismState s = make_state(m);
  for (double seed : {0.1, 1.7, 4.2}) {
    EXPECT_LT(test::joint_round_trip_error(m, s, seed), 1e-12) << seed;
    EXPECT_LT(test::actuator_round_trip_error(m, s, seed), 1e-12) << seed;
    propagate_actuator_to_joint_position(m, s);
    EXPECT_NEAR(test::joint_power(m, s, true), test::actuator_power(s, true), 1e-12);
    // Commands: joint efforts -> actuator efforts, at the same velocities.
    s.joints[0].commanded_effort = 1.5;
    s.joints[1].commanded_effort = -0.7;
    propagate_joint_to_actuator_effort(m, s);
    EXPECT_NEAR(test::joint_power(m, s, false), test::actuator_power(s, false), 1e-12);
    EXPECT_NE(test::actuator_power(s, false), 0.0);
  }
}

TEST(DifferentialTransmission, RoundTripsAndPower) {
  expect_round_trips_and_power<DifferentialTransmission>({2.0, -3.0}, {4.0, 0.5}, {0.1, -0.2});
}
TEST(FourBarLinkageTransmission, RoundTripsAndPower) {
  expect_round_trips_and_power<FourBarLinkageTransmission>({2.0, -3.0}, {4.0, 0.5}, {0.1, -0.2});
}
TEST(Pr2WristTransmission, RoundTripsAndPower) {
  expect_round_trips_and_power<Pr2WristTransmission>({60.17142857142857, 60.17142857142857}, {-1.0, 1.0}, {});
}

TEST(Pr2WristTransmission, MixedCommandModesFallBackToEffortOnActuators) {
  const MechanismModel m = pair_model<Pr2WristTransmission>({60.0, 60.0}, {-1.0, 1.0}, {});
  MechanismState s = make_state(m);
  s.joints[0].command_mode = HardwareInterface::Position;
  s.joints[1].command_mode = HardwareInterface::Position;
  propagate_joint_to_actuator_effort(m, s);
  EXPECT_EQ(s.actuators[0].command_mode, HardwareInterface::Position);
  s.joints[1].command_mode = HardwareInterface::Effort;
  propagate_joint_to_actuator_effort(m, s);
  EXPECT_EQ(s.actuators[0].command_mode, HardwareInterface::Effort);
  EXPECT_EQ(s.actuators[1].command_mode, HardwareInterface::Effort);
}

description::Transmission ros_pair(const std::string& type, bool with_roles) {
  description::Transmission t;
  t.name = "pair_trans";
  t.type = type;
  t.line = 40;
  t.xml = test::xml("transmission", {{"name", t.name}}, 40);
  // Written in reverse order so that the roles matter.
  const char* joints[] = {"j2", "j1"};
  const char* actuators[] = {"a2", "a1"};
  for (int i = 0; i < 2; ++i) {
    t.actuators.push_back(description::TransmissionActuator{actuators[i], "", i == 0 ? 3.0 : 2.0, {}});
    description::XmlNode ax = test::xml("actuator", {{"name", actuators[i]}}, 41 + i);
    if (with_roles) ax.children.push_back(test::xml("role", {}, 41 + i, i == 0 ? "actuator2" : "actuator1"));
    t.xml.children.push_back(ax);
  }
  for (int i = 0; i < 2; ++i) {
    t.joints.push_back(description::TransmissionJoint{joints[i], "", {"hardware_interface/EffortJointInterface"},
                                                      i == 0 ? 5.0 : 4.0});
    description::XmlNode jx = test::xml("joint", {{"name", joints[i]}}, 45 + i);
    if (with_roles) jx.children.push_back(test::xml("role", {}, 45 + i, i == 0 ? "joint2" : "joint1"));
    jx.children.push_back(test::xml("offset", {}, 45 + i, i == 0 ? "-0.2" : "0.1"));
    t.xml.children.push_back(jx);
  }
  return t;
}

TEST(DifferentialTransmission, BuiltWithRolesFromUrdf) {
  description::RobotModel robot = test::make_robot({test::make_joint("j1", JointType::Revolute, description::JointLimits{-1, 1, 10, 1}),
                                                    test::make_joint("j2", JointType::Continuous)});
  robot.transmissions.push_back(ros_pair("transmission_interface/DifferentialTransmission", true));
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.transmissions.size(), 1u);
  const auto& t = *m.transmissions[0];
  // joint1 and actuator1 come first whatever the document order.
  EXPECT_EQ(m.joints[t.joints()[0]].name, "j1");
  EXPECT_EQ(m.joints[t.joints()[1]].name, "j2");
  EXPECT_EQ(m.actuators[t.actuators()[0]].name, "a1");
  EXPECT_EQ(m.actuators[t.actuators()[1]].name, "a2");
  MechanismState s = make_state(m);
  s.actuators[t.actuators()[0]].position = 1.2;
  s.actuators[t.actuators()[1]].position = -0.6;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_NEAR(s.joints[t.joints()[0]].position, 0.15, 1e-15);  // same numbers as KnownValues
  EXPECT_NEAR(s.joints[t.joints()[1]].position, -0.12, 1e-15);
}

TEST(FourBarLinkageTransmission, BuiltInDocumentOrderWithoutRoles) {
  description::RobotModel robot =
      test::make_robot({test::make_joint("j1", JointType::Continuous), test::make_joint("j2", JointType::Continuous)});
  robot.transmissions.push_back(ros_pair("transmission_interface/FourBarLinkageTransmission", false));
  const MechanismModel m = build_mechanism(robot);
  const auto& t = *m.transmissions[0];
  EXPECT_EQ(m.joints[t.joints()[0]].name, "j2");
  EXPECT_EQ(m.actuators[t.actuators()[0]].name, "a2");
  EXPECT_NE(dynamic_cast<const FourBarLinkageTransmission*>(&t), nullptr);
}

TEST(Pr2WristTransmission, BuiltFromPr2Format) {
  description::RobotModel robot = test::make_robot(
      {test::make_joint("r_wrist_flex_joint", JointType::Revolute), test::make_joint("r_wrist_roll_joint", JointType::Continuous)});
  description::Transmission t;
  t.name = "r_wrist_trans";
  t.type = "pr2_mechanism_model/WristTransmission";
  t.line = 1866;
  t.actuators = {{"r_wrist_r_motor", "right", 60.17142857142857, {}}, {"r_wrist_l_motor", "left", 60.17142857142857, {}}};
  t.joints = {{"r_wrist_flex_joint", "flex", {}, -1.0}, {"r_wrist_roll_joint", "roll", {}, 1.0}};
  robot.transmissions.push_back(t);
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.joints.size(), 2u);
  EXPECT_EQ(m.joints[0].name, "r_wrist_flex_joint");
  EXPECT_EQ(m.joints[0].interfaces, std::vector<HardwareInterface>{HardwareInterface::Effort});
  EXPECT_EQ(m.actuators[0].name, "r_wrist_r_motor");
  EXPECT_NE(dynamic_cast<const Pr2WristTransmission*>(m.transmissions[0].get()), nullptr);
}

}  // namespace
}  // namespace mechsim::mechanism
