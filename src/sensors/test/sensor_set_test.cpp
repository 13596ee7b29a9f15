// The sensor set on a small robot: a laser in front of a box against the analytic ranges, Gazebo's
// out-of-range values, rates in simulated time, an IMU at rest, contacts, joint wrenches, ground
// truth, and seeded noise (reproducible, with the configured statistics).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "physics/transform.hpp"
#include "sensor_test_util.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sensors {
namespace {

using ::testing::HasSubstr;

std::string laser_block(double stddev, const std::string& extra_sensor = "", double range_min = 0.1) {
  return R"(<gazebo reference="laser_link"><sensor type="ray" name="front_laser"><update_rate>20</update_rate>
  <ray><scan><horizontal><samples>181</samples><min_angle>-1.2</min_angle><max_angle>1.2</max_angle></horizontal></scan>
    <range><min>)" + std::to_string(range_min) + R"(</min><max>10.0</max></range>
    <noise type="gaussian"><mean>0</mean><stddev>)" + std::to_string(stddev) + R"(</stddev></noise></ray>
  <plugin name="l" filename="libgazebo_ros_laser.so"><topicName>scan</topicName><frameName>laser_link</frameName></plugin>
</sensor></gazebo>)" + extra_sensor;
}

struct Rig {
  description::RobotModel robot;
  std::shared_ptr<const physics::PhysicsModel> model;
  std::unique_ptr<physics::Physics> physics;
  Rig(const std::string& gazebo, double wall_x) : robot(test::parse(test::robot_urdf(gazebo))) {
    model = test::build(robot, wall_x);
    physics = std::make_unique<physics::Physics>(model);
  }
  void settle(double seconds = 1.0) {
    while (physics->time() < seconds) ASSERT_TRUE(physics->step().ok());
  }
};

const LaserScan& scan_of(const SensorSet& set, std::size_t i) { return std::get<LaserScan>(set.reading(i).value); }

TEST(RaySensor, RangesToABoxMatchTheAnalyticDistance) {
  Rig rig(laser_block(0.0), 2.1);  // the wall's face 2.0 m ahead of the laser (at x = 0.1)
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  const LaserScan& scan = scan_of(set, 0);
  ASSERT_EQ(scan.ranges.size(), 181u);
  EXPECT_DOUBLE_EQ(scan.angle_min, -1.2);
  EXPECT_NEAR(scan.angle_increment, 2.4 / 180, 1e-15);
  double worst = 0.0;
  int on_wall = 0;
  for (int i = 0; i < 181; ++i) {
    const double a = -1.2 + i * 2.4 / 180;
    const double d = 2.0 / std::cos(a);
    if (std::abs(2.0 * std::tan(a)) < 1.999) {
      worst = std::max(worst, std::abs(scan.ranges[i] - d));
      ++on_wall;
    } else if (std::abs(2.0 * std::tan(a)) > 2.001) {
      EXPECT_EQ(scan.ranges[i], std::numeric_limits<float>::infinity()) << "ray " << i << " misses the wall";
    }
  }
  EXPECT_GT(on_wall, 100);
  EXPECT_LT(worst, 1e-5);  // float ranges; the acceptance bound is 1 cm
  std::printf("laser to box: %d rays on the wall, worst |range - analytic| = %.2e m\n", on_wall, worst);
}

TEST(RaySensor, OutOfRangeAsGazebo) {
  Rig far(laser_block(0.0), 12.0);  // beyond range max: +inf, noise or not
  SensorSet set(far.robot.sensors, far.model, 1);
  set.sample_all(*far.physics, 0.0);
  for (const float r : scan_of(set, 0).ranges) EXPECT_EQ(r, std::numeric_limits<float>::infinity());
  // A wall (0.05 to 0.25 m away) nearer than range min (0.5 m) is not seen at all: Gazebo's rays
  // start at the minimum range.
  Rig near(laser_block(0.0, "", 0.5), 0.15);
  SensorSet near_set(near.robot.sensors, near.model, 1);
  near_set.sample_all(*near.physics, 0.0);
  const LaserScan& s = scan_of(near_set, 0);
  EXPECT_EQ(s.ranges[90], std::numeric_limits<float>::infinity());
}

