// Transmissions (ros_control and PR2 formats) and gazebo extensions read beside urdfdom.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A two-joint chain with a wrist-like pair, used with different extension sections.
std::string robot_with(const std::string& extensions) {
  return R"(<robot name="r">
  <link name="base"/>
  <joint name="flex" type="revolute">
    <parent link="base"/><child link="l1"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="5" velocity="2"/>
  </joint>
  <link name="l1"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="roll" type="continuous">
    <parent link="l1"/><child link="l2"/><axis xyz="1 0 0"/>
  </joint>
  <link name="l2"/>
)" + extensions + "\n</robot>\n";
}

TEST(UrdfTransmissions, ReadsTheRosControlFormat) {
  const RobotModel m = parse_urdf_string(robot_with(R"(
  <transmission name="flex_tran">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="flex">
      <hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>
      <hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>
    </joint>
    <actuator name="flex_motor">
      <hardwareInterface>EffortJointInterface</hardwareInterface>
      <mechanicalReduction>50</mechanicalReduction>
    </actuator>
  </transmission>)"),
                                         "r.urdf", UrdfOptions{});
  ASSERT_EQ(m.transmissions.size(), 1u);
  const Transmission& t = m.transmissions[0];
  EXPECT_EQ(t.name, "flex_tran");
  EXPECT_EQ(t.type, "transmission_interface/SimpleTransmission");
  EXPECT_EQ(t.line, 13);
  ASSERT_EQ(t.joints.size(), 1u);
  EXPECT_EQ(t.joints[0].name, "flex");
  EXPECT_EQ(t.joints[0].role, "");
  EXPECT_THAT(t.joints[0].hardware_interfaces,
              ElementsAre("hardware_interface/EffortJointInterface", "hardware_interface/PositionJointInterface"));
  ASSERT_EQ(t.actuators.size(), 1u);
  EXPECT_EQ(t.actuators[0].name, "flex_motor");
  ASSERT_TRUE(t.actuators[0].mechanical_reduction.has_value());
  EXPECT_DOUBLE_EQ(*t.actuators[0].mechanical_reduction, 50.0);
  EXPECT_THAT(t.actuators[0].hardware_interfaces, ElementsAre("EffortJointInterface"));
  EXPECT_FALSE(t.mechanical_reduction.has_value());
  // The whole element is kept.
  EXPECT_EQ(t.xml.name, "transmission");
  EXPECT_EQ(t.xml.line, 13);
  ASSERT_NE(t.xml.child("actuator"), nullptr);
  EXPECT_EQ(t.xml.child("actuator")->line, 19);
}

TEST(UrdfTransmissions, ReadsThePr2SimpleAndWristFormats) {
  const RobotModel m = parse_urdf_string(robot_with(R"(
  <transmission name="simple" type="pr2_mechanism_model/SimpleTransmission">
    <actuator name="roll_motor"/>
    <joint name="roll"/>
    <mechanicalReduction>-79.2</mechanicalReduction>
    <compensator k_belt="4000.0" kd_motor="15.0" lambda_combined="0.0"/>
  </transmission>
  <transmission name="wrist" type="pr2_mechanism_model/WristTransmission">
    <rightActuator mechanicalReduction="60.17" name="r_motor"/>
    <leftActuator mechanicalReduction="60.17" name="l_motor"/>
    <flexJoint mechanicalReduction="-1.0" name="flex"/>
    <rollJoint mechanicalReduction="1.0" name="roll"/>
  </transmission>)"),
                                         "r.urdf", UrdfOptions{});
  ASSERT_EQ(m.transmissions.size(), 2u);
  const Transmission& s = m.transmissions[0];
  EXPECT_EQ(s.type, "pr2_mechanism_model/SimpleTransmission");
  ASSERT_TRUE(s.mechanical_reduction.has_value());
  EXPECT_DOUBLE_EQ(*s.mechanical_reduction, -79.2);
  ASSERT_EQ(s.joints.size(), 1u);
  EXPECT_EQ(s.joints[0].name, "roll");
  ASSERT_EQ(s.actuators.size(), 1u);
  EXPECT_EQ(s.actuators[0].name, "roll_motor");
  ASSERT_NE(s.xml.child("compensator"), nullptr);
  EXPECT_EQ(s.xml.child("compensator")->attribute("k_belt"), "4000.0");

  const Transmission& w = m.transmissions[1];
  ASSERT_EQ(w.actuators.size(), 2u);
  EXPECT_EQ(w.actuators[0].name, "r_motor");
  EXPECT_EQ(w.actuators[0].role, "right");
  EXPECT_DOUBLE_EQ(*w.actuators[0].mechanical_reduction, 60.17);
  EXPECT_EQ(w.actuators[1].role, "left");
  ASSERT_EQ(w.joints.size(), 2u);
  EXPECT_EQ(w.joints[0].name, "flex");
  EXPECT_EQ(w.joints[0].role, "flex");
  EXPECT_DOUBLE_EQ(*w.joints[0].mechanical_reduction, -1.0);
  EXPECT_EQ(w.joints[1].role, "roll");
}

