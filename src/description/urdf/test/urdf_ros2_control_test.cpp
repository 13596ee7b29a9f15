// <ros2_control> tags and the gazebo_ros2_control / gz_ros2_control plugin element: what is read,
// what Gazebo's systems make of it (initial values, mimic joints) and the errors and warnings bad
// input gets, each naming the file, the line and the element.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "description/ros2_control.hpp"
#include "description/ros2_control_plugin.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

// A two-joint arm with a gripper whose right finger mimics the left one; `tags` is the
// <ros2_control> part, `plugin` the <gazebo> part.
std::string arm(const std::string& tags, const std::string& plugin = "", const std::string& right_mimic = "") {
  return R"(<robot name="arm">
  <link name="world"/>
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="fixed" type="fixed"><parent link="world"/><child link="base"/></joint>
  <link name="l1"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="joint1" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <link name="l2"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="joint2" type="revolute"><parent link="l1"/><child link="l2"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <link name="fl"><inertial><mass value="0.1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="left_finger" type="prismatic"><parent link="l2"/><child link="fl"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.04" effort="10" velocity="1"/></joint>
  <link name="fr"><inertial><mass value="0.1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="right_finger" type="prismatic"><parent link="l2"/><child link="fr"/><axis xyz="0 -1 0"/>
    <limit lower="0" upper="0.04" effort="10" velocity="1"/>)" +
         right_mimic + R"(</joint>
  <gazebo reference="l2"><sensor name="tip_imu" type="imu"><update_rate>100</update_rate></sensor></gazebo>
)" + tags + plugin + "\n</robot>\n";
}

const std::string kTags = R"(
  <ros2_control name="ArmSystem" type="system">
    <hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin><param name="example">1</param></hardware>
    <joint name="joint1">
      <command_interface name="position"><param name="min">-1</param><param name="max">1.5</param></command_interface>
      <command_interface name="velocity"/>
      <state_interface name="position"><param name="initial_value">0.25</param></state_interface>
      <state_interface name="velocity"/>
    </joint>
    <joint name="joint2">
      <command_interface name="effort"/>
      <state_interface name="position"/>
    </joint>
    <joint name="left_finger">
      <command_interface name="position"/>
      <state_interface name="position"/>
    </joint>
    <joint name="right_finger">
      <param name="mimic">left_finger</param>
      <param name="multiplier">2</param>
      <state_interface name="position"/>
    </joint>
    <sensor name="tip_imu">
      <state_interface name="orientation.x"/><state_interface name="angular_velocity.z"/>
    </sensor>
    <gpio name="flange"><command_interface name="digital_out"/></gpio>
  </ros2_control>)";

const std::string kPlugin = R"(
  <gazebo>
    <plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">
      <robot_param>robot_description_full</robot_param>
      <robot_param_node>my_state_publisher</robot_param_node>
      <parameters>/opt/does/not/exist/controllers.yaml</parameters>
      <parameters>second.yaml</parameters>
      <controller_manager_name>arm_manager</controller_manager_name>
      <hold_joints>false</hold_joints>
      <ros>
        <namespace>/robot1/</namespace>
        <remapping>/tf:=tf</remapping>
        <remapping>joint_trajectory_controller/joint_trajectory:=arm/command</remapping>
        <argument>--params-file</argument><argument>third.yaml</argument>
      </ros>
    </plugin>
  </gazebo>)";

RobotModel parse(const std::string& xml, std::vector<std::string>* warnings = nullptr) {
  return parse_urdf_string(xml, "arm.urdf", UrdfOptions{}, warnings);
}

