#include "mechanism/build_mechanism.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "description/transmission_types.hpp"
#include "mechanism/propagation.hpp"
#include "mechanism/transmission_factory.hpp"
#include "mechanism_test_util.hpp"

namespace mechsim::mechanism {
namespace {

using description::JointType;
using ::testing::HasSubstr;

description::RobotModel two_joint_robot() {
  return test::make_robot({test::make_joint("j1", JointType::Revolute, description::JointLimits{-1, 1, 5, 2}),
                           test::make_joint("j2", JointType::Prismatic), test::make_joint("fixed", JointType::Fixed)});
}

// The message of the MechanismError build_mechanism throws, or "" when it does not throw.
std::string build_error(const description::RobotModel& robot) {
  try {
    build_mechanism(robot);
  } catch (const MechanismError& e) {
    return e.what();
  }
  return "";
}

TEST(BuildMechanism, ConnectsJointsAndActuatorsByName) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 10.0));
  robot.transmissions.push_back(test::pr2_simple("t2", "j2", "m2", -4.0));
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.joints.size(), 2u);
  ASSERT_EQ(m.actuators.size(), 2u);
  EXPECT_EQ(m.source, "test.urdf");
  EXPECT_EQ(m.joints[m.joint_index("j1")].transmission, 0);
  EXPECT_EQ(m.joints[m.joint_index("j2")].transmission, 1);
  EXPECT_EQ(m.actuators[m.actuator_index("m2")].transmission, 1);
  EXPECT_EQ(m.joints[0].limits->effort, 5.0);
  EXPECT_EQ(m.joint_index("fixed"), -1);  // no transmission, not a mechanism joint
  MechanismState s = make_state(m);
  s.actuators[1].position = 8.0;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_DOUBLE_EQ(s.joints[1].position, -2.0);
  EXPECT_DOUBLE_EQ(s.joints[0].position, 0.0);
}

TEST(BuildMechanism, RobotWithoutTransmissionsHasAnEmptyMechanism) {
  const MechanismModel m = build_mechanism(two_joint_robot());
  EXPECT_TRUE(m.joints.empty());
  EXPECT_TRUE(m.transmissions.empty());
  MechanismState s = make_state(m);
  propagate_actuator_to_joint_position(m, s);
  enforce_safety_limits(m, s);
}

TEST(BuildMechanism, UnknownTransmissionType) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 1.0, "EffortJointInterface", 12));
  robot.transmissions[0].type = "transmission_interface/WarpDrive";
  const std::string e = build_error(robot);
  EXPECT_THAT(e, HasSubstr("test.urdf:12: transmission 't1' (transmission_interface/WarpDrive)"));
  EXPECT_THAT(e, HasSubstr("unknown transmission type 'transmission_interface/WarpDrive'"));
  EXPECT_THAT(e, HasSubstr("pr2_mechanism_model/PR2GripperTransmission"));  // lists the known ones
}

// The description layer's list of simulated types (a lenient parse leaves out the others) is the
// factory's.
TEST(BuildMechanism, TheDescriptionsTransmissionTypesAreTheFactorys) {
  std::vector<std::string> described(description::kTransmissionTypes.begin(), description::kTransmissionTypes.end());
  std::vector<std::string> built = known_transmission_types();
  std::sort(described.begin(), described.end());
  std::sort(built.begin(), built.end());
  EXPECT_EQ(described, built);
}

TEST(BuildMechanism, MissingJoint) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "nojoint", "m1", 1.0, "EffortJointInterface", 20));
  const std::string e = build_error(robot);
  EXPECT_THAT(e, HasSubstr("test.urdf:22: transmission 't1'"));
  EXPECT_THAT(e, HasSubstr("joint 'nojoint' is not in the robot"));
}

TEST(BuildMechanism, MissingActuator) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::pr2_simple("t1", "j1", "m1", 1.0, 7));
  robot.transmissions[0].actuators.clear();
  EXPECT_THAT(build_error(robot), HasSubstr("test.urdf:7: transmission 't1' (pr2_mechanism_model/SimpleTransmission): no <actuator>"));
}

