// The tricycle drive (libgazebo_ros_tricycle_drive.so) and Gazebo's own libDiffDrivePlugin.so in
// the Simulation, on MuJoCo: a tricycle steered 0.4 rad turns at the rate its geometry gives
// (v sin(a) / L for a front wheel at v m/s, L m ahead of the rear axle) and its encoder odometry
// follows it; Gazebo's diff drive, commanded through its vel_cmd port, drives at the commanded
// speed and turns clockwise for a positive turn rate, on wheels it measured itself.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/plugins/gazebo_diff_drive_plugin.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

constexpr const char* kInertia = R"(<inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>)";
constexpr const char* kTyre = R"(<collision><origin rpy="1.5707963 0 0"/><geometry><cylinder radius="0.06" length="0.03"/></geometry></collision>)";

std::string wheel_link(const std::string& name) { return "<link name=\"" + name + "\">" + kInertia + kTyre + "</link>"; }

// A tricycle: the front wheel steered 0.3 m ahead of the rear (encoder) axle, rear wheels 0.3 m apart.
std::string tricycle_urdf(const std::string& elements) {
  return std::string(R"(<robot name="trike">
  <link name="base_link">
    <inertial><mass value="5"/><inertia ixx="0.05" iyy="0.05" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0.05 0 0.05"/><geometry><box size="0.45 0.3 0.05"/></geometry></collision>
  </link>
  <link name="fork"><inertial><mass value="0.2"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="front_steering_joint" type="revolute"><parent link="base_link"/><child link="fork"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 0 1"/><limit lower="-1.6" upper="1.6" effort="20" velocity="5"/></joint>
  <joint name="front_wheel_joint" type="continuous"><parent link="fork"/><child link="front_wheel"/><axis xyz="0 1 0"/></joint>
  <joint name="left_wheel_joint" type="continuous"><parent link="base_link"/><child link="left_wheel"/>
    <origin xyz="-0.1 0.15 0"/><axis xyz="0 1 0"/></joint>
  <joint name="right_wheel_joint" type="continuous"><parent link="base_link"/><child link="right_wheel"/>
    <origin xyz="-0.1 -0.15 0"/><axis xyz="0 1 0"/></joint>)") +
         wheel_link("front_wheel") + wheel_link("left_wheel") + wheel_link("right_wheel") +
         R"(<gazebo><plugin name="tricycle_drive" filename="libgazebo_ros_tricycle_drive.so">
      <actuatedWheelDiameter>0.12</actuatedWheelDiameter><encoderWheelDiameter>0.12</encoderWheelDiameter>
      <encoderWheelSeparation>0.3</encoderWheelSeparation>)" +
         elements + "</plugin></gazebo></robot>";
}

// Gazebo's pioneer-like two-wheeler: wheels 0.4 m apart, a frictionless caster behind.
const std::string kTwoWheeler = std::string(R"(<robot name="gzdd">
  <link name="chassis">
    <inertial><mass value="5"/><inertia ixx="0.05" iyy="0.05" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.05"/><geometry><box size="0.4 0.3 0.05"/></geometry></collision>
    <collision><origin xyz="-0.15 0 -0.01"/><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <gazebo reference="chassis"><mu1>0</mu1><mu2>0</mu2></gazebo>
  <joint name="left_wheel_hinge" type="continuous"><parent link="chassis"/><child link="left_wheel"/>
    <origin xyz="0.1 0.2 0"/><axis xyz="0 1 0"/></joint>
  <joint name="right_wheel_hinge" type="continuous"><parent link="chassis"/><child link="right_wheel"/>
    <origin xyz="0.1 -0.2 0"/><axis xyz="0 1 0"/></joint>)") +
                              wheel_link("left_wheel") + wheel_link("right_wheel") +
                              R"(<gazebo><plugin name="diff_drive" filename="libDiffDrivePlugin.so">
    <left_joint>left_wheel_hinge</left_joint><right_joint>right_wheel_hinge</right_joint><torque>5</torque>
  </plugin></gazebo></robot>)";

description::RobotModel parse(const std::string& urdf, const char* name) {
  return description::parse_urdf_string(urdf, name, description::UrdfOptions{});
}

double yaw_of(const description::Quat& q) { return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z)); }

SimulationOptions on_the_ground() {
  SimulationOptions o;
  o.spawn.z = 0.065;
  return o;
}

