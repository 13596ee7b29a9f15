#include "mechanism/pr2_gripper_transmission.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mechanism/build_mechanism.hpp"
#include "mechanism/propagation.hpp"
#include "mechanism_test_util.hpp"

namespace mechsim::mechanism {
namespace {

using description::JointType;

// The PR2 reference URDF's gripper parameters.
GripperGeometry pr2_geometry() {
  GripperGeometry g;
  g.mechanical_reduction = 1.0;
  g.screw_reduction = 0.004;
  g.gear_ratio = 40.095;
  g.theta0 = 0.0628824676201037;
  g.phi0 = 0.5185181221457433;
  g.t0 = -0.0001914;
  g.L0 = 0.0375528;
  g.h = 0.0;
  g.a = 0.0683698;
  g.b = 0.043384900000000004;
  g.r = 0.0915;
  return g;
}

// gap, passive x4, screw; one motor.
MechanismModel gripper_model(GripperGeometry g = pr2_geometry()) {
  MechanismModel m;
  for (const char* n : {"gap", "lf", "rf", "rt", "lt", "screw"}) {
    m.joints.push_back(JointInfo{});
    m.joints.back().name = n;
  }
  for (int i = 1; i <= 4; ++i) m.joints[i].role = JointRole::Passive;
  m.joints[5].role = JointRole::SimulatedActuated;
  m.actuators = {ActuatorInfo{"motor", 0}};
  m.transmissions.push_back(std::make_unique<Pr2GripperTransmission>(
      "g", "pr2_mechanism_model/PR2GripperTransmission", 0, std::vector<int>{1, 2, 3, 4}, 5, -1, 0, g, 3141.6));
  return m;
}

TEST(Pr2GripperTransmission, KnownGapFromMotorAngle) {
  const MechanismModel m = gripper_model();
  MechanismState s = make_state(m);
  const double theta_m = 500.0;  // rad
  s.actuators[0].position = theta_m;
  propagate_actuator_to_joint_position(m, s);

  // By hand: motor revolutions, nut travel, law of cosines, finger angle, half gap.
  const double MR = 500.0 / (2.0 * std::numbers::pi);
  const double L = 0.0375528 + MR * 0.004 / 40.095;
  const double a = 0.0683698, b = 0.043384900000000004;
  const double u = (a * a + b * b - L * L) / (2.0 * a * b);
  const double theta = 0.0628824676201037 - 0.5185181221457433 + std::acos(u);
  const double half_gap = -0.0001914 + 0.0915 * (std::sin(theta) - std::sin(0.0628824676201037));
  EXPECT_NEAR(s.joints[0].position, 2.0 * half_gap, 1e-15);
  for (int i = 1; i <= 4; ++i) EXPECT_NEAR(s.joints[i].position, theta - 0.0628824676201037, 1e-15);
  // A plausible PR2 opening for ~80 motor revolutions.
  EXPECT_GT(s.joints[0].position, 0.01);
  EXPECT_LT(s.joints[0].position, 0.09);
}

TEST(Pr2GripperTransmission, ClosedAtMotorZeroAndOpensMonotonically) {
  const Pr2GripperTransmission t("g", "x", 0, {}, -1, -1, 0, pr2_geometry());
  // The PR2's t0 is chosen so that the gripper is closed (gap within 0.01 mm of 0) at motor zero.
  EXPECT_NEAR(t.at_motor(0.0).gap, 0.0, 1e-5);
  double previous = -1.0;
  for (double th = 0.0; th <= 1500.0; th += 50.0) {
    const double gap = t.at_motor(th).gap;
    EXPECT_GT(gap, previous) << th;
    previous = gap;
  }
  EXPECT_GT(previous, 0.08);  // fully open PR2 gripper: about 0.09 m
}

TEST(Pr2GripperTransmission, JacobiansMatchFiniteDifferences) {
  const Pr2GripperTransmission t("g", "x", 0, {}, -1, -1, 0, pr2_geometry());
  for (double th : {100.0, 500.0, 1000.0}) {
    const double h = 1e-2;  // rad; the motor angle's scale is 10^3 rad
    const double dgap = (t.at_motor(th + h).gap - t.at_motor(th - h).gap) / (2 * h);
    const double dfin = (t.at_motor(th + h).finger - t.at_motor(th - h).finger) / (2 * h);
    EXPECT_NEAR(t.at_motor(th).gap_jacobian, dgap, 1e-7 * std::abs(dgap)) << th;
    EXPECT_NEAR(t.at_motor(th).finger_jacobian, dfin, 1e-7 * std::abs(dfin)) << th;
  }
}

TEST(Pr2GripperTransmission, MotorAngleInvertsGap) {
  const Pr2GripperTransmission t("g", "x", 0, {}, -1, -1, 0, pr2_geometry());
  for (double th : {1.0, 100.0, 700.0, 1400.0}) EXPECT_NEAR(t.motor_angle(t.at_motor(th).gap), th, 1e-9) << th;
}

TEST(Pr2GripperTransmission, RoundTrips) {
  const MechanismModel m = gripper_model();
  MechanismState s = make_state(m);
  for (double seed : {0.3, 2.0, 5.5}) {
    EXPECT_LT(test::joint_round_trip_error(m, s, seed), 1e-12) << seed;
    // Motor angles are ~10^3 rad here: the identity holds to 1e-12 relative.
    for (ActuatorState& a : s.actuators) a = ActuatorState{};
    s.actuators[0].position = 700.0 + 100.0 * seed;
    s.actuators[0].velocity = 30.0;
    s.actuators[0].last_measured_effort = 0.05;
    s.actuators[0].commanded_effort = -0.02;
    s.actuators[0].commanded_position = 650.0;
    s.actuators[0].commanded_velocity = -12.0;
    const ActuatorState before = s.actuators[0];
    propagate_actuator_to_joint_position(m, s);
    propagate_actuator_to_joint_effort(m, s);
    s.actuators[0] = ActuatorState{};
    propagate_joint_to_actuator_position(m, s);
    propagate_joint_to_actuator_effort(m, s);
    EXPECT_NEAR(s.actuators[0].position, before.position, 1e-12 * before.position);
    EXPECT_NEAR(s.actuators[0].velocity, before.velocity, 1e-12 * std::abs(before.velocity));
    EXPECT_NEAR(s.actuators[0].last_measured_effort, before.last_measured_effort, 1e-12);
    EXPECT_NEAR(s.actuators[0].commanded_effort, before.commanded_effort, 1e-12);
    EXPECT_NEAR(s.actuators[0].commanded_position, before.commanded_position, 1e-12 * before.commanded_position);
    EXPECT_NEAR(s.actuators[0].commanded_velocity, before.commanded_velocity, 1e-12 * std::abs(before.commanded_velocity));
  }
}

TEST(Pr2GripperTransmission, PreservesPowerOnTheGapAndOnTheFingers) {
  const MechanismModel m = gripper_model();
  MechanismState s = make_state(m);
  s.actuators[0].position = 800.0;
  s.actuators[0].velocity = 25.0;  // rad/s
  s.actuators[0].last_measured_effort = 0.04;  // N m
  propagate_actuator_to_joint_position(m, s);
  const double motor_power = 25.0 * 0.04;
  EXPECT_NEAR(test::joint_power(m, s, true, JointRole::Actuated), motor_power, 1e-12);
  EXPECT_NEAR(test::joint_power(m, s, true, JointRole::Passive), motor_power, 1e-12);
  // Commanded gap force -> motor torque, at the same state.
  s.joints[0].commanded_effort = -30.0;  // N, closing
  propagate_joint_to_actuator_effort(m, s);
  EXPECT_NEAR(s.actuators[0].commanded_effort * 25.0, -30.0 * s.joints[0].velocity, 1e-12);
  // PR2 value for n = 1: gap force = motor torque * pi / (dt/dMR).
  const Pr2GripperTransmission& t = static_cast<const Pr2GripperTransmission&>(*m.transmissions[0]);
  const double dt_dmr = t.at_motor(800.0).gap_jacobian * 2.0 * std::numbers::pi / 2.0;
  EXPECT_NEAR(s.joints[0].measured_effort, 0.04 * std::numbers::pi / dt_dmr, 1e-9);
}

TEST(Pr2GripperTransmission, PreservesPowerWithAnyReduction) {
  GripperGeometry g = pr2_geometry();
  g.mechanical_reduction = -2.5;  // the PR2 uses 1, where its own effort map is also power preserving
  const MechanismModel m = gripper_model(g);
  MechanismState s = make_state(m);
  s.actuators[0].position = -2000.0;
  s.actuators[0].velocity = -40.0;
  s.actuators[0].last_measured_effort = 0.03;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_GT(s.joints[0].position, 0.01);  // the reduction's sign turns the motor the other way
  EXPECT_NEAR(test::joint_power(m, s, true, JointRole::Actuated), -40.0 * 0.03, 1e-12);
  EXPECT_LT(test::joint_round_trip_error(m, s, 0.9), 1e-12);
}

TEST(Pr2GripperTransmission, ScrewJointGetsPr2ScrewTorque) {
  const MechanismModel m = gripper_model();
  MechanismState s = make_state(m);
  s.actuators[0].position = 600.0;
  s.actuators[0].commanded_effort = 0.1;
  propagate_actuator_to_joint_effort(m, s);
  EXPECT_NEAR(s.joints[5].commanded_effort, 2.0 * s.joints[0].commanded_effort / 3141.6, 1e-15);
  EXPECT_NE(s.joints[5].commanded_effort, 0.0);
}

description::RobotModel pr2_gripper_robot() {
  using description::JointLimits;
  description::RobotModel robot = test::make_robot({
      test::make_joint("r_gripper_joint", JointType::Prismatic, JointLimits{0.0, 0.09, 1000.0, 0.2}, std::nullopt, 2354),
      test::make_joint("r_gripper_l_finger_joint", JointType::Revolute, JointLimits{0.0, 0.548, 1000, 0.5}),
      test::make_joint("r_gripper_r_finger_joint", JointType::Revolute, JointLimits{0.0, 0.548, 1000, 0.5}),
      test::make_joint("r_gripper_motor_screw_joint", JointType::Continuous),
      test::make_joint("r_gripper_motor_slider_joint", JointType::Prismatic, JointLimits{-0.1, 0.1, 1000, 0.2}),
  });
  description::Transmission t;
  t.name = "r_gripper_trans";
  t.type = "pr2_mechanism_model/PR2GripperTransmission";
  t.line = 2200;
  t.actuators = {{"r_gripper_motor", "", std::nullopt, {}}};
  t.joints = {{"r_gripper_joint", "gap", {}, 1.0},
              {"r_gripper_l_finger_joint", "passive", {}, std::nullopt},
              {"r_gripper_r_finger_joint", "passive", {}, std::nullopt},
              {"r_gripper_motor_screw_joint", "simulated_actuated", {}, std::nullopt}};
  t.xml = test::xml("transmission", {{"name", t.name}}, 2200);
  t.xml.children.push_back(test::xml("actuator", {{"name", "r_gripper_motor"}}, 2201));
  t.xml.children.push_back(test::xml("gap_joint",
                                     {{"name", "r_gripper_joint"},
                                      {"L0", "0.0375528"},
                                      {"a", "0.0683698"},
                                      {"b", "0.043384900000000004"},
                                      {"gear_ratio", "40.095"},
                                      {"h", "0.0"},
                                      {"mechanical_reduction", "1.0"},
                                      {"phi0", "0.5185181221457433"},
                                      {"r", "0.0915"},
                                      {"screw_reduction", "0.004"},
                                      {"t0", "-0.0001914"},
                                      {"theta0", "0.0628824676201037"}},
                                     2202));
  t.xml.children.push_back(test::xml("passive_joint", {{"name", "r_gripper_l_finger_joint"}}, 2207));
  t.xml.children.push_back(test::xml("passive_joint", {{"name", "r_gripper_r_finger_joint"}}, 2208));
  t.xml.children.push_back(test::xml("simulated_actuated_joint",
                                     {{"name", "r_gripper_motor_screw_joint"},
                                      {"passive_actuated_joint", "r_gripper_motor_slider_joint"},
                                      {"simulated_reduction", "3141.6"}},
                                     2211));
  robot.transmissions.push_back(t);
  return robot;
}

TEST(Pr2GripperTransmission, BuiltFromPr2Format) {
  const MechanismModel m = build_mechanism(pr2_gripper_robot());
  ASSERT_EQ(m.joints.size(), 5u);
  EXPECT_EQ(m.joints[0].name, "r_gripper_joint");
  EXPECT_EQ(m.joints[0].role, JointRole::Actuated);
  EXPECT_EQ(m.joints[0].interfaces, std::vector<HardwareInterface>{HardwareInterface::Effort});
  EXPECT_EQ(m.joints[1].role, JointRole::Passive);
  EXPECT_TRUE(m.joints[1].interfaces.empty());
  EXPECT_EQ(m.joints[3].name, "r_gripper_motor_screw_joint");
  EXPECT_EQ(m.joints[3].role, JointRole::SimulatedActuated);
  EXPECT_EQ(m.joints[4].name, "r_gripper_motor_slider_joint");
  EXPECT_EQ(m.joints[4].role, JointRole::SimulatedActuated);
  const auto* t = dynamic_cast<const Pr2GripperTransmission*>(m.transmissions[0].get());
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->geometry().gear_ratio, 40.095);
  EXPECT_EQ(t->geometry().r, 0.0915);
  MechanismState s = make_state(m);
  s.actuators[0].position = 500.0;
  propagate_actuator_to_joint_position(m, s);
  const MechanismModel reference = gripper_model();
  MechanismState rs = make_state(reference);
  rs.actuators[0].position = 500.0;
  propagate_actuator_to_joint_position(reference, rs);
  EXPECT_DOUBLE_EQ(s.joints[0].position, rs.joints[0].position);
}

TEST(Pr2GripperTransmission, BadGeometryIsAnErrorNamingTheParameter) {
  description::RobotModel robot = pr2_gripper_robot();
  robot.transmissions[0].xml.children[1].attributes["gear_ratio"] = "0";
  try {
    build_mechanism(robot);
    FAIL() << "expected a MechanismError";
  } catch (const MechanismError& e) {
    EXPECT_NE(std::string(e.what()).find("test.urdf:2202: transmission 'r_gripper_trans'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("gear_ratio"), std::string::npos) << e.what();
  }
  robot = pr2_gripper_robot();
  robot.transmissions[0].xml.children[1].attributes["r"] = "abc";
  EXPECT_THROW(build_mechanism(robot), MechanismError);
}

}  // namespace
}  // namespace mechsim::mechanism
