// The mechanism of a ros2_control robot: its <ros2_control> joints with their command and state
// interfaces, min/max bounds on the commands, passive (state-only and mimic) joints, hold_joints,
// and a joint a transmission already drives.
#include <gtest/gtest.h>

#include <cmath>

#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::mechanism {
namespace {

const char* kRobot = R"(<robot name="r">
  <link name="base"/>
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="c"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="d"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="10" velocity="100"/></joint>
  <joint name="j2" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit effort="5" velocity="30"/></joint>
  <joint name="j3" type="revolute"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="5" velocity="3"/>
    <mimic joint="j1" multiplier="0.5"/></joint>
  <joint name="j4" type="revolute"><parent link="c"/><child link="d"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="5" velocity="3"/></joint>
  <transmission name="t4"><type>transmission_interface/SimpleTransmission</type>
    <joint name="j4"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="m4"><mechanicalReduction>10</mechanicalReduction></actuator></transmission>
  <ros2_control name="S" type="system">
    <hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin></hardware>
    <joint name="j1">
      <command_interface name="position"><param name="min">-0.5</param><param name="max">0.75</param></command_interface>
      <command_interface name="effort"><param name="min">-3</param><param name="max">2</param></command_interface>
      <state_interface name="position"/><state_interface name="velocity"/>
    </joint>
    <joint name="j2">
      <command_interface name="velocity"><param name="max">4</param></command_interface>
      <state_interface name="velocity"/>
    </joint>
    <joint name="j3"><state_interface name="position"/></joint>
    <joint name="j4"><command_interface name="position"/><state_interface name="position"/></joint>
  </ros2_control>
  HOLD
</robot>)";

MechanismModel build(const std::string& hold = "") {
  std::string xml = kRobot;
  xml.replace(xml.find("HOLD"), 4, hold);
  return build_mechanism(description::parse_urdf_string(xml, "r.urdf", {}));
}

TEST(Ros2ControlJoints, InterfacesRolesAndBoundsComeFromTheTags) {
  const MechanismModel m = build();
  ASSERT_EQ(m.joints.size(), 4u);
  // The transmission's joint first (transmissions are built first), then the tags' in order.
  EXPECT_EQ(m.joints[0].name, "j4");
  EXPECT_EQ(m.joints[1].name, "j1");
  const JointInfo& j1 = m.joints[static_cast<std::size_t>(m.joint_index("j1"))];
  EXPECT_TRUE(j1.ros2_control);
  EXPECT_EQ(j1.role, JointRole::Actuated);
  EXPECT_EQ(j1.interfaces, (std::vector<HardwareInterface>{HardwareInterface::Position, HardwareInterface::Effort}));
  EXPECT_EQ(j1.state_interfaces, (std::vector<std::string>{"position", "velocity"}));
  EXPECT_TRUE(j1.has_state_interface("velocity"));
  EXPECT_FALSE(j1.has_state_interface("effort"));
  EXPECT_EQ(j1.command_min[static_cast<std::size_t>(HardwareInterface::Position)], -0.5);
  EXPECT_EQ(j1.command_max[static_cast<std::size_t>(HardwareInterface::Effort)], 2.0);
  EXPECT_TRUE(std::isinf(j1.command_max[static_cast<std::size_t>(HardwareInterface::Velocity)]));
  EXPECT_TRUE(j1.hold_when_unclaimed);  // hold_joints defaults to true
  const JointInfo& j3 = m.joints[static_cast<std::size_t>(m.joint_index("j3"))];
  EXPECT_EQ(j3.role, JointRole::Passive);  // a mimic joint: the physics moves it
  EXPECT_TRUE(j3.interfaces.empty());
  EXPECT_FALSE(j3.hold_when_unclaimed);
  // j4: its transmission (reduction 10) stays; its interfaces are the tag's.
  const JointInfo& j4 = m.joints[static_cast<std::size_t>(m.joint_index("j4"))];
  EXPECT_EQ(j4.interfaces, (std::vector<HardwareInterface>{HardwareInterface::Position}));
  EXPECT_EQ(m.transmissions[static_cast<std::size_t>(j4.transmission)]->name(), "t4");
  // The tags' own joints get a SimpleTransmission of reduction 1 and an actuator each.
  EXPECT_EQ(m.actuator_index("j1_ros2_control") >= 0, true);
  EXPECT_EQ(m.transmissions[static_cast<std::size_t>(j1.transmission)]->name(), "j1_ros2_control");
}

TEST(Ros2ControlJoints, HoldJointsFalseHoldsNothing) {
  const MechanismModel m = build(R"(<gazebo><plugin filename="libgazebo_ros2_control.so" name="g">
      <hold_joints>false</hold_joints></plugin></gazebo>)");
  for (const JointInfo& j : m.joints) EXPECT_FALSE(j.hold_when_unclaimed) << j.name;
}

TEST(Ros2ControlJoints, CommandsAreClampedIntoTheInterfacesMinAndMax) {
  const MechanismModel m = build();
  MechanismState s = make_state(m);
  const auto j1 = static_cast<std::size_t>(m.joint_index("j1"));
  const auto j2 = static_cast<std::size_t>(m.joint_index("j2"));
  s.joints[j1].command_mode = HardwareInterface::Position;
  s.joints[j1].commanded_position = 1.5;  // URDF allows 2, the interface 0.75
  s.joints[j2].command_mode = HardwareInterface::Velocity;
  s.joints[j2].commanded_velocity = -10.0;  // no min: only the max bounds it
  enforce_safety_limits(m, s, 1.0);
  EXPECT_EQ(s.joints[j1].commanded_position, 0.75);
  EXPECT_EQ(s.joints[j2].commanded_velocity, -10.0);
  s.joints[j2].commanded_velocity = 10.0;
  s.joints[j1].command_mode = HardwareInterface::Effort;
  s.joints[j1].commanded_effort = -8.0;  // URDF effort limit 10, the interface -3
  enforce_safety_limits(m, s, 1.0);
  EXPECT_EQ(s.joints[j2].commanded_velocity, 4.0);
  EXPECT_EQ(s.joints[j1].commanded_effort, -3.0);
}

}  // namespace
}  // namespace mechsim::mechanism
