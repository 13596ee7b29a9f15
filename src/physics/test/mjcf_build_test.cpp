#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "physics/physics_error.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using ::testing::HasSubstr;
using test::build;

TEST(MjcfBuild, PendulumCompilesFromMemoryWithItsJointAndActuator) {
  auto model = build(test::pendulum_urdf(1.0, 2.0, 1e-4));
  EXPECT_TRUE(model->fixed_to_world());
  ASSERT_EQ(model->joints().size(), 1u);
  EXPECT_EQ(model->joints()[0].name, "hinge");
  EXPECT_TRUE(model->joints()[0].actuated);
  EXPECT_FALSE(model->joints()[0].limited);
  EXPECT_EQ(model->body_count(), 2);  // world + bob
  EXPECT_THAT(model->mjcf(), HasSubstr("<joint name=\"hinge\" type=\"hinge\""));
  EXPECT_THAT(model->mjcf(), HasSubstr("fullinertia"));
}

TEST(MjcfBuild, FloatingRootGetsAFreeJointAtTheSpawnPose) {
  BuildOptions o;
  o.spawn.z = 1.5;
  o.spawn.yaw = 0.5;
  auto model = build(test::box_urdf(), o);
  EXPECT_FALSE(model->fixed_to_world());
  EXPECT_THAT(model->mjcf(), HasSubstr("<freejoint name=\"box:free\"/>"));
  Physics p(model);
  const auto X = p.base_pose();
  EXPECT_NEAR(X.position.z, 1.5, 1e-12);
  EXPECT_NEAR(X.orientation.w, std::cos(0.25), 1e-12);
  EXPECT_NEAR(X.orientation.z, std::sin(0.25), 1e-12);
}

TEST(MjcfBuild, VisualGeomsNeverCollideAndSitInGroupOne) {
  auto model = build(test::box_urdf());
  EXPECT_THAT(model->mjcf(), HasSubstr("name=\"box/visual/0\" type=\"box\""));
  EXPECT_THAT(model->mjcf(), HasSubstr("contype=\"0\" conaffinity=\"0\" group=\"1\""));
  BuildOptions o;
  o.visuals = false;
  EXPECT_THAT(build(test::box_urdf(), o)->mjcf(), ::testing::Not(HasSubstr("visual")));
}

TEST(MjcfBuild, MasslessFixedLinkMergesIntoParentAndKeepsItsFrame) {
  const std::string urdf = R"(<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="sensor"/>
  <joint name="sensor_joint" type="fixed"><parent link="base"/><child link="sensor"/><origin xyz="0.1 0.2 0.3" rpy="0 0 1.5707963267948966"/></joint>
</robot>)";
  auto model = build(urdf);
  EXPECT_EQ(model->body_count(), 2);  // world + base: sensor merged
  EXPECT_TRUE(model->warnings().empty()) << model->warnings().front();
  Physics p(model);
  const auto base = p.link_pose(*model->link_index("base"));
  const auto sensor = p.link_pose(*model->link_index("sensor"));
  EXPECT_NEAR(sensor.position.x - base.position.x, 0.1, 1e-12);
  EXPECT_NEAR(sensor.position.y - base.position.y, 0.2, 1e-12);
  EXPECT_NEAR(sensor.position.z - base.position.z, 0.3, 1e-12);
  EXPECT_NEAR(sensor.orientation.z, std::sin(M_PI / 4), 1e-12);
}

TEST(MjcfBuild, MasslessLinkOnMovableJointIsMergedWithAWarning) {
  const std::string urdf = R"(<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="tip"/>
  <joint name="slider" type="prismatic"><parent link="base"/><child link="tip"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.1" effort="10" velocity="1"/></joint>
</robot>)";
  auto model = build(urdf);
  EXPECT_FALSE(model->joint_index("slider").has_value());
  ASSERT_EQ(model->dropped_joints().size(), 1u);
  EXPECT_EQ(model->dropped_joints()[0], "slider");
  ASSERT_FALSE(model->warnings().empty());
  EXPECT_THAT(model->warnings()[0], HasSubstr("slider"));
  EXPECT_THAT(model->warnings()[0], HasSubstr("no mass"));
}

TEST(MjcfBuild, JointTypesMapToMujocoJoints) {
  const std::string urdf = R"(<robot name="r">
  <link name="world"/>
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="c"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="planar" type="planar"><parent link="world"/><child link="a"/><axis xyz="0 0 1"/></joint>
  <joint name="rev" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="2" effort="5" velocity="1"/><dynamics damping="0.5" friction="0.25"/></joint>
  <joint name="pri" type="prismatic"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
    <limit lower="0" upper="0.3" effort="7" velocity="1"/></joint>
</robot>)";
  auto model = build(urdf);
  EXPECT_EQ(model->dof_count(), 5);
  for (const char* n : {"planar:x", "planar:y", "planar:yaw", "rev", "pri"})
    EXPECT_TRUE(model->joint_index(n).has_value()) << n;
  const JointInfo& rev = model->joints()[*model->joint_index("rev")];
  EXPECT_TRUE(rev.limited);
  EXPECT_DOUBLE_EQ(rev.lower, -1.0);
  EXPECT_DOUBLE_EQ(rev.upper, 2.0);
  EXPECT_DOUBLE_EQ(rev.damping, 0.5);
  EXPECT_DOUBLE_EQ(rev.frictionloss, 0.25);
  EXPECT_DOUBLE_EQ(rev.effort_limit, 5.0);
  const JointInfo& pri = model->joints()[*model->joint_index("pri")];
  EXPECT_TRUE(pri.prismatic);
  EXPECT_DOUBLE_EQ(pri.effort_limit, 7.0);
  EXPECT_FALSE(model->joints()[*model->joint_index("planar:x")].actuated);
}

TEST(MjcfBuild, ParentChildPairsAreExcludedFromContact) {
  const std::string urdf = R"(<robot name="r">
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint>
</robot>)";
  EXPECT_THAT(build(urdf)->mjcf(), HasSubstr("<exclude body1=\"a\" body2=\"b\"/>"));
}

TEST(MjcfBuild, MujocoRejectionIsReportedWithItsMessageAndElement) {
  // A box with a negative edge passes URDF parsing only leniently; build it by hand.
  description::RobotModel robot = test::parse(test::box_urdf());
  robot.links[0].collisions[0].geometry.size = {-0.1, 0.1, 0.1};
  try {
    PhysicsModel::build(robot);
    FAIL() << "expected PhysicsError";
  } catch (const PhysicsError& e) {
    EXPECT_THAT(e.what(), HasSubstr("MuJoCo rejected"));
    EXPECT_THAT(e.what(), HasSubstr("box/collision/0"));
  }
}

TEST(MjcfBuild, BadTimestepIsABuildError) {
  BuildOptions o;
  o.timestep = 0.0;
  EXPECT_THROW(build(test::box_urdf(), o), PhysicsError);
}

}  // namespace
}  // namespace mechsim::physics