TEST(UrdfTransmissions, ReadsThePr2GripperFormat) {
  const RobotModel m = parse_urdf_string(robot_with(R"(
  <transmission name="gripper" type="pr2_mechanism_model/PR2GripperTransmission">
    <actuator name="gripper_motor"/>
    <gap_joint L0="0.0375528" a="0.0683698" gear_ratio="40.095" mechanical_reduction="1.0" name="flex" screw_reduction="0.004"/>
    <use_simulated_gripper_joint/>
    <passive_joint name="roll"/>
    <simulated_actuated_joint name="roll" passive_actuated_joint="flex" simulated_reduction="3141.6"/>
  </transmission>)"),
                                         "r.urdf", UrdfOptions{});
  const Transmission& g = m.transmissions.at(0);
  ASSERT_EQ(g.joints.size(), 3u);
  EXPECT_EQ(g.joints[0].role, "gap");
  EXPECT_EQ(g.joints[0].name, "flex");
  EXPECT_DOUBLE_EQ(*g.joints[0].mechanical_reduction, 1.0);
  EXPECT_EQ(g.joints[1].role, "passive");
  EXPECT_EQ(g.joints[2].role, "simulated_actuated");
  EXPECT_EQ(g.actuators.at(0).name, "gripper_motor");
  // The gap joint's linkage parameters stay in the XML for the transmission to read.
  EXPECT_EQ(g.xml.child("gap_joint")->attribute("screw_reduction"), "0.004");
  EXPECT_NE(g.xml.child("use_simulated_gripper_joint"), nullptr);
}

void expect_error(const std::string& urdf, const std::string& a, const std::string& b) {
  try {
    parse_urdf_string(urdf, "bad.urdf", UrdfOptions{});
    FAIL() << "no error for " << a;
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr(a));
    EXPECT_THAT(e.what(), HasSubstr(b));
  }
}

TEST(UrdfTransmissions, RejectsBadTransmissions) {
  expect_error(robot_with(R"(<transmission name="t"><joint name="flex"/><actuator name="m"/></transmission>)"),
               "transmission 't'", "no type");
  expect_error(robot_with(R"(<transmission name="t" type="x"><joint name="nope"/><actuator name="m"/></transmission>)"),
               "transmission 't': joint 'nope'", "does not exist");
  expect_error(robot_with(R"(<transmission name="t" type="x"><actuator name="m"/></transmission>)"),
               "transmission 't'", "names no joint");
  expect_error(robot_with(R"(<transmission name="t" type="x"><joint name="flex"/><actuator name="m"/>
      <mechanicalReduction>fast</mechanicalReduction></transmission>)"),
               "bad.urdf:13: transmission 't'", "not a number: \"fast\"");
  expect_error(robot_with(R"(<transmission name="t" type="x"><joint name="flex"/><actuator name="m"/>
      <mechanicalReduction>0</mechanicalReduction></transmission>)"),
               "transmission 't'", "mechanical reduction is zero");
}

// What ros_control accepts loads, with a warning naming the lines.
TEST(UrdfTransmissions, RepeatedNamesAndInterfacesInTheActuatorAreWarnings) {
  std::vector<std::string> warnings;
  const RobotModel m = parse_urdf_string(robot_with(R"(<transmission name="t" type="x"><joint name="flex"/><actuator name="m"/></transmission>
      <transmission name="t" type="x"><joint name="roll"/><actuator name="m2"/></transmission>
      <transmission name="f"><type>transmission_interface/SimpleTransmission</type><joint name="flex"/>
        <actuator name="m"><hardwareInterface>VelocityJointInterface</hardwareInterface></actuator></transmission>
      <transmission name="g"><type>transmission_interface/SimpleTransmission</type><joint name="flex"/>
        <actuator name="m3"/></transmission>)"),
                                         "r.urdf", UrdfOptions{}, &warnings);
  EXPECT_EQ(m.transmissions.size(), 4u);
  ASSERT_EQ(warnings.size(), 3u) << ::testing::PrintToString(warnings);
  EXPECT_THAT(warnings[0], HasSubstr("r.urdf:13: transmission 't' is defined twice (first at line 12); both are loaded"));
  EXPECT_THAT(warnings[1], HasSubstr("r.urdf:14: transmission 'f': joint 'flex' names its <hardwareInterface> in <actuator> 'm'"));
  EXPECT_THAT(warnings[2], HasSubstr("r.urdf:17: transmission 'g': joint 'flex' is also driven by transmission 't' (line 12) "
                                     "through actuator 'm'; actuator 'm3' is no second motor"));
}

