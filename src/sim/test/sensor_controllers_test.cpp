// The controllers' sensor interfaces over simulated sensors (sim/sensor_handles.hpp): an IMU at
// rest publishes gravity through imu_sensor_controller, a force-torque sensor under a known load
// reads it through force_torque_sensor_controller, at their publish_rate, holding the sensors'
// last samples; a sensor nobody else consumes stays sampled while a controller reads it.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "controllers/sensor/sensor_state_controllers.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

using ::testing::HasSubstr;

// A 1 kg bob on a hinge about x, fixed to the world, hanging at rest: its centre of mass 0.1 m
// ahead of and 0.5 m below the hinge, so the hinge carries its weight (9.81 N) and, about y, the
// torque 0.1 m x 9.81 N = 0.981 N m (gravity's torque about x is zero: it stays at rest). An IMU
// (100 Hz, noise off) on the bob, a force-torque sensor (50 Hz) at the hinge (parent on child,
// child frame).
constexpr const char* kBob = R"(<robot name="bob">
  <link name="world"/>
  <joint name="fix" type="fixed"><parent link="world"/><child link="post"/><origin xyz="0 0 1"/></joint>
  <link name="post"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="revolute"><parent link="post"/><child link="bob"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="50" velocity="10"/></joint>
  <link name="bob"><inertial><origin xyz="0.1 0 -0.5"/><mass value="1"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <gazebo reference="bob"><sensor type="imu" name="bob_imu"><update_rate>100</update_rate>
    <plugin filename="libgazebo_ros_imu_sensor.so" name="imu_plugin"><topicName>bob/imu</topicName>
      <frameName>/bob_imu_link</frameName></plugin></sensor></gazebo>
  <gazebo reference="hinge"><sensor type="force_torque" name="hinge_ft"><update_rate>50</update_rate>
    <force_torque><frame>child</frame><measure_direction>parent_to_child</measure_direction></force_torque></sensor></gazebo>
</robot>)";

constexpr const char* kControllers = R"(
imu_sensor_controller: {type: imu_sensor_controller/ImuSensorController, publish_rate: 200}
ft_sensor_controller: {type: force_torque_sensor_controller/ForceTorqueSensorController, publish_rate: 25}
)";

std::unique_ptr<Simulation> make(SimulationOptions options = {}) {
  return std::make_unique<Simulation>(description::parse_urdf_string(kBob, "bob.urdf", {}), make_world({}),
                                      control::Params::from_yaml_string(kControllers, "controllers"), options);
}

TEST(SensorControllers, AnImuAtRestPublishesGravityAtItsRateWithItsFrame) {
  auto sim = make();
  sim->load_and_start({"imu_sensor_controller"});
  ASSERT_TRUE(sim->run_for(1.0));
  auto* c = dynamic_cast<control::ImuSensorController*>(sim->controllers().controller("imu_sensor_controller"));
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->sensor_count(), 1u);
  EXPECT_EQ(c->ports()[0]->name(), "bob_imu");
  const control::ImuSnapshot s = c->sensor_port(0)->read();
  EXPECT_EQ(s.imu.frame_id, "bob_imu_link");  // the plugin's frameName, without its '/'
  EXPECT_NEAR(s.imu.linear_acceleration[0], 0.0, 0.01);
  EXPECT_NEAR(s.imu.linear_acceleration[1], 0.0, 0.01);
  EXPECT_NEAR(s.imu.linear_acceleration[2], 9.81, 0.01);
  EXPECT_NEAR(std::hypot(s.imu.angular_velocity[0], s.imu.angular_velocity[1], s.imu.angular_velocity[2]), 0.0, 1e-3);
  EXPECT_NEAR(std::abs(s.imu.orientation[3]), 1.0, 1e-6);
  // 200 Hz of snapshots from a 100 Hz IMU: each holds the last sample (stamped on the 10 ms grid).
  EXPECT_GE(c->sensor_port(0)->sequence(), 198u);
  EXPECT_LE(c->sensor_port(0)->sequence(), 200u);
  EXPECT_NEAR(s.imu.stamp * 100.0, std::round(s.imu.stamp * 100.0), 1e-6);
  EXPECT_LE(s.stamp - s.imu.stamp, 0.0101);
  std::printf("IMU at rest through imu_sensor_controller: f = (%.2e, %.2e, %.6f) m/s^2\n", s.imu.linear_acceleration[0],
              s.imu.linear_acceleration[1], s.imu.linear_acceleration[2]);
}

TEST(SensorControllers, AForceTorqueSensorReadsTheLoadItCarries) {
  auto sim = make();
  sim->load_and_start({"ft_sensor_controller"});
  ASSERT_TRUE(sim->run_for(1.0));
  auto* c = dynamic_cast<control::ForceTorqueSensorController*>(sim->controllers().controller("ft_sensor_controller"));
  ASSERT_NE(c, nullptr);
  const control::WrenchSnapshot s = c->sensor_port(0)->read();
  EXPECT_EQ(s.wrench.frame_id, "bob");  // no plugin: the joint's child link
  EXPECT_NEAR(s.wrench.force[0], 0.0, 1e-3);
  EXPECT_NEAR(s.wrench.force[1], 0.0, 1e-3);
  EXPECT_NEAR(s.wrench.force[2], 9.81, 1e-3);
  EXPECT_NEAR(s.wrench.torque[0], 0.0, 1e-3);
  EXPECT_NEAR(s.wrench.torque[1], -0.981, 1e-3);
  EXPECT_NEAR(s.wrench.torque[2], 0.0, 1e-3);
  EXPECT_GE(c->sensor_port(0)->sequence(), 24u);
  EXPECT_LE(c->sensor_port(0)->sequence(), 25u);
}

TEST(SensorControllers, ASensorNobodyElseConsumesIsSampledWhileAControllerReadsIt) {
  auto sim = make();
  const std::size_t imu = *sim->sensors().find("bob_imu");
  sim->sensors().set_enabled(imu, false);  // as the ROS node does with nobody subscribed
  ASSERT_TRUE(sim->run_for(0.2));
  const std::uint64_t before = sim->sensors().reading(imu).count;
  EXPECT_EQ(before, 1u);  // only the first sample, at construction
  sim->load_and_start({"imu_sensor_controller"});
  ASSERT_TRUE(sim->run_for(0.5));
  EXPECT_GE(sim->sensors().reading(imu).count, before + 48);
}

TEST(SensorControllers, ARobotWithoutSensorsRefusesThemNamingTheController) {
  SimulationOptions o;
  o.sensors = false;
  auto sim = make(o);
  const control::ControlResult r = sim->controllers().load_controller("imu_sensor_controller");
  EXPECT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("'imu_sensor_controller'"));
  EXPECT_THAT(r.error, HasSubstr("the robot has no IMU"));
}

}  // namespace
}  // namespace mechsim::sim
