#include "mechanism/hardware_interface.hpp"

#include <gtest/gtest.h>

#include "mechanism/build_mechanism.hpp"
#include "mechanism_test_util.hpp"

namespace mechsim::mechanism {
namespace {

using description::JointType;

TEST(HardwareInterface, ParsesRosControlNamesLongAndShort) {
  EXPECT_EQ(parse_hardware_interface("hardware_interface/EffortJointInterface"), InterfaceName::Effort);
  EXPECT_EQ(parse_hardware_interface("EffortJointInterface"), InterfaceName::Effort);
  EXPECT_EQ(parse_hardware_interface(" hardware_interface/PositionJointInterface\n"), InterfaceName::Position);
  EXPECT_EQ(parse_hardware_interface("PositionJointInterface"), InterfaceName::Position);
  EXPECT_EQ(parse_hardware_interface("hardware_interface/VelocityJointInterface"), InterfaceName::Velocity);
  EXPECT_EQ(parse_hardware_interface("VelocityJointInterface"), InterfaceName::Velocity);
  EXPECT_EQ(parse_hardware_interface("hardware_interface/JointStateInterface"), InterfaceName::StateOnly);
  EXPECT_EQ(parse_hardware_interface("effort"), InterfaceName::Effort);
  EXPECT_EQ(parse_hardware_interface("velocity"), InterfaceName::Velocity);
}

TEST(HardwareInterface, RejectsUnknownNames) {
  EXPECT_FALSE(parse_hardware_interface("hardware_interface/TorqueJointInterface"));
  EXPECT_FALSE(parse_hardware_interface("effortjointinterface"));
  EXPECT_FALSE(parse_hardware_interface("other_package/EffortJointInterface"));
  EXPECT_FALSE(parse_hardware_interface(""));
  EXPECT_EQ(command_interface(InterfaceName::StateOnly), std::nullopt);
  EXPECT_EQ(command_interface(InterfaceName::Velocity), HardwareInterface::Velocity);
}

description::RobotModel one_joint_robot(const description::Transmission& t) {
  description::RobotModel robot = test::make_robot({test::make_joint("j", JointType::Revolute)});
  robot.transmissions.push_back(t);
  return robot;
}

TEST(HardwareInterface, JointGetsTheInterfacesItsTransmissionNames) {
  description::Transmission t = test::ros_simple("t", "j", "a", 1.0, "hardware_interface/PositionJointInterface", 5);
  t.joints[0].hardware_interfaces.push_back("VelocityJointInterface");
  t.joints[0].hardware_interfaces.push_back("PositionJointInterface");  // duplicate, kept once
  t.joints[0].hardware_interfaces.push_back("hardware_interface/JointStateInterface");  // read only
  const MechanismModel m = build_mechanism(one_joint_robot(t));
  EXPECT_EQ(m.joints[0].interfaces,
            (std::vector<HardwareInterface>{HardwareInterface::Position, HardwareInterface::Velocity}));
  EXPECT_TRUE(m.joints[0].has_interface(HardwareInterface::Velocity));
  EXPECT_FALSE(m.joints[0].has_interface(HardwareInterface::Effort));
}

TEST(HardwareInterface, Pr2TransmissionsGiveEffort) {
  const MechanismModel m = build_mechanism(one_joint_robot(test::pr2_simple("t", "j", "a", 6.0)));
  EXPECT_EQ(m.joints[0].interfaces, std::vector<HardwareInterface>{HardwareInterface::Effort});
}

TEST(HardwareInterface, UnknownNameIsAnErrorNamingTransmissionJointAndLine) {
  const description::Transmission t = test::ros_simple("arm_tran", "j", "a", 1.0, "hardware_interface/FooInterface", 30);
  try {
    build_mechanism(one_joint_robot(t));
    FAIL() << "expected a MechanismError";
  } catch (const MechanismError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("test.urdf:32: transmission 'arm_tran' (transmission_interface/SimpleTransmission)"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("joint 'j'"), std::string::npos) << what;
    EXPECT_NE(what.find("'hardware_interface/FooInterface'"), std::string::npos) << what;
    EXPECT_EQ(e.line(), 32);
    EXPECT_EQ(e.transmission(), "arm_tran");
    EXPECT_EQ(e.element(), "j");
  }
}

TEST(HardwareInterface, UnknownActuatorInterfaceIsAnError) {
  description::Transmission t = test::ros_simple("t", "j", "a", 1.0, "EffortJointInterface", 30);
  t.actuators[0].hardware_interfaces.push_back("EffortActuatorInterfacee");
  EXPECT_THROW(build_mechanism(one_joint_robot(t)), MechanismError);
}

TEST(HardwareInterface, RosControlJointWithoutInterfaceIsAnError) {
  const description::Transmission t = test::ros_simple("t", "j", "a", 1.0, "", 30);
  try {
    build_mechanism(one_joint_robot(t));
    FAIL() << "expected a MechanismError";
  } catch (const MechanismError& e) {
    EXPECT_NE(std::string(e.what()).find("names no <hardwareInterface>"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mechsim::mechanism