TEST(DrivePluginsInSimulation, ATricycleTurnsAtTheRateItsSteeringAngleGives) {
  Simulation sim(parse(tricycle_urdf("<odometrySource>encoder</odometrySource>"), "trike.urdf"), make_world({}),
                 control::Params(), on_the_ground());
  control::Controller* plugin = sim.controllers().controller("tricycle_drive");
  ASSERT_NE(plugin, nullptr);
  auto* cmd = plugin->port_as<control::TwistCommandPort>("cmd_vel");
  auto* odom = plugin->port_as<control::StatePort<control::OdometrySnapshot>>("odom");
  ASSERT_TRUE(cmd && odom);
  ASSERT_TRUE(sim.run_for(0.5));  // settle on the wheels
  control::Twist t;
  t.linear.x = 0.3;   // the front wheel's rim speed, m/s
  t.angular.z = 0.4;  // the steering angle, rad
  ASSERT_TRUE(cmd->write(t));
  ASSERT_TRUE(sim.run_for(2.0));  // the steering and the speed settle
  const description::Pose a = sim.physics().base_pose();
  const double odom_yaw_a = odom->read().yaw;
  ASSERT_TRUE(sim.run_for(2.0));
  const description::Pose b = sim.physics().base_pose();
  const double rate = std::remainder(yaw_of(b.orientation) - yaw_of(a.orientation), 2.0 * M_PI) / 2.0;
  const double odom_rate = std::remainder(odom->read().yaw - odom_yaw_a, 2.0 * M_PI) / 2.0;
  const double expected = 0.3 * std::sin(0.4) / 0.3;
  std::printf("[ figures  ] tricycle drive, 0.3 m/s steered 0.4 rad: yaw rate %.4f rad/s (geometry %.4f), encoder "
              "odometry %.4f rad/s, steering %.4f rad\n",
              rate, expected, odom_rate, sim.mechanism_state().joints[sim.mechanism().joint_index("front_steering_joint")].position);
  EXPECT_NEAR(rate, expected, 0.1 * expected);
  EXPECT_NEAR(odom_rate, rate, 0.05 * expected);  // the encoder odometry turns the same way, as fast
  EXPECT_NEAR(sim.mechanism_state().joints[sim.mechanism().joint_index("front_steering_joint")].position, 0.4, 0.02);
}

TEST(DrivePluginsInSimulation, GazebosDiffDriveMeasuresItsWheelsAndTurnsClockwise) {
  Simulation sim(parse(kTwoWheeler, "gzdd.urdf"), make_world({}), control::Params(), on_the_ground());
  auto* plugin = dynamic_cast<control::GazeboDiffDrivePlugin*>(sim.controllers().controller("diff_drive"));
  ASSERT_NE(plugin, nullptr);
  EXPECT_NEAR(plugin->geometry().separation, 0.4, 1e-9);
  EXPECT_NEAR(plugin->geometry().radius, 0.06, 1e-6);
  ASSERT_TRUE(sim.run_for(0.5));
  EXPECT_NEAR(sim.physics().base_pose().position.x, 0.0, 2e-3);  // no command, no motion
  auto* cmd = plugin->port_as<control::TwistCommandPort>("vel_cmd");
  ASSERT_NE(cmd, nullptr);
  control::Twist t;
  t.linear.x = 0.2;   // m/s
  t.angular.z = 0.5;  // rad/s, Gazebo's sense: clockwise
  ASSERT_TRUE(cmd->write(t));
  ASSERT_TRUE(sim.run_for(0.5));
  const description::Pose a = sim.physics().base_pose();
  ASSERT_TRUE(sim.run_for(2.0));
  const description::Pose b = sim.physics().base_pose();
  const double rate = std::remainder(yaw_of(b.orientation) - yaw_of(a.orientation), 2.0 * M_PI) / 2.0;
  // The chord of an arc of 1 rad at radius 0.4 m, 0.8 m long: 2 R sin(0.5).
  const double chord = std::hypot(b.position.x - a.position.x, b.position.y - a.position.y);
  std::printf("[ figures  ] libDiffDrivePlugin, 0.2 m/s at 0.5 rad/s: yaw rate %.4f rad/s, chord %.4f m in 2 s "
              "(expected -0.5, %.4f)\n",
              rate, chord, 2.0 * 0.4 * std::sin(0.5));
  EXPECT_NEAR(rate, -0.5, 0.05);
  EXPECT_NEAR(chord, 2.0 * 0.4 * std::sin(0.5), 0.04);
}

}  // namespace
}  // namespace mechsim::sim
