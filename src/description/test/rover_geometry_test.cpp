// rover_geometry: forward kinematics at zero joint angles, axis signs and wheel radius, on an
// inline rover, on the real CC8 description (shared/robots/reference/cc8.urdf) and on mechsim's
// own CC8 xacro. Expected positions are the sums of the joint origins, written out by hand.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "description/robot_loader.hpp"
#include "description/rover_geometry.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A body with one steered corner (axis down, on a rocker turned 90 deg about z so that the
// joint origins must be rotated to sum) and one fixed wheel whose axis is -y.
constexpr const char* kRover = R"(<?xml version="1.0"?>
<robot name="mini">
  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/><origin xyz="0 0 0.3"/>
  </joint>
  <link name="base_link"/>
  <joint name="rocker" type="continuous">
    <parent link="base_link"/><child link="rocker_link"/>
    <origin xyz="0.1 0.2 0.0" rpy="0 0 1.5707963267948966"/><axis xyz="0 1 0"/>
  </joint>
  <link name="rocker_link"/>
  <joint name="steer" type="continuous">
    <parent link="rocker_link"/><child link="fork"/>
    <origin xyz="0.3 0.0 -0.1" rpy="0 0 -1.5707963267948966"/><axis xyz="0 0 -1"/>
  </joint>
  <link name="fork"/>
  <joint name="wheel_a" type="continuous">
    <parent link="fork"/><child link="tyre_a"/><origin xyz="0 0.05 -0.1"/><axis xyz="0 1 0"/>
  </joint>
  <link name="tyre_a">
    <collision><origin xyz="0 -0.04 0" rpy="1.5707963267948966 0 0"/>
      <geometry><cylinder radius="0.12" length="0.05"/></geometry></collision>
  </link>
  <joint name="wheel_b" type="continuous">
    <parent link="base_link"/><child link="tyre_b"/><origin xyz="-0.4 -0.3 -0.2"/><axis xyz="0 -1 0"/>
  </joint>
  <link name="tyre_b">
    <collision><origin xyz="0 0 0" rpy="1.5707963267948966 0 0"/>
      <geometry><cylinder radius="0.12" length="0.05"/></geometry></collision>
  </link>
  <joint name="sideways" type="continuous">
    <parent link="base_link"/><child link="odd"/><origin xyz="0 0 0"/><axis xyz="1 0 0"/>
  </joint>
  <link name="odd"/>
</robot>)";

RobotModel mini() { return parse_urdf_string(kRover, "mini.urdf", {}); }

void expect_vec(const Vec3& v, double x, double y, double z, const std::string& what) {
  EXPECT_NEAR(v.x, x, 1e-9) << what;
  EXPECT_NEAR(v.y, y, 1e-9) << what;
  EXPECT_NEAR(v.z, z, 1e-9) << what;
}

TEST(RoverGeometry, SumsRotatedJointOriginsAtZero) {
  const RobotModel m = mini();
  // rocker at (0.1, 0.2, 0) turned +90 deg: its x axis is the base's y. steer's origin (0.3, 0,
  // -0.1) in it is (0, 0.3, -0.1) in the base; steer turns back by -90 deg.
  const Pose X = joint_pose_at_zero(m, "steer", "base_link");
  expect_vec(X.position, 0.1, 0.5, -0.1, "steer");
  EXPECT_NEAR(std::abs(X.orientation.w), 1.0, 1e-9);  // the two turns cancel
  const RoverGeometry g = rover_geometry(m, {"wheel_a", "wheel_b"}, {"steer"});
  ASSERT_EQ(g.wheels.size(), 2u);
  ASSERT_EQ(g.steering.size(), 1u);
  expect_vec(g.steering[0].position, 0.1, 0.5, -0.1, "steer");
  EXPECT_EQ(g.steering[0].axis_sign, -1.0);
  expect_vec(g.wheels[0].joint_position, 0.1, 0.55, -0.2, "wheel_a joint");
  expect_vec(g.wheels[0].tyre_position, 0.1, 0.51, -0.2, "wheel_a tyre");
  EXPECT_EQ(g.wheels[0].steering_joint, "steer");
  EXPECT_EQ(g.wheels[0].axis_sign, 1.0);
  EXPECT_EQ(g.wheels[1].steering_joint, "");
  EXPECT_EQ(g.wheels[1].axis_sign, -1.0);
  expect_vec(g.wheels[1].tyre_position, -0.4, -0.3, -0.2, "wheel_b");
  ASSERT_TRUE(g.wheel_radius.has_value());
  EXPECT_DOUBLE_EQ(*g.wheel_radius, 0.12);
  // From the footprint, the base joint's 0.3 m is added.
  expect_vec(joint_pose_at_zero(m, "wheel_b", "base_footprint").position, -0.4, -0.3, 0.1, "from footprint");
}