std::string error_of(const std::string& xml) {
  try {
    parse(xml);
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Ros2ControlTags, ReadsHardwareJointsInterfacesAndSensors) {
  std::vector<std::string> warnings;
  const RobotModel m = parse(arm(kTags, kPlugin), &warnings);
  ASSERT_EQ(m.ros2_control.size(), 1u);
  const Ros2ControlHardware& h = m.ros2_control[0];
  EXPECT_EQ(h.name, "ArmSystem");
  EXPECT_EQ(h.type, "system");
  EXPECT_EQ(h.plugin, kGazeboSystem);
  EXPECT_TRUE(h.gazebo_system());
  EXPECT_EQ(h.hardware_parameters.at("example"), "1");
  ASSERT_EQ(h.joints.size(), 4u);
  const Ros2ControlComponent& j1 = h.joints[0];
  EXPECT_EQ(j1.name, "joint1");
  ASSERT_EQ(j1.command_interfaces.size(), 2u);
  EXPECT_EQ(j1.command_interfaces[0].name, "position");
  EXPECT_EQ(j1.command_interfaces[0].min, -1.0);
  EXPECT_EQ(j1.command_interfaces[0].max, 1.5);
  EXPECT_FALSE(j1.command_interfaces[1].min);
  EXPECT_EQ(j1.state_interface("position")->initial_value, 0.25);
  EXPECT_GT(j1.line, 0);
  ASSERT_EQ(h.sensors.size(), 1u);
  EXPECT_EQ(h.sensors[0].state_interfaces.size(), 2u);
  ASSERT_EQ(h.gpios.size(), 1u);
  EXPECT_EQ(ros2_control_initial_positions(m), (std::map<std::string, double>{{"joint1", 0.25}}));
  // The GPIO is read, with a warning that it is not simulated.
  bool gpio_warned = false;
  for (const std::string& w : warnings) gpio_warned = gpio_warned || w.find("gpio 'flange' is NOT SIMULATED") != std::string::npos;
  EXPECT_TRUE(gpio_warned);
}

TEST(Ros2ControlTags, HumbleMimicParamMakesTheJointAMimicOfItsLeader) {
  const RobotModel m = parse(arm(kTags));
  const Joint* right = m.joint("right_finger");
  ASSERT_TRUE(right->mimic);
  EXPECT_EQ(right->mimic->joint, "left_finger");
  EXPECT_EQ(right->mimic->multiplier, 2.0);
  const auto mimic = ros2_control_mimic(m, *find_ros2_control_joint(m, "right_finger"));
  ASSERT_TRUE(mimic);
  EXPECT_TRUE(mimic->from_param);
  EXPECT_FALSE(ros2_control_mimic(m, *find_ros2_control_joint(m, "left_finger")));
}

TEST(Ros2ControlTags, JazzyMimicComesFromTheUrdfUnlessTheAttributeSaysFalse) {
  std::string tags = kTags;
  tags.replace(tags.find("<param name=\"mimic\">left_finger</param>"), std::string("<param name=\"mimic\">left_finger</param>").size(), "");
  tags.replace(tags.find("<param name=\"multiplier\">2</param>"), std::string("<param name=\"multiplier\">2</param>").size(), "");
  const std::string urdf_mimic = R"(<mimic joint="left_finger" multiplier="1" offset="0.01"/>)";
  const RobotModel m = parse(arm(tags, "", urdf_mimic));
  const auto mimic = ros2_control_mimic(m, *find_ros2_control_joint(m, "right_finger"));
  ASSERT_TRUE(mimic);
  EXPECT_FALSE(mimic->from_param);
  EXPECT_EQ(mimic->offset, 0.01);
  std::string off = tags;
  off.replace(off.find("<joint name=\"right_finger\">"), std::string("<joint name=\"right_finger\">").size(),
              "<joint name=\"right_finger\" mimic=\"false\">");
  const RobotModel m2 = parse(arm(off, "", urdf_mimic));
  EXPECT_FALSE(ros2_control_mimic(m2, *find_ros2_control_joint(m2, "right_finger")));
  // mimic="true" on a joint whose URDF has no <mimic>: Jazzy's parser refuses it.
  std::string wrong = tags;
  wrong.replace(wrong.find("<joint name=\"joint2\">"), std::string("<joint name=\"joint2\">").size(), "<joint name=\"joint2\" mimic=\"true\">");
  EXPECT_THAT(error_of(arm(wrong, "", urdf_mimic)), HasSubstr("joint 'joint2' has mimic=\"true\" but its URDF joint has no <mimic>"));
}

TEST(Ros2ControlPlugin, ReadsTheGazeboRos2ControlElement) {
  const RobotModel m = parse(arm(kTags, kPlugin));
  const std::optional<Ros2ControlPlugin> p = find_ros2_control_plugin(m);
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->modern_gazebo);
  EXPECT_EQ(p->robot_param, "robot_description_full");
  EXPECT_EQ(p->robot_param_node, "my_state_publisher");
  EXPECT_EQ(p->controller_manager_name, "arm_manager");
  EXPECT_FALSE(p->hold_joints);
  EXPECT_EQ(p->ros_namespace, "/robot1/");
  EXPECT_EQ(p->node_namespace(), "/robot1");
  EXPECT_EQ(p->controller_manager_node(), "/robot1/arm_manager");
  ASSERT_EQ(p->remappings.size(), 2u);
  EXPECT_EQ(p->remappings[0].from, "/tf");
  EXPECT_EQ(p->remappings[0].to, "tf");
  EXPECT_EQ(p->remappings[1].to, "arm/command");
  // <parameters> in order, then --params-file arguments; none of these exists.
  EXPECT_EQ(p->parameters, (std::vector<std::string>{"/opt/does/not/exist/controllers.yaml", "second.yaml", "third.yaml"}));
  EXPECT_EQ(p->parameter_paths, (std::vector<std::string>{"", "", ""}));
  EXPECT_THAT(p->origin, HasSubstr("arm.urdf:"));
}