TEST(UrdfGazebo, ReadsLinkAndJointPropertiesInBothSpellings) {
  std::vector<std::string> warnings;
  const RobotModel m = parse_urdf_string(robot_with(R"(
  <gazebo reference="l1">
    <material>Gazebo/Silver</material>
    <mu1>0.2</mu1>
    <mu2>0.3</mu2>
    <kp>1000000.0</kp>
    <kd>1.0</kd>
    <selfCollide>true</selfCollide>
    <gravity>false</gravity>
    <minDepth>0.001</minDepth>
    <maxVel>100</maxVel>
  </gazebo>
  <gazebo reference="l2">
    <mu1 value="100.0"/>
    <material value="PR2/Red"/>
    <turnGravityOff value="true"/>
  </gazebo>
  <gazebo reference="flex">
    <stopKd value="1.0"/>
    <stopKp>1000000.0</stopKp>
    <provideFeedback value="true"/>
  </gazebo>
  <gazebo reference="ghost"><mu1>1</mu1></gazebo>)"),
                                         "r.urdf", UrdfOptions{}, &warnings);
  ASSERT_EQ(m.gazebo_links.count("l1"), 1u);
  const GazeboLinkProperties& l1 = m.gazebo_links.at("l1");
  EXPECT_EQ(l1.material, "Gazebo/Silver");
  EXPECT_DOUBLE_EQ(*l1.mu1, 0.2);
  EXPECT_DOUBLE_EQ(*l1.mu2, 0.3);
  EXPECT_DOUBLE_EQ(*l1.kp, 1e6);
  EXPECT_DOUBLE_EQ(*l1.kd, 1.0);
  EXPECT_TRUE(*l1.self_collide);
  EXPECT_FALSE(*l1.gravity);
  EXPECT_DOUBLE_EQ(*l1.min_depth, 0.001);
  EXPECT_DOUBLE_EQ(*l1.max_vel, 100.0);
  const GazeboLinkProperties& l2 = m.gazebo_links.at("l2");
  EXPECT_DOUBLE_EQ(*l2.mu1, 100.0);
  EXPECT_FALSE(l2.mu2.has_value());
  EXPECT_EQ(l2.material, "PR2/Red");
  EXPECT_FALSE(*l2.gravity);  // turnGravityOff = true
  ASSERT_EQ(m.gazebo_joints.count("flex"), 1u);
  EXPECT_DOUBLE_EQ(*m.gazebo_joints.at("flex").stop_kd, 1.0);
  EXPECT_DOUBLE_EQ(*m.gazebo_joints.at("flex").stop_kp, 1e6);
  EXPECT_TRUE(*m.gazebo_joints.at("flex").provide_feedback);
  EXPECT_EQ(m.gazebo_links.count("ghost"), 0u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("ghost"));
}

TEST(UrdfGazebo, ReadsModelAndSensorPlugins) {
  const RobotModel m = parse_urdf_string(robot_with(R"(
  <gazebo>
    <plugin filename="libgazebo_ros_control.so" name="gazebo_ros_control">
      <robotNamespace>/cc8</robotNamespace>
    </plugin>
  </gazebo>
  <gazebo>
    <plugin filename="libleo_gazebo_differential_plugin.so" name="rocker_differential">
      <jointA>flex</jointA>
      <jointB>roll</jointB>
      <forceConstant>1000.0</forceConstant>
    </plugin>
  </gazebo>
  <gazebo reference="l2">
    <sensor type="camera" name="cam"><camera/>
      <plugin name="cam_controller" filename="libgazebo_ros_camera.so"><frameName>l2</frameName></plugin>
    </sensor>
  </gazebo>)"),
                                         "r.urdf", UrdfOptions{});
  ASSERT_EQ(m.plugins.size(), 3u);
  EXPECT_EQ(m.plugins[0].name, "gazebo_ros_control");
  EXPECT_EQ(m.plugins[0].filename, "libgazebo_ros_control.so");
  EXPECT_EQ(m.plugins[0].parameters.at("robotNamespace"), "/cc8");
  EXPECT_EQ(m.plugins[0].reference, "");
  EXPECT_EQ(m.plugins[0].sensor, "");
  EXPECT_EQ(m.plugins[1].parameters.at("jointA"), "flex");
  EXPECT_EQ(m.plugins[1].parameters.at("jointB"), "roll");
  EXPECT_EQ(m.plugins[1].parameters.at("forceConstant"), "1000.0");
  EXPECT_EQ(m.plugins[1].xml.line, 19);
  EXPECT_EQ(m.plugins[2].sensor, "cam");
  EXPECT_EQ(m.plugins[2].reference, "l2");
}

TEST(UrdfGazebo, RejectsNonNumbersAndNonBooleans) {
  expect_error(robot_with(R"(<gazebo reference="l1"><mu1>slippery</mu1></gazebo>)"), "bad.urdf:12: link 'l1'",
               "<mu1> is not a number: \"slippery\"");
  expect_error(robot_with(R"(<gazebo reference="l1"><selfCollide>maybe</selfCollide></gazebo>)"),
               "link 'l1'", "<selfCollide> is not a boolean");
  expect_error(robot_with(R"(<gazebo reference="l1"><kp>nan</kp></gazebo>)"), "link 'l1'", "not finite");
}

}  // namespace
}  // namespace mechsim::description
