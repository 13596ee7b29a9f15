// build_mechanism on descriptions read by the real URDF parser (inline documents): the ros_control
// and PR2 formats arrive as the transmissions expect them, and errors carry the document's lines.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/differential_transmission.hpp"
#include "mechanism/propagation.hpp"
#include "mechanism/simple_transmission.hpp"

namespace mechsim::mechanism {
namespace {

using ::testing::HasSubstr;

// Two revolute joints in a chain plus whatever transmissions are given.
std::string robot_with(const std::string& transmissions) {
  return R"(<?xml version="1.0"?>
<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <link name="l1"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <link name="l2"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <joint name="foo_joint" type="revolute">
    <parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="5" velocity="2"/>
  </joint>
  <joint name="bar_joint" type="continuous">
    <parent link="l1"/><child link="l2"/><axis xyz="0 1 0"/>
  </joint>
)" + transmissions + "</robot>\n";
}

MechanismModel build(const std::string& xml) {
  return build_mechanism(description::parse_urdf_string(xml, "inline.urdf", description::UrdfOptions{}));
}

std::string build_error(const std::string& xml) {
  try {
    build(xml);
  } catch (const MechanismError& e) {
    return e.what();
  }
  return "";
}

TEST(UrdfIntegration, RosControlDifferentialWithRolesReductionsAndOffsets) {
  const MechanismModel m = build(robot_with(R"(
  <transmission name="differential_trans">
    <type>transmission_interface/DifferentialTransmission</type>
    <joint name="bar_joint">
      <role>joint2</role>
      <offset>-0.5</offset>
      <mechanicalReduction>-2</mechanicalReduction>
      <hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>
    </joint>
    <joint name="foo_joint">
      <role>joint1</role>
      <offset>0.5</offset>
      <mechanicalReduction>2</mechanicalReduction>
      <hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>
    </joint>
    <actuator name="foo_actuator"><role>actuator1</role><mechanicalReduction>50</mechanicalReduction></actuator>
    <actuator name="bar_actuator"><role>actuator2</role><mechanicalReduction>-50</mechanicalReduction></actuator>
  </transmission>
)"));
  ASSERT_EQ(m.transmissions.size(), 1u);
  const auto& t = *m.transmissions[0];
  ASSERT_NE(dynamic_cast<const DifferentialTransmission*>(&t), nullptr);
  const int foo = m.joint_index("foo_joint"), bar = m.joint_index("bar_joint");
  EXPECT_EQ(t.joints()[0], foo);
  EXPECT_EQ(t.joints()[1], bar);
  EXPECT_EQ(m.actuators[t.actuators()[0]].name, "foo_actuator");
  EXPECT_EQ(m.joints[foo].interfaces, std::vector<HardwareInterface>{HardwareInterface::Position});
  MechanismState s = make_state(m);
  // Both actuators at 100 rad: w = (100/50, 100/-50) = (2, -2);
  // x_j1 = (2 - 2)/(2*2) + 0.5 = 0.5;  x_j2 = (2 + 2)/(2*-2) - 0.5 = -1.5
  s.actuators[t.actuators()[0]].position = 100.0;
  s.actuators[t.actuators()[1]].position = 100.0;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_DOUBLE_EQ(s.joints[foo].position, 0.5);
  EXPECT_DOUBLE_EQ(s.joints[bar].position, -1.5);
}

TEST(UrdfIntegration, RosControlSimpleWithOffset) {
  const MechanismModel m = build(robot_with(R"(
  <transmission name="t">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="bar_joint">
      <offset>0.25</offset>
      <hardwareInterface>VelocityJointInterface</hardwareInterface>
      <hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>
    </joint>
    <actuator name="bar_motor"><mechanicalReduction>-4</mechanicalReduction></actuator>
  </transmission>
)"));
  const auto* t = dynamic_cast<const SimpleTransmission*>(m.transmissions.at(0).get());
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->reduction(), -4.0);
  EXPECT_EQ(t->offset(), 0.25);
  EXPECT_EQ(m.joints[0].interfaces,
            (std::vector<HardwareInterface>{HardwareInterface::Velocity, HardwareInterface::Effort}));
}

TEST(UrdfIntegration, Pr2WristFormat) {
  const MechanismModel m = build(robot_with(R"(
  <transmission type="pr2_mechanism_model/WristTransmission" name="wrist_trans">
    <rightActuator name="r_motor" mechanicalReduction="60.17142857142857"/>
    <leftActuator name="l_motor" mechanicalReduction="60.17142857142857"/>
    <flexJoint name="foo_joint" mechanicalReduction="-1.0"/>
    <rollJoint name="bar_joint" mechanicalReduction="1.0"/>
  </transmission>
)"));
  MechanismState s = make_state(m);
  const double n = 60.17142857142857;
  s.actuators[m.actuator_index("r_motor")].position = 0.3 * n;
  s.actuators[m.actuator_index("l_motor")].position = -0.1 * n;
  propagate_actuator_to_joint_position(m, s);
  EXPECT_NEAR(s.joints[m.joint_index("foo_joint")].position, -0.2, 1e-14);
  EXPECT_NEAR(s.joints[m.joint_index("bar_joint")].position, -0.1, 1e-14);
}

TEST(UrdfIntegration, ErrorsCarryTheDocumentLine) {
  // Line 14 is the <transmission> element, 17 its <actuator> (the document starts at line 1).
  // (A joint missing from the robot is already a DescriptionError of the parser.)
  const std::string u = build_error(robot_with(R"(
  <transmission name="t2" type="pr2_mechanism_model/BeltTransmission">
    <actuator name="m"/><joint name="foo_joint"/><mechanicalReduction>3</mechanicalReduction>
  </transmission>
)"));
  EXPECT_THAT(u, HasSubstr("inline.urdf:14: transmission 't2' (pr2_mechanism_model/BeltTransmission): unknown "
                           "transmission type"));
  const std::string h = build_error(robot_with(R"(
  <transmission name="t3">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="foo_joint"><hardwareInterface>hardware_interface/ImpedanceJointInterface</hardwareInterface></joint>
    <actuator name="m"><mechanicalReduction>2</mechanicalReduction></actuator>
  </transmission>
)"));
  EXPECT_THAT(h, HasSubstr("inline.urdf:16: transmission 't3' (transmission_interface/SimpleTransmission): joint "
                           "'foo_joint': unknown hardware interface 'hardware_interface/ImpedanceJointInterface'"));
}

}  // namespace
}  // namespace mechsim::mechanism
