// parse_urdf_string on small inline descriptions: what urdfdom reads, converted to RobotModel.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

constexpr const char* kArm = R"(<?xml version="1.0"?>
<robot name="arm">
  <material name="blue"><color rgba="0 0 1 1"/></material>
  <link name="base">
    <inertial>
      <origin xyz="0 0 0.1" rpy="0 0 0"/>
      <mass value="2.5"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.05"/>
    </inertial>
    <visual>
      <geometry><box size="0.2 0.3 0.4"/></geometry>
      <material name="blue"/>
    </visual>
    <collision><geometry><cylinder radius="0.1" length="0.4"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/>
    <child link="upper"/>
    <origin xyz="0 0 0.4" rpy="0 0 1.5707963267948966"/>
    <axis xyz="0 0 2"/>
    <limit lower="-1" upper="2" effort="30" velocity="3"/>
    <dynamics damping="0.5" friction="0.1"/>
    <safety_controller soft_lower_limit="-0.9" soft_upper_limit="1.9" k_position="100" k_velocity="10"/>
    <calibration rising="0.25"/>
  </joint>
  <link name="upper">
    <inertial>
      <mass value="1.0"/>
      <inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.01"/>
    </inertial>
    <visual><geometry><mesh filename="package://arm_pkg/meshes/upper.dae" scale="2 2 2"/></geometry></visual>
    <collision><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <joint name="finger" type="prismatic">
    <parent link="upper"/>
    <child link="finger_link"/>
    <axis xyz="1 0 0"/>
    <limit lower="0" upper="0.04" effort="10" velocity="0.2"/>
  </joint>
  <link name="finger_link"/>
  <joint name="finger2" type="prismatic">
    <parent link="upper"/>
    <child link="finger2_link"/>
    <axis xyz="1 0 0"/>
    <limit lower="0" upper="0.04" effort="10" velocity="0.2"/>
    <mimic joint="finger" multiplier="-1" offset="0.01"/>
  </joint>
  <link name="finger2_link"/>
  <joint name="wheel" type="continuous">
    <parent link="base"/>
    <child link="wheel_link"/>
    <axis xyz="0 1 0"/>
  </joint>
  <link name="wheel_link"/>
  <joint name="tool" type="fixed">
    <parent link="upper"/>
    <child link="tool_link"/>
  </joint>
  <link name="tool_link"/>
</robot>
)";