TEST(BuildMechanism, ZeroReduction) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 0.0, "EffortJointInterface", 20));
  const std::string e = build_error(robot);
  EXPECT_THAT(e, HasSubstr("test.urdf:25: transmission 't1'"));
  EXPECT_THAT(e, HasSubstr("mechanicalReduction is 0"));
  EXPECT_THAT(e, HasSubstr("finite and nonzero"));
}

TEST(BuildMechanism, MissingPr2Reduction) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::pr2_simple("t1", "j1", "m1", std::nullopt, 7));
  EXPECT_THAT(build_error(robot), HasSubstr("mechanicalReduction is missing"));
}

TEST(BuildMechanism, RosControlReductionDefaultsToOne) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", std::nullopt));
  const MechanismModel m = build_mechanism(robot);
  MechanismState s = make_state(m);
  s.actuators[0].position = 0.25;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_DOUBLE_EQ(s.joints[0].position, 0.25);
}

TEST(BuildMechanism, TransmissionsDrivingOneJointWithDifferentReductionsConflict) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 1.0, "EffortJointInterface", 10));
  robot.transmissions.push_back(test::ros_simple("t2", "j1", "m2", 2.0, "EffortJointInterface", 20));
  const std::string error = build_error(robot);
  EXPECT_THAT(error, HasSubstr("test.urdf:22: transmission 't2' (transmission_interface/SimpleTransmission): "
                               "joint 'j1' is already driven by transmission 't1' (line 10) with reduction 1"));
  EXPECT_THAT(error, HasSubstr("this one gives 2 and 0"));
  EXPECT_THAT(error, HasSubstr("conflicting"));
}

// ros_control descriptions give a joint one transmission per interface, often all of one name.
TEST(BuildMechanism, SameNameTransmissionsOnOneJointAddTheirInterfaces) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("j1_trans", "j1", "j1_motor", 160.0, "PositionJointInterface", 10));
  robot.transmissions.push_back(test::ros_simple("j1_trans", "j1", "j1_motor", 160.0, "VelocityJointInterface", 20));
  robot.transmissions.push_back(test::ros_simple("j1_trans", "j1", "j1_motor", 160.0, "EffortJointInterface", 30));
  robot.transmissions.push_back(test::ros_simple("j2_trans", "j2", "j2_motor", 1.0, "EffortJointInterface", 40));
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.transmissions.size(), 2u);
  ASSERT_EQ(m.joints.size(), 2u);
  ASSERT_EQ(m.actuators.size(), 2u);
  const JointInfo& j1 = m.joints[static_cast<std::size_t>(m.joint_index("j1"))];
  EXPECT_EQ(j1.interfaces, (std::vector<HardwareInterface>{HardwareInterface::Position, HardwareInterface::Velocity,
                                                           HardwareInterface::Effort}));
  EXPECT_EQ(j1.transmission, 0);
  EXPECT_EQ(m.joints[static_cast<std::size_t>(m.joint_index("j2"))].transmission, 1);
  MechanismState s = make_state(m);
  s.actuators[0].position = 16.0;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_DOUBLE_EQ(s.joints[0].position, 0.1);  // one actuator, the reduction applied once
}

TEST(BuildMechanism, SecondActuatorOfAJointWithTheSameReductionIsNoSecondMotor) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 2.0, "EffortJointInterface", 10));
  robot.transmissions.push_back(test::ros_simple("t2", "j1", "m2", 2.0, "VelocityJointInterface", 20));
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.actuators.size(), 1u);
  EXPECT_EQ(m.actuators[0].name, "m1");
  EXPECT_EQ(m.actuator_index("m2"), -1);
  EXPECT_EQ(m.joints[0].interfaces, (std::vector<HardwareInterface>{HardwareInterface::Effort, HardwareInterface::Velocity}));
}

TEST(BuildMechanism, ActuatorOfAnotherJointCannotAddAnInterface) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 1.0, "EffortJointInterface", 10));
  robot.transmissions.push_back(test::ros_simple("t2", "j2", "m2", 1.0, "EffortJointInterface", 20));
  robot.transmissions.push_back(test::ros_simple("t3", "j1", "m2", 1.0, "VelocityJointInterface", 30));
  EXPECT_THAT(build_error(robot), HasSubstr("actuator 'm2' already belongs to transmission 't2', which drives another joint"));
}