TEST(Ros2ControlPlugin, GzRos2ControlAndItsDefaults) {
  std::string tags = kTags;
  tags.replace(tags.find(kGazeboSystem), std::string(kGazeboSystem).size(), kGazeboSimSystem);
  const RobotModel m = parse(arm(tags, R"(<gazebo><plugin filename="gz_ros2_control-system"
      name="gz_ros2_control::GazeboSimROS2ControlPlugin"><parameters>c.yaml</parameters></plugin></gazebo>)"));
  EXPECT_TRUE(m.ros2_control[0].gazebo_system());
  const auto p = find_ros2_control_plugin(m);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->modern_gazebo);
  EXPECT_TRUE(p->hold_joints);
  EXPECT_EQ(p->controller_manager_node(), "/controller_manager");
  EXPECT_EQ(p->robot_param, "robot_description");
}

TEST(Ros2ControlTags, AnotherHardwarePluginIsAWarningAndSimulatedAsGazebos) {
  std::string tags = kTags;
  tags.replace(tags.find(kGazeboSystem), std::string(kGazeboSystem).size(), "mock_components/GenericSystem");
  std::vector<std::string> warnings;
  const RobotModel m = parse(arm(tags), &warnings);
  EXPECT_FALSE(m.ros2_control[0].gazebo_system());
  bool warned = false;
  for (const std::string& w : warnings) warned = warned || w.find("'mock_components/GenericSystem' is not one of Gazebo's") != std::string::npos;
  EXPECT_TRUE(warned);
}