TEST(UrdfParser, ReadsLinksJointsAndTheirProperties) {
  std::vector<std::string> warnings;
  UrdfOptions options;
  options.packages["arm_pkg"] = "/opt/arm_pkg";
  const RobotModel m = parse_urdf_string(kArm, "arm.urdf", options, &warnings);
  EXPECT_EQ(m.name, "arm");
  EXPECT_EQ(m.source, "arm.urdf");
  EXPECT_EQ(m.root_link, "base");
  ASSERT_EQ(m.links.size(), 6u);
  ASSERT_EQ(m.joints.size(), 5u);
  // Document order, with lines.
  EXPECT_EQ(m.links[0].name, "base");
  EXPECT_EQ(m.links[0].line, 4);
  EXPECT_EQ(m.links[1].name, "upper");
  EXPECT_EQ(m.joints[0].name, "shoulder");
  EXPECT_EQ(m.joints[0].line, 16);

  const Link& base = *m.link("base");
  ASSERT_TRUE(base.inertial.has_value());
  EXPECT_DOUBLE_EQ(base.inertial->mass, 2.5);
  EXPECT_DOUBLE_EQ(base.inertial->izz, 0.05);
  EXPECT_DOUBLE_EQ(base.inertial->origin.position.z, 0.1);
  ASSERT_EQ(base.visuals.size(), 1u);
  EXPECT_EQ(base.visuals[0].geometry.type, GeometryType::Box);
  EXPECT_DOUBLE_EQ(base.visuals[0].geometry.size.y, 0.3);
  EXPECT_EQ(base.visuals[0].material_name, "blue");
  ASSERT_TRUE(base.visuals[0].rgba.has_value());
  EXPECT_DOUBLE_EQ((*base.visuals[0].rgba)[2], 1.0);
  ASSERT_EQ(base.collisions.size(), 1u);
  EXPECT_EQ(base.collisions[0].geometry.type, GeometryType::Cylinder);
  EXPECT_DOUBLE_EQ(base.collisions[0].geometry.length, 0.4);
  EXPECT_EQ(base.parent_joint, "");
  EXPECT_THAT(base.child_joints, ::testing::ElementsAre("shoulder", "wheel"));

  const Link& upper = *m.link("upper");
  EXPECT_EQ(upper.parent_joint, "shoulder");
  ASSERT_EQ(upper.visuals.size(), 1u);
  const Geometry& mesh = upper.visuals[0].geometry;
  EXPECT_EQ(mesh.type, GeometryType::Mesh);
  EXPECT_EQ(mesh.mesh_uri, "package://arm_pkg/meshes/upper.dae");
  EXPECT_EQ(mesh.mesh_path, "/opt/arm_pkg/meshes/upper.dae");
  EXPECT_DOUBLE_EQ(mesh.mesh_scale.x, 2.0);
  EXPECT_EQ(upper.collisions[0].geometry.type, GeometryType::Sphere);
  EXPECT_DOUBLE_EQ(upper.collisions[0].geometry.radius, 0.05);
  EXPECT_FALSE(m.link("finger_link")->inertial.has_value());

  const Joint& shoulder = *m.joint("shoulder");
  EXPECT_EQ(shoulder.type, JointType::Revolute);
  EXPECT_EQ(shoulder.parent_link, "base");
  EXPECT_EQ(shoulder.child_link, "upper");
  EXPECT_DOUBLE_EQ(shoulder.origin.position.z, 0.4);
  // rpy (0, 0, pi/2) -> quaternion (cos(pi/4), 0, 0, sin(pi/4)).
  EXPECT_NEAR(shoulder.origin.orientation.w, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(shoulder.origin.orientation.z, std::sqrt(0.5), 1e-12);
  // The axis is normalized.
  EXPECT_DOUBLE_EQ(shoulder.axis.z, 1.0);
  ASSERT_TRUE(shoulder.limits.has_value());
  EXPECT_DOUBLE_EQ(shoulder.limits->lower, -1.0);
  EXPECT_DOUBLE_EQ(shoulder.limits->upper, 2.0);
  EXPECT_DOUBLE_EQ(shoulder.limits->effort, 30.0);
  EXPECT_DOUBLE_EQ(shoulder.limits->velocity, 3.0);
  ASSERT_TRUE(shoulder.dynamics.has_value());
  EXPECT_DOUBLE_EQ(shoulder.dynamics->damping, 0.5);
  EXPECT_DOUBLE_EQ(shoulder.dynamics->friction, 0.1);
  ASSERT_TRUE(shoulder.safety.has_value());
  EXPECT_DOUBLE_EQ(shoulder.safety->soft_lower_limit, -0.9);
  EXPECT_DOUBLE_EQ(shoulder.safety->k_position, 100.0);
  ASSERT_TRUE(shoulder.calibration.has_value());
  ASSERT_TRUE(shoulder.calibration->rising.has_value());
  EXPECT_DOUBLE_EQ(*shoulder.calibration->rising, 0.25);
  EXPECT_FALSE(shoulder.calibration->falling.has_value());
  EXPECT_FALSE(shoulder.mimic.has_value());

  const Joint& finger2 = *m.joint("finger2");
  ASSERT_TRUE(finger2.mimic.has_value());
  EXPECT_EQ(finger2.mimic->joint, "finger");
  EXPECT_DOUBLE_EQ(finger2.mimic->multiplier, -1.0);
  EXPECT_DOUBLE_EQ(finger2.mimic->offset, 0.01);
  EXPECT_EQ(m.joint("wheel")->type, JointType::Continuous);
  EXPECT_EQ(m.joint("tool")->type, JointType::Fixed);

  EXPECT_EQ(m.dof(), 3u);  // shoulder, finger, wheel (finger2 mimics, tool is fixed)
  EXPECT_DOUBLE_EQ(m.total_mass(), 3.5);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(UrdfParser, WarnsAboutAnUnknownMeshPackage) {
  std::vector<std::string> warnings;
  const RobotModel m = parse_urdf_string(kArm, "arm.urdf", UrdfOptions{}, &warnings);
  EXPECT_EQ(m.link("upper")->visuals[0].geometry.mesh_path, "");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("package://arm_pkg/meshes/upper.dae"));
}

TEST(UrdfParser, ResolvesRelativeMeshPathsAgainstTheFile) {
  const std::string urdf = R"(<robot name="r"><link name="a">
    <visual><geometry><mesh filename="meshes/a.stl"/></geometry></visual></link></robot>)";
  const RobotModel m = parse_urdf_string(urdf, "/data/robots/r.urdf", UrdfOptions{});
  EXPECT_EQ(m.links[0].visuals[0].geometry.mesh_path, "/data/robots/meshes/a.stl");
}

TEST(UrdfParser, ReadsAFile) {
  const std::string path = ::testing::TempDir() + "/urdf_parser_test_arm.urdf";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(kArm, f);
    std::fclose(f);
  }
  const RobotModel m = parse_urdf_file(path, UrdfOptions{});
  EXPECT_EQ(m.source, path);
  EXPECT_EQ(m.links.size(), 6u);
  std::remove(path.c_str());
}

TEST(UrdfParser, AMissingFileIsADescriptionError) {
  try {
    parse_urdf_file("/nonexistent/robot.urdf", UrdfOptions{});
    FAIL() << "no error";
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/robot.urdf"));
  }
}

TEST(UrdfParser, PrintsNothingOnTheConsoleWhenUrdfdomComplains) {
  // A visual whose material names no defined material and holds no color: urdfdom logs about it
  // (or rejects it); either way nothing may reach stdout/stderr.
  const std::string urdf = R"(<robot name="r"><link name="a">
    <visual><geometry><box size="1 1 1"/></geometry><material name="undefined"/></visual></link></robot>)";
  std::vector<std::string> warnings;
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  try {
    parse_urdf_string(urdf, "r.urdf", UrdfOptions{}, &warnings);
  } catch (const DescriptionError&) {
  }
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  // What urdfdom said comes back once, as a warning naming the file.
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("r.urdf: urdfdom: link 'a' material 'undefined' undefined"));
}

}  // namespace
}  // namespace mechsim::description