TEST(BuildMechanism, HardwareInterfaceInTheActuatorIsTheJoints) {
  description::RobotModel robot = two_joint_robot();
  description::Transmission t = test::ros_simple("t1", "j1", "m1", std::nullopt, "", 10);
  t.actuators[0].hardware_interfaces.push_back("hardware_interface/VelocityJointInterface");
  robot.transmissions.push_back(t);
  const MechanismModel m = build_mechanism(robot);
  EXPECT_EQ(m.joints[0].interfaces, (std::vector<HardwareInterface>{HardwareInterface::Velocity}));
}

TEST(BuildMechanism, ActuatorSharedByTwoTransmissions) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 1.0, "EffortJointInterface", 10));
  robot.transmissions.push_back(test::ros_simple("t2", "j2", "m1", 1.0, "EffortJointInterface", 20));
  EXPECT_THAT(build_error(robot), HasSubstr("actuator 'm1' already belongs to transmission 't1'"));
}

TEST(BuildMechanism, FixedJointCannotBeDriven) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "fixed", "m1", 1.0));
  EXPECT_THAT(build_error(robot), HasSubstr("joint 'fixed' is fixed"));
}

TEST(BuildMechanism, RepeatedTransmissionNameOnOtherJointsLoads) {
  description::RobotModel robot = two_joint_robot();
  robot.transmissions.push_back(test::ros_simple("t1", "j1", "m1", 1.0, "EffortJointInterface", 10));
  robot.transmissions.push_back(test::ros_simple("t1", "j2", "m2", 1.0, "EffortJointInterface", 20));
  const MechanismModel m = build_mechanism(robot);
  ASSERT_EQ(m.transmissions.size(), 2u);
  EXPECT_EQ(m.joints[static_cast<std::size_t>(m.joint_index("j2"))].transmission, 1);
}

TEST(BuildMechanism, WristWithoutFlexJoint) {
  description::RobotModel robot = two_joint_robot();
  description::Transmission t;
  t.name = "w";
  t.type = "pr2_mechanism_model/WristTransmission";
  t.line = 50;
  t.actuators = {{"r", "right", 60.0, {}}, {"l", "left", 60.0, {}}};
  t.joints = {{"j2", "roll", {}, 1.0}};
  robot.transmissions.push_back(t);
  EXPECT_THAT(build_error(robot), HasSubstr("test.urdf:50: transmission 'w' (pr2_mechanism_model/WristTransmission): no flex joint"));
  robot.transmissions[0].joints.insert(robot.transmissions[0].joints.begin(), {"j1", "flex", {}, 0.0});
  EXPECT_THAT(build_error(robot), HasSubstr("mechanicalReduction of the flexJoint is 0"));
}

TEST(BuildMechanism, DifferentialNeedsTwoJoints) {
  description::RobotModel robot = two_joint_robot();
  description::Transmission t = test::ros_simple("d", "j1", "m1", 1.0, "EffortJointInterface", 60);
  t.type = "transmission_interface/DifferentialTransmission";
  t.actuators.push_back({"m2", "", 1.0, {}});
  robot.transmissions.push_back(t);
  EXPECT_THAT(build_error(robot),
              HasSubstr("test.urdf:60: transmission 'd' (transmission_interface/DifferentialTransmission): needs exactly 2 <joint> entries, has 1"));
}

TEST(BuildMechanism, BadRoleIsAnError) {
  description::RobotModel robot = two_joint_robot();
  description::Transmission t = test::ros_simple("d", "j1", "m1", 1.0, "EffortJointInterface", 60);
  t.type = "transmission_interface/DifferentialTransmission";
  t.actuators.push_back({"m2", "", 1.0, {}});
  t.joints.push_back({"j2", "", {"EffortJointInterface"}, std::nullopt});
  t.xml.children.push_back(test::xml("joint", {{"name", "j2"}}, 70));
  t.xml.children[0].children.push_back(test::xml("role", {}, 63, "joint1"));
  t.xml.children.back().children.push_back(test::xml("role", {}, 71, "joint3"));
  robot.transmissions.push_back(t);
  EXPECT_THAT(build_error(robot), HasSubstr("test.urdf:71: transmission 'd'"));
  EXPECT_THAT(build_error(robot), HasSubstr("<role>joint3</role> is neither joint1 nor joint2"));
}

}  // namespace
}  // namespace mechsim::mechanism
