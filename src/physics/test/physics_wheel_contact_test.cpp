// Narrow wheels touch the ground at one point (ContactDefaults::point_contact_wheels): which
// cylinders count as wheels, what MuJoCo gets, and the scrub torque the point contact removes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A steerable wheel pressed on the ground by 20 kg: world -> "lift" (prismatic z, free) ->
// "steer" (revolute about z) -> "spin" (`spin_type` about `spin_axis`), the wheel a cylinder of
// radius 0.08 m and `width`, rotated by `cylinder_rpy` in the wheel link. Friction 100 (the
// PR2's Gazebo value) on the wheel.
std::string steerable_wheel_urdf(double width, const std::string& spin_type = "continuous",
                                 const std::string& spin_axis = "0 1 0", const std::string& cylinder_rpy = "1.5707963267948966 0 0") {
  return R"(<robot name="caster">
  <link name="world"/>
  <link name="carriage"><inertial><mass value="20"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="fork"><inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.0016" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy=")" + cylinder_rpy + R"("/><geometry><cylinder radius="0.08" length=")" + std::to_string(width) + R"("/></geometry></collision>
  </link>
  <joint name="lift" type="prismatic"><parent link="world"/><child link="carriage"/><origin xyz="0 0 0.079"/>
    <axis xyz="0 0 1"/><limit lower="-0.1" upper="0.1" effort="1000" velocity="10"/></joint>
  <joint name="steer" type="continuous"><parent link="carriage"/><child link="fork"/><axis xyz="0 0 1"/>
    <limit effort="100" velocity="10"/></joint>
  <joint name="spin" type=")" + spin_type + R"("><parent link="fork"/><child link="wheel"/><axis xyz=")" + spin_axis + R"("/>
    <limit lower="-100" upper="100" effort="100" velocity="100"/></joint>
  <gazebo reference="wheel"><mu1>100</mu1><mu2>100</mu2></gazebo>
</robot>)";
}

bool has_ellipsoid(const PhysicsModel& m) { return m.mjcf().find("type=\"ellipsoid\"") != std::string::npos; }

TEST(WheelContact, NarrowCylindersTurningAboutTheirAxisBecomeEllipsoidsWithTheSameRadius) {
  const auto narrow = test::build(steerable_wheel_urdf(0.034));
  EXPECT_THAT(narrow->mjcf(), HasSubstr("type=\"ellipsoid\" size=\"0.080000000000000002 0.080000000000000002 0.017000000000000001\""));
  EXPECT_THAT(narrow->mjcf(), Not(HasSubstr("type=\"cylinder\"")));
  // A revolute joint counts too.
  EXPECT_TRUE(has_ellipsoid(*test::build(steerable_wheel_urdf(0.034, "revolute"))));
}

TEST(WheelContact, WideWheelsOtherJointsOtherAxesAndTheOptionOffKeepTheCylinder) {
  EXPECT_FALSE(has_ellipsoid(*test::build(steerable_wheel_urdf(0.2))));                          // wider than its radius
  EXPECT_FALSE(has_ellipsoid(*test::build(steerable_wheel_urdf(0.034, "prismatic"))));           // does not turn
  EXPECT_FALSE(has_ellipsoid(*test::build(steerable_wheel_urdf(0.034, "continuous", "1 0 0"))));  // turns across the cylinder
  EXPECT_FALSE(has_ellipsoid(*test::build(steerable_wheel_urdf(0.034, "continuous", "0 1 0", "0 0 0"))));  // cylinder upright
  BuildOptions off;
  off.contact.point_contact_wheels = false;
  EXPECT_FALSE(has_ellipsoid(*test::build(steerable_wheel_urdf(0.034), off)));
}

// Steering the loaded wheel in place with 2 N m: the line contact of a MuJoCo cylinder holds it
// (two rim points 34 mm apart, each with friction up to 100 x its load), the point contact turns.
double steer_angle_after_one_second(const BuildOptions& options) {
  Physics p(test::build(steerable_wheel_urdf(0.034), options));
  const std::size_t steer = 1;
  EXPECT_EQ(p.model().joints()[steer].name, "steer");
  while (p.time() < 1.0) {
    p.set_effort(steer, 2.0);
    EXPECT_TRUE(p.step().ok());
  }
  return p.position(steer);
}

TEST(WheelContact, APointContactLetsALoadedWheelSteerInPlaceWhereTheLineContactHoldsIt) {
  BuildOptions line;
  line.contact.point_contact_wheels = false;
  const double with_point = steer_angle_after_one_second({}), with_line = steer_angle_after_one_second(line);
  std::cout << "[ figures  ] steer angle after 1 s at 2 N m: point contact " << with_point << " rad, line contact "
            << with_line << " rad\n";
  EXPECT_GT(with_point, 1.0);
  EXPECT_LT(std::abs(with_line), 0.1);
}

// The point contact rolls on the same circle: the wheel rests with its axle 0.08 m up.
TEST(WheelContact, TheWheelRestsOnItsRadius) {
  Physics p(test::build(steerable_wheel_urdf(0.034)));
  while (p.time() < 1.0) ASSERT_TRUE(p.step().ok());
  const auto wheel = p.model().link_index("wheel");
  ASSERT_TRUE(wheel.has_value());
  EXPECT_NEAR(p.link_pose(*wheel).position.z, 0.08, 0.002);
}

}  // namespace
}  // namespace mechsim::physics