TEST(SensorSet, SamplesAtTheirRatesInSimulatedTime) {
  Rig rig(laser_block(0.0, R"(<gazebo reference="head"><sensor type="imu" name="fast_imu"/></gazebo>
    <gazebo reference="head"><sensor type="imu" name="imu_30"><update_rate>30</update_rate></sensor></gazebo>)"),
          2.1);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  std::vector<double> stamps_20;
  std::uint64_t seen = set.reading(0).count;
  for (int k = 1; k <= 1000; ++k) {
    ASSERT_TRUE(rig.physics->step().ok());
    set.sample_due(*rig.physics, k * 0.001);
    if (set.reading(0).count != seen) {
      seen = set.reading(0).count;
      stamps_20.push_back(set.reading(0).stamp);
    }
  }
  EXPECT_EQ(set.reading(0).count, 21u);    // t = 0, 0.05, ..., 1.0
  EXPECT_EQ(set.reading(1).count, 1001u);  // rate 0: every tick
  EXPECT_EQ(set.reading(2).count, 31u);    // due at k/30 s, sampled at the next tick: no drift
  ASSERT_EQ(stamps_20.size(), 20u);
  for (std::size_t i = 0; i < stamps_20.size(); ++i) EXPECT_NEAR(stamps_20[i], 0.05 * static_cast<double>(i + 1), 1e-9);
  EXPECT_NEAR(set.reading(2).stamp, 1.0, 1e-9);
}

TEST(SensorSet, DisabledSensorsAreNotSampled) {
  Rig rig(laser_block(0.0), 2.1);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.set_enabled(0, false);
  set.sample_all(*rig.physics, 0.0);
  EXPECT_EQ(set.reading(0).count, 0u);
  set.set_enabled(0, true);
  set.sample_due(*rig.physics, 0.0);
  EXPECT_EQ(set.reading(0).count, 1u);
}