TEST(RoverGeometry, ErrorsNameTheJoint) {
  const RobotModel m = mini();
  auto message = [&](const std::vector<std::string>& wheels, const std::vector<std::string>& steering,
                     const std::string& base = "base_link") {
    try {
      rover_geometry(m, wheels, steering, base);
    } catch (const RoverGeometryError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message({"wheel_a", "wheel_x"}, {}), HasSubstr("wheel joint 'wheel_x' is not a joint"));
  EXPECT_THAT(message({"wheel_a", "sideways"}, {}), HasSubstr("'sideways'"));
  EXPECT_THAT(message({"wheel_a", "sideways"}, {}), HasSubstr("not lateral"));
  EXPECT_THAT(message({"wheel_a", "wheel_b"}, {"rocker"}), HasSubstr("not vertical"));
  EXPECT_THAT(message({"wheel_b"}, {"steer"}), HasSubstr("carries 0"));
  EXPECT_THAT(message({"wheel_a"}, {}, "fork_x"), HasSubstr("base link 'fork_x'"));
  EXPECT_THAT(message({"wheel_a"}, {}, "tyre_b"), HasSubstr("not below link 'tyre_b'"));
}

void expect_cc8(const RoverGeometry& g, double tyre_inset) {
  ASSERT_EQ(g.steering.size(), 4u);
  ASSERT_EQ(g.wheels.size(), 6u);
  // Left side: case (0, 0.275, 0.15) + rocker (0, 0.0215, -0.075); FL on the rocker at
  // (0.496003, 0.094, -0.045701); the bogie at (-0.211097, 0.086631, -0.059825) on the rocker,
  // RL at (-0.292, 0.0316, 0.01) and ML at (0.211047, 0.121437, -0.175838) on the bogie.
  const double rocker_y = 0.275 + 0.0215, rocker_z = 0.15 - 0.075;
  const double bogie_x = -0.211097, bogie_y = rocker_y + 0.086631, bogie_z = rocker_z - 0.059825;
  expect_vec(g.steering[0].position, 0.496003, rocker_y + 0.094, rocker_z - 0.045701, "steering_FL");
  expect_vec(g.steering[1].position, 0.496003, -(rocker_y + 0.094), rocker_z - 0.045701, "steering_FR");
  expect_vec(g.steering[2].position, bogie_x - 0.292, bogie_y + 0.0316, bogie_z + 0.01, "steering_RL");
  expect_vec(g.steering[3].position, bogie_x - 0.292, -(bogie_y + 0.0316), bogie_z + 0.01, "steering_RR");
  for (const auto& s : g.steering) EXPECT_EQ(s.axis_sign, -1.0) << s.joint;
  expect_vec(g.wheels[0].joint_position, 0.496003, rocker_y + 0.094 + 0.059, rocker_z - 0.045701 - 0.1895, "wheel FL");
  expect_vec(g.wheels[2].joint_position, bogie_x + 0.211047, bogie_y + 0.121437, bogie_z - 0.175838, "wheel ML");
  expect_vec(g.wheels[3].joint_position, bogie_x + 0.211047, -(bogie_y + 0.121437), bogie_z - 0.175838, "wheel MR");
  EXPECT_NEAR(g.wheels[0].tyre_position.y, rocker_y + 0.094 + 0.059 - tyre_inset, 1e-9);
  EXPECT_NEAR(g.wheels[1].tyre_position.y, -(rocker_y + 0.094 + 0.059 - tyre_inset), 1e-9);
  const std::vector<std::string> steering{"steering_FL", "steering_FR", "", "", "steering_RL", "steering_RR"};
  const std::vector<double> signs{1, -1, -1, -1, 1, -1};  // FL +y, FR -y, ML -y, MR -y, RL +y, RR -y
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(g.wheels[i].steering_joint, steering[i]) << g.wheels[i].joint;
    EXPECT_EQ(g.wheels[i].axis_sign, signs[i]) << g.wheels[i].joint;
  }
  ASSERT_TRUE(g.wheel_radius.has_value());
  EXPECT_DOUBLE_EQ(*g.wheel_radius, 0.09);
}

const std::vector<std::string> kWheels{"wheel_joint_FL", "wheel_joint_FR", "wheel_joint_ML",
                                       "wheel_joint_MR", "wheel_joint_RL", "wheel_joint_RR"};
const std::vector<std::string> kSteering{"steering_FL", "steering_FR", "steering_RL", "steering_RR"};

TEST(RoverGeometry, ReferenceCc8) {
  const fs::path path = fs::path(MECHSIM_SHARED_DIR) / "robots" / "reference" / "cc8.urdf";
  if (!fs::exists(path)) GTEST_SKIP() << "shared data not found at " << path << " (MECHSIM_SHARED_DIR)";
  UrdfOptions options;
  options.lenient = true;
  const RobotModel m = parse_urdf_file(path.string(), options);
  expect_cc8(rover_geometry(m, kWheels, kSteering), 0.06);  // tyres 0.06 m inboard of the joints
}

TEST(RoverGeometry, MechsimCc8Xacro) {
  const fs::path dir = fs::path(MECHSIM_SOURCE_DIR) / "robots" / "cc8";
  LoadOptions options;
  options.packages["mechsim_cc8"] = dir.string();
  const LoadedRobot robot = load_robot((dir / "urdf" / "cc8.urdf.xacro").string(), options);
  expect_cc8(rover_geometry(robot.model, kWheels, kSteering), 0.045);
}

}  // namespace
}  // namespace mechsim::description