// Each bad input: the message names the file, the line and the element.
TEST(Ros2ControlTags, BadInputIsAnErrorNamingFileLineAndElement) {
  const auto with = [](std::string from, const std::string& what, const std::string& by) {
    from.replace(from.find(what), what.size(), by);
    return from;
  };
  EXPECT_THAT(error_of(arm(with(kTags, "<command_interface name=\"effort\"/>", "<command_interface name=\"torque\"/>"))),
              HasSubstr("joint 'joint2': unknown command interface 'torque'"));
  EXPECT_THAT(error_of(arm(with(kTags, "<command_interface name=\"effort\"/>", "<command_interface name=\"torque\"/>"))),
              testing::MatchesRegex("(.|\n)*arm.urdf:[0-9]+: <ros2_control name=\"ArmSystem\">(.|\n)*"));
  EXPECT_THAT(error_of(arm(with(kTags, "<joint name=\"joint2\">", "<joint name=\"elbow\">"))),
              HasSubstr("joint 'elbow' is not a joint of the robot"));
  EXPECT_THAT(error_of(arm(with(kTags, "<param name=\"min\">-1</param>", "<param name=\"min\">low</param>"))),
              HasSubstr("command_interface 'position': <param name=\"min\">low</param> is not a finite number"));
  EXPECT_THAT(error_of(arm(with(kTags, "<param name=\"max\">1.5</param>", "<param name=\"max\">-3</param>"))),
              HasSubstr("min -1 is greater than max -3"));
  EXPECT_THAT(error_of(arm(with(kTags, "<param name=\"initial_value\">0.25</param>", "<param name=\"initial_value\">up</param>"))),
              HasSubstr("<param name=\"initial_value\">up</param> is not a finite number"));
  EXPECT_THAT(error_of(arm(with(kTags, "<hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin>", "<hardware>"))),
              HasSubstr("<hardware> names no <plugin>"));
  EXPECT_THAT(error_of(arm(with(kTags, "<gpio name=\"flange\">", "<actuators/><gpio name=\"flange\">"))),
              HasSubstr("<actuators> is not an element of <ros2_control>"));
  EXPECT_THAT(error_of(arm(with(kTags, "<param name=\"mimic\">left_finger</param>", "<param name=\"mimic\">joint9</param>"))),
              HasSubstr("mimics joint 'joint9', which is not a joint of the robot"));
  EXPECT_THAT(error_of(arm(with(kTags, "<state_interface name=\"angular_velocity.z\"/>", "<state_interface name=\"spin\"/>"))),
              HasSubstr("sensor 'tip_imu': unknown state interface 'spin'"));
  EXPECT_THAT(error_of(arm(with(kTags, "<joint name=\"joint2\">", "<joint name=\"fixed\">"))),
              HasSubstr("joint 'fixed' is a fixed, floating or planar joint"));
  EXPECT_THAT(error_of(arm(with(kTags, "<joint name=\"joint2\">", "<joint name=\"joint1\">"))),
              HasSubstr("joint 'joint1' is already in <ros2_control name=\"ArmSystem\">"));
  EXPECT_THAT(error_of(arm(with(kTags, "<ros2_control name=\"ArmSystem\" type=\"system\">", "<ros2_control name=\"ArmSystem\">"))),
              HasSubstr("no type attribute"));
  EXPECT_THAT(error_of(arm(kTags, with(kPlugin, "<hold_joints>false</hold_joints>", "<hold_joints>maybe</hold_joints>"))),
              HasSubstr("<hold_joints>maybe</hold_joints> is not a boolean"));
  EXPECT_THAT(error_of(arm(kTags, with(kPlugin, "<remapping>/tf:=tf</remapping>", "<remapping>/tf</remapping>"))),
              HasSubstr("<remapping>/tf</remapping> is not a remapping rule FROM:=TO"));
  EXPECT_THAT(error_of(arm(kTags, with(kPlugin, "<argument>third.yaml</argument>", ""))),
              HasSubstr("--params-file</argument> is not followed by an <argument>"));
}

TEST(Ros2ControlTags, AnIncompleteSensorOrACommandOnAMimicJointIsAWarning) {
  std::vector<std::string> warnings;
  std::string tags = kTags;
  tags.replace(tags.find("<sensor name=\"tip_imu\">"), std::string("<sensor name=\"tip_imu\">").size(), "<sensor name=\"wrist_imu\">");
  tags.replace(tags.find("<param name=\"multiplier\">2</param>"), std::string("<param name=\"multiplier\">2</param>").size(),
               "<command_interface name=\"position\"/>");
  parse(arm(tags), &warnings);
  std::string all;
  for (const std::string& w : warnings) all += w + "\n";
  EXPECT_THAT(all, HasSubstr("sensor 'wrist_imu' names no <sensor> of the robot's <gazebo> blocks"));
  EXPECT_THAT(all, HasSubstr("joint 'right_finger' is a mimic joint with command interfaces"));
}

}  // namespace
}  // namespace mechsim::description