TEST(SensorSet, SameSeedSameNoiseOtherSeedOtherNoiseWithTheConfiguredStatistics) {
  Rig rig(laser_block(0.01), 2.1);
  SensorSet a(rig.robot.sensors, rig.model, 42), b(rig.robot.sensors, rig.model, 42), c(rig.robot.sensors, rig.model, 43);
  Rig clean(laser_block(0.0), 2.1);
  SensorSet truth(clean.robot.sensors, clean.model, 1);
  truth.sample_all(*clean.physics, 0.0);
  double sum = 0.0, sum2 = 0.0;
  int n = 0, differ = 0;
  for (int k = 0; k < 200; ++k) {
    a.sample_all(*rig.physics, k * 0.05);
    b.sample_all(*rig.physics, k * 0.05);
    c.sample_all(*rig.physics, k * 0.05);
    const LaserScan &sa = scan_of(a, 0), &sb = scan_of(b, 0), &sc = scan_of(c, 0), &st = scan_of(truth, 0);
    for (std::size_t i = 0; i < sa.ranges.size(); ++i) {
      ASSERT_EQ(std::memcmp(&sa.ranges[i], &sb.ranges[i], sizeof(float)), 0) << "sample " << k << " ray " << i;
      if (!std::isfinite(st.ranges[i])) continue;
      differ += sa.ranges[i] != sc.ranges[i];
      const double e = sa.ranges[i] - st.ranges[i];
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  const double mean = sum / n, stddev = std::sqrt(sum2 / n - mean * mean);
  EXPECT_GT(differ, n * 0.99);
  EXPECT_NEAR(mean, 0.0, 4.0 * 0.01 / std::sqrt(n));
  EXPECT_NEAR(stddev, 0.01, 0.01 * 0.02);
  std::printf("laser noise over %d ranges: mean %.2e m, stddev %.5f m (configured 0.01)\n", n, mean, stddev);
}

TEST(ImuSensor, AtRestReadsGravityInTheSensorFrame) {
  Rig rig(R"(<gazebo reference="head"><sensor type="imu" name="imu"><pose>0.02 0 0.01 0.3 0 0</pose></sensor></gazebo>)", 0.0);
  rig.settle();
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, rig.physics->time());
  const ImuReading& r = std::get<ImuReading>(set.reading(0).value);
  // The sensor frame is rolled 0.3 rad about x: gravity's reaction (0, 0, g) seen from it.
  const double g = 9.81;
  EXPECT_NEAR(r.linear_acceleration.x, 0.0, 0.01);
  EXPECT_NEAR(r.linear_acceleration.y, g * std::sin(0.3), 0.01);
  EXPECT_NEAR(r.linear_acceleration.z, g * std::cos(0.3), 0.01);
  EXPECT_NEAR(std::hypot(r.angular_velocity.x, r.angular_velocity.y, r.angular_velocity.z), 0.0, 1e-3);
  const Quat q = physics::quat_from_rpy(0.3, 0.0, 0.0);
  EXPECT_NEAR(std::abs(r.orientation.w * q.w + r.orientation.x * q.x + r.orientation.y * q.y + r.orientation.z * q.z),
              1.0, 1e-6);
  std::printf("IMU at rest: |f - g| = %.2e m/s^2\n",
              std::hypot(r.linear_acceleration.x, r.linear_acceleration.y - g * std::sin(0.3),
                         r.linear_acceleration.z - g * std::cos(0.3)));
}

TEST(ContactSensor, ReportsTheGroundHoldingTheRobot) {
  Rig rig(R"(<gazebo reference="base"><sensor type="contact" name="bumper"><update_rate>100</update_rate>
    <contact><collision>base_collision</collision></contact>
    <plugin name="b" filename="libgazebo_ros_bumper.so"><bumperTopicName>base_bumper</bumperTopicName><frameName>world</frameName></plugin>
  </sensor></gazebo>)", 0.0);
  rig.settle();
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, rig.physics->time());
  const ContactsReading& r = std::get<ContactsReading>(set.reading(0).value);
  ASSERT_EQ(r.count, 1u);
  const ContactState& s = r.states[0];
  EXPECT_EQ(s.collision1_name, "boxes::base::base_collision");
  EXPECT_EQ(s.collision2_name, "ground_plane::link::collision");
  EXPECT_GE(s.contact_positions.size(), 1u);
  EXPECT_EQ(s.contact_positions.size(), s.wrenches.size());
  EXPECT_NEAR(s.total_wrench.force.z, 11.0 * 9.81, 0.02 * 11.0 * 9.81);
  for (std::size_t i = 0; i < s.contact_positions.size(); ++i) {
    EXPECT_NEAR(s.contact_positions[i].z, 0.0, 2e-3);
    EXPECT_NEAR(s.contact_normals[i].z, 1.0, 1e-6);
  }
}

