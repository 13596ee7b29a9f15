// The summary `mechsim check` prints.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "description/robot_summary.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

TEST(RobotSummary, CountsJointsTransmissionsAndPlugins) {
  const std::string urdf = R"(<robot name="rover">
  <link name="base"><inertial><mass value="10"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="w1" type="continuous"><parent link="base"/><child link="wheel1"/><axis xyz="0 1 0"/></joint>
  <link name="wheel1"><inertial><mass value="1.5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="w2" type="continuous"><parent link="base"/><child link="wheel2"/><axis xyz="0 1 0"/>
    <mimic joint="w1"/></joint>
  <link name="wheel2"/>
  <joint name="cam" type="fixed"><parent link="base"/><child link="camera"/></joint>
  <link name="camera"/>
  <transmission name="t1"><type>transmission_interface/SimpleTransmission</type>
    <joint name="w1"><hardwareInterface>EffortJointInterface</hardwareInterface></joint>
    <actuator name="m1"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <gazebo><plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so"><robotNamespace>/rover</robotNamespace></plugin></gazebo>
  <gazebo reference="camera"><sensor name="c" type="camera"><camera/><plugin name="cam" filename="libcam.so"/></sensor></gazebo>
</robot>)";
  const std::string s = summarize_robot(parse_urdf_string(urdf, "rover.urdf", UrdfOptions{}));
  EXPECT_THAT(s, HasSubstr("robot 'rover' (rover.urdf)"));
  EXPECT_THAT(s, HasSubstr("root link:       base"));
  EXPECT_THAT(s, HasSubstr("links:           4 (2 with mass)"));
  EXPECT_THAT(s, HasSubstr("joints:          3: 2 continuous, 1 fixed"));
  EXPECT_THAT(s, HasSubstr("degrees of freedom: 1 (1 mimic joint not counted)"));
  EXPECT_THAT(s, HasSubstr("total mass:      11.500 kg"));
  EXPECT_THAT(s, HasSubstr("transmissions:   1: 1 transmission_interface/SimpleTransmission"));
  EXPECT_THAT(s, HasSubstr("gazebo plugins:  1 model, 1 sensor"));
  EXPECT_THAT(s, HasSubstr("gazebo_ros_control (libgazebo_ros_control.so) robotNamespace=/rover"));
}

}  // namespace
}  // namespace mechsim::description