TEST(ContactSensor, CollisionOfALinkWithoutShapesLeavesTheSensorOutWithAWarning) {
  // laser_link has no collision (as a link whose mesh the physics could not load): the PR2's
  // reference URDF without its meshes made mechsim_node fail on base_contact_sensor.
  const auto robot = test::parse(test::robot_urdf(R"(<gazebo reference="base"><sensor type="contact" name="bumper">
    <contact><collision>laser_link_collision</collision></contact></sensor></gazebo>)"));
  const auto model = test::build(robot, 0.0);
  SensorSet set(robot.sensors, model, 1);
  EXPECT_EQ(set.size(), 0u);
  ASSERT_EQ(set.skipped().size(), 1u);
  EXPECT_TRUE(set.skipped()[0].left_out);
  EXPECT_THAT(set.skipped()[0].reason, HasSubstr("sensor 'bumper'"));
  EXPECT_THAT(set.skipped()[0].reason, HasSubstr("link 'laser_link' has none"));
  EXPECT_THAT(set.skipped()[0].reason, HasSubstr("the sensor is left out"));
}

TEST(ContactSensor, UnknownCollisionIsAnErrorNamingTheSensor) {
  const auto robot = test::parse(test::robot_urdf(R"(<gazebo reference="base"><sensor type="contact" name="bumper">
    <contact><collision>no_such_link_collision</collision></contact></sensor></gazebo>)"));
  const auto model = test::build(robot, 0.0);
  try {
    SensorSet set(robot.sensors, model, 1);
    FAIL() << "no error";
  } catch (const SensorError& e) {
    EXPECT_THAT(e.what(), HasSubstr("test.urdf:"));
    EXPECT_THAT(e.what(), HasSubstr("sensor 'bumper'"));
    EXPECT_THAT(e.what(), HasSubstr("no_such_link_collision"));
  }
}

TEST(ForceTorqueSensor, TheNeckCarriesTheHead) {
  Rig rig(R"(<gazebo reference="neck"><sensor type="force_torque" name="neck_ft"><update_rate>100</update_rate>
      <force_torque><frame>child</frame><measure_direction>parent_to_child</measure_direction></force_torque></sensor></gazebo>
    <gazebo><plugin name="neck_ft_plugin" filename="libgazebo_ros_ft_sensor.so"><jointName>neck</jointName><topicName>ft</topicName></plugin></gazebo>)",
          0.0);
  rig.settle();
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, rig.physics->time());
  for (std::size_t i : {0u, 1u}) {
    const WrenchReading& w = std::get<WrenchReading>(set.reading(i).value);
    EXPECT_NEAR(w.force.x, 0.0, 1e-3);
    EXPECT_NEAR(w.force.z, 9.81, 1e-3);
    EXPECT_NEAR(w.torque.y, -0.05 * 9.81, 1e-3);
  }
  // A joint whose child the physics merged away (massless) has no wrench to measure.
  const auto robot = test::parse(test::robot_urdf(
      R"(<gazebo reference="laser_joint"><sensor type="force_torque" name="bad_ft"/></gazebo>)"));
  EXPECT_THROW(SensorSet(robot.sensors, test::build(robot, 0.0), 1), SensorError);
}

TEST(GroundTruthSensor, PoseOfALinkInTheWorldAndInAnotherLink) {
  Rig rig(R"(<gazebo><plugin name="p3d" filename="libgazebo_ros_p3d.so"><bodyName>base</bodyName><topicName>gt</topicName><frameName>map</frameName></plugin>
    <plugin name="p3d_rel" filename="libgazebo_ros_p3d.so"><bodyName>base</bodyName><topicName>gt2</topicName><frameName>head</frameName>
      <xyzOffsets>1 0 0</xyzOffsets></plugin></gazebo>)",
          0.0);
  rig.settle();
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, rig.physics->time());
  const GroundTruthReading& w = std::get<GroundTruthReading>(set.reading(0).value);
  const description::Pose base = rig.physics->base_pose();
  EXPECT_NEAR(w.pose.position.x, base.position.x, 1e-12);
  EXPECT_NEAR(w.pose.position.z, base.position.z, 1e-12);
  const GroundTruthReading& rel = std::get<GroundTruthReading>(set.reading(1).value);
  EXPECT_NEAR(rel.pose.position.x, 1.0, 1e-6);
  EXPECT_NEAR(rel.pose.position.z, -0.5, 1e-6);
}

TEST(SensorSet, UnsimulatedCamerasAreSkippedWithTheirReason) {
  const auto robot = test::parse(test::robot_urdf(R"(<gazebo reference="head"><sensor type="thermal" name="cam"/></gazebo>)"));
  SensorSet set(robot.sensors, test::build(robot, 0.0), 1);
  EXPECT_EQ(set.size(), 0u);
  ASSERT_EQ(set.skipped().size(), 1u);
  EXPECT_EQ(set.skipped()[0].spec.name, "cam");
  EXPECT_THAT(set.skipped()[0].reason, HasSubstr("not thermal"));
}

}  // namespace
}  // namespace mechsim::sensors
