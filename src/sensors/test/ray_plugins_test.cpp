// What gazebo_plugins' ray-sensor plugins make of the rays, against analytic geometry: the laser's
// intensities (the laser_retro of what each ray hit), gazebo_ros_range's shortest ray (the maximum
// when nothing is in range, the plugin's noise only below it), gazebo_ros_block_laser's
// interpolated points and averaged intensities; and the bumper's wrenches as Gazebo reports them
// (the body's frame, about its centre of mass; points and normals in the world).
#include <gtest/gtest.h>

#include <cmath>

#include "physics/transform.hpp"
#include "sensor_test_util.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sensors {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The robot of sensor_test_util with `gazebo`, before a wall whose face is `face` m ahead of the
// laser (laser_link at x = 0.1), 4 m wide and 1 m high, reflecting `retro`; no gravity.
struct Rig {
  description::RobotModel robot;
  std::shared_ptr<const physics::PhysicsModel> model;
  std::unique_ptr<physics::Physics> physics;
  Rig(const std::string& gazebo, double face, double retro) : robot(test::parse(test::robot_urdf(gazebo))) {
    physics::BuildOptions o;
    o.world.gravity = 0.0;
    o.world.ground_plane = false;
    physics::WorldBox wall;
    wall.name = "wall";
    wall.pose.position = {0.1 + face + 0.1, 0.0, 0.5};
    wall.size = {0.2, 4.0, 1.0};
    wall.laser_retro = retro;
    o.world.boxes.push_back(wall);
    model = test::build(robot, 0.0, o);
    physics = std::make_unique<physics::Physics>(model);
  }
};

std::string ray_sensor(const std::string& name, const std::string& scan, double max, const std::string& plugin) {
  return R"(<gazebo reference="laser_link"><sensor type="ray" name=")" + name + R"("><update_rate>10</update_rate>
    <ray><scan>)" + scan + "</scan><range><min>0.1</min><max>" + std::to_string(max) + "</max></range></ray>" + plugin +
         "</sensor></gazebo>\n";
}

const char* kSonarScan = R"(<horizontal><samples>5</samples><resolution>1</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></horizontal>
  <vertical><samples>5</samples><resolution>1</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></vertical>)";

TEST(LaserIntensity, EachRayReportsTheRetroOfWhatItHit) {
  Rig rig(ray_sensor("laser",
                     "<horizontal><samples>181</samples><min_angle>-1.5</min_angle><max_angle>1.5</max_angle></horizontal>", 10.0,
                     R"(<plugin name="l" filename="libgazebo_ros_laser.so"/>)"),
          2.0, 750.0);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  const LaserScan& scan = std::get<LaserScan>(set.reading(0).value);
  ASSERT_EQ(scan.intensities.size(), 181u);
  int on_wall = 0, beside = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (std::isinf(scan.ranges[i])) {
      EXPECT_EQ(scan.intensities[i], 0.0f) << "ray " << i << " hits nothing";
      ++beside;
    } else {
      EXPECT_EQ(scan.intensities[i], 750.0f) << "ray " << i << " at " << scan.ranges[i] << " m";
      ++on_wall;
    }
  }
  EXPECT_GT(on_wall, 80);
  EXPECT_GT(beside, 20);
}

TEST(LaserIntensity, LinksCarryTheirLaserRetroIntoThePhysics) {
  Rig rig(R"(<gazebo reference="head"><laserRetro>77</laserRetro></gazebo>)", 2.0, 5.0);
  const physics::PhysicsModel& m = *rig.model;
  int head = 0, wall = 0, others = 0;
  for (int g = 0; g < m.geom_count(); ++g) {
    const std::string name(m.geom_name(g));
    if (name.rfind("head/", 0) == 0) {
      EXPECT_DOUBLE_EQ(m.geom_laser_retro(g), 77.0) << name;
      ++head;
    } else if (name == "box:wall") {
      EXPECT_DOUBLE_EQ(m.geom_laser_retro(g), 5.0);
      ++wall;
    } else {
      EXPECT_DOUBLE_EQ(m.geom_laser_retro(g), 0.0) << name;
      ++others;
    }
  }
  EXPECT_GE(head, 1);
  EXPECT_EQ(wall, 1);
  EXPECT_GE(others, 1);
  EXPECT_DOUBLE_EQ(m.geom_laser_retro(-1), 0.0);
}

TEST(RangePlugin, ShortestRayOrTheMaximumWhenNothingIsInRange) {
  const std::string range = R"(<plugin name="r" filename="libgazebo_ros_range.so"><fov>0.5</fov><radiation>infrared</radiation></plugin>)";
  Rig rig(ray_sensor("near", kSonarScan, 3.0, range) + ray_sensor("short", kSonarScan, 1.5, range), 2.0, 0.0);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  const RangeReading& near = std::get<RangeReading>(set.reading(0).value);
  EXPECT_NEAR(near.range, 2.0, 1e-9) << "the ray straight ahead meets the wall square on";
  EXPECT_DOUBLE_EQ(near.max_range, 3.0);
  EXPECT_DOUBLE_EQ(near.min_range, 0.1);
  EXPECT_DOUBLE_EQ(near.field_of_view, 0.5);
  EXPECT_EQ(near.radiation, 1);
  const RangeReading& short_one = std::get<RangeReading>(set.reading(1).value);
  EXPECT_EQ(short_one.range, short_one.max_range) << "gazebo_plugins' range test: exactly the maximum";
}

TEST(RangePlugin, GaussianNoiseBelowTheMaximumOnly) {
  const std::string noisy = R"(<plugin name="r" filename="libgazebo_ros_range.so"><gaussianNoise>0.01</gaussianNoise></plugin>)";
  Rig rig(ray_sensor("near", kSonarScan, 3.0, noisy) + ray_sensor("short", kSonarScan, 1.5, noisy), 2.0, 0.0);
  SensorSet set(rig.robot.sensors, rig.model, 3);
  set.set_enabled(0, true);
  double sum = 0, sum2 = 0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    set.sample_all(*rig.physics, k * 0.1);
    const double r = std::get<RangeReading>(set.reading(0).value).range;
    sum += r;
    sum2 += r * r;
    EXPECT_EQ(std::get<RangeReading>(set.reading(1).value).range, 1.5);
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 2.0, 0.002);
  EXPECT_NEAR(sd, 0.01, 0.001);
}

TEST(BlockLaser, PointsAndIntensitiesInterpolatedAsThePluginDoes) {
  const char* scan = R"(<horizontal><samples>3</samples><resolution>1</resolution><min_angle>-0.2</min_angle><max_angle>0.2</max_angle></horizontal>
    <vertical><samples>3</samples><resolution>1</resolution><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></vertical>)";
  Rig rig(ray_sensor("block", scan, 10.0, R"(<plugin name="b" filename="libgazebo_ros_block_laser.so"/>)"), 2.0, 150.0);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  const PointCloudReading& cloud = std::get<PointCloudReading>(set.reading(0).value);
  ASSERT_EQ(cloud.points.size(), 9u);
  ASSERT_EQ(cloud.intensities.size(), 9u);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      // Range of ray (i, j); direction half-way to the next ray (the last one's own).
      const double yaw = -0.2 + 0.2 * i, pitch = -0.1 + 0.1 * j;
      const double r = 2.0 / (std::cos(yaw) * std::cos(pitch));
      const double y_angle = -0.2 + 0.1 * (i + std::min(i + 1, 2)), p_angle = -0.1 + 0.05 * (j + std::min(j + 1, 2));
      const Vec3& p = cloud.points[static_cast<std::size_t>(3 * j + i)];
      EXPECT_NEAR(p.x, r * std::cos(p_angle) * std::cos(y_angle), 1e-9) << i << "," << j;
      EXPECT_NEAR(p.y, r * std::cos(p_angle) * std::sin(y_angle), 1e-9) << i << "," << j;
      EXPECT_NEAR(p.z, -r * std::sin(p_angle), 1e-9) << "the plugin's sign: " << i << "," << j;
      EXPECT_FLOAT_EQ(cloud.intensities[static_cast<std::size_t>(3 * j + i)], 150.0f);
    }
  }
}

TEST(BlockLaser, ResolutionInterpolatesRangesBetweenRays) {
  const char* scan = R"(<horizontal><samples>2</samples><resolution>3</resolution><min_angle>-0.3</min_angle><max_angle>0.3</max_angle></horizontal>)";
  Rig rig(ray_sensor("block", scan, 10.0, R"(<plugin name="b" filename="libgazebo_ros_block_laser.so"/>)"), 2.0, 40.0);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  const PointCloudReading& cloud = std::get<PointCloudReading>(set.reading(0).value);
  ASSERT_EQ(cloud.points.size(), 6u);  // samples x resolution
  const double r = 2.0 / std::cos(0.3);  // both rays: the ranges between them are the same
  for (const Vec3& p : cloud.points) EXPECT_NEAR(std::hypot(p.x, p.y, p.z), r, 1e-9);
  // The first five points lie between the two rays (direction 0: half-way); the last on the last ray.
  EXPECT_NEAR(cloud.points[0].y, 0.0, 1e-12);
  EXPECT_NEAR(std::atan2(cloud.points[5].y, cloud.points[5].x), 0.3, 1e-12);
}

TEST(BlockLaser, RaysWithoutAHitAreCappedNoiselessPointsAndIntensityIsNoisy) {
  const char* scan = R"(<horizontal><samples>4</samples><min_angle>-0.2</min_angle><max_angle>0.2</max_angle></horizontal>)";
  Rig rig(ray_sensor("block", scan, 1.5, R"(<plugin name="b" filename="libgazebo_ros_block_laser.so"><gaussianNoise>0.02</gaussianNoise></plugin>)"),
          2.0, 0.0);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  set.sample_all(*rig.physics, 0.0);
  const PointCloudReading& cloud = std::get<PointCloudReading>(set.reading(0).value);
  ASSERT_EQ(cloud.points.size(), 4u);
  int noisy = 0;
  for (std::size_t k = 0; k < cloud.points.size(); ++k) {
    EXPECT_NEAR(std::hypot(cloud.points[k].x, cloud.points[k].y, cloud.points[k].z), 1.5 - 0.1, 1e-12)
        << "the plugin caps a ray at max - min and adds no noise there";
    if (cloud.intensities[k] != 0.0f) ++noisy;
  }
  EXPECT_EQ(noisy, 4);
}

TEST(BumperWrench, InTheBodysFrameAboutItsCentreOfMassPointsInTheWorld) {
  const std::string bumper = R"(<gazebo reference="base"><sensor type="contact" name="bumper"><update_rate>100</update_rate>
    <contact><collision>base_collision</collision></contact>
    <plugin name="b" filename="libgazebo_ros_bumper.so"><bumperTopicName>b</bumperTopicName><frameName>base</frameName></plugin>
  </sensor></gazebo>)";
  const auto robot = test::parse(test::robot_urdf(bumper));
  physics::BuildOptions o;
  o.spawn.yaw = kPi / 3;
  auto model = test::build(robot, 0.0, o);
  physics::Physics physics(model);
  while (physics.time() < 0.5) ASSERT_TRUE(physics.step().ok());
  SensorSet set(robot.sensors, model, 1);
  set.sample_all(physics, physics.time());
  const ContactsReading& r = std::get<ContactsReading>(set.reading(0).value);
  ASSERT_EQ(r.count, 1u);
  const description::Pose X_WB = physics.link_pose(*model->link_index("base"));
  EXPECT_NEAR(r.X_WL.position.x, X_WB.position.x, 1e-12);
  const Vec3 com = X_WB.position;  // the base's inertia sits at its origin
  const ContactState& s = r.states[0];
  ASSERT_GE(s.wrenches.size(), 1u);
  Vec3 total{};
  for (std::size_t i = 0; i < s.wrenches.size(); ++i) {
    const Vec3& p = s.contact_positions[i];
    EXPECT_NEAR(p.z, 0.0, 2e-3) << "a point on the ground, world frame";
    const Vec3 F_W = physics::rotate(X_WB.orientation, s.wrenches[i].force);
    EXPECT_GT(F_W.z, 0.0) << "the ground pushes the base up";
    const Vec3 arm{p.x - com.x, p.y - com.y, p.z - com.z};
    const Vec3 T_W{arm.y * F_W.z - arm.z * F_W.y, arm.z * F_W.x - arm.x * F_W.z, arm.x * F_W.y - arm.y * F_W.x};
    const Vec3 T_B = physics::rotate(physics::quat_conjugate(X_WB.orientation), T_W);
    EXPECT_NEAR(s.wrenches[i].torque.x, T_B.x, 1e-9);
    EXPECT_NEAR(s.wrenches[i].torque.y, T_B.y, 1e-9);
    EXPECT_NEAR(s.wrenches[i].torque.z, T_B.z, 1e-9);
    total = {total.x + s.wrenches[i].force.x, total.y + s.wrenches[i].force.y, total.z + s.wrenches[i].force.z};
  }
  EXPECT_NEAR(s.total_wrench.force.z, total.z, 1e-9);
  EXPECT_NEAR(total.z, 11.0 * 9.81, 0.02 * 11.0 * 9.81) << "the base is level: its z is the world's";
}

}  // namespace
}  // namespace mechsim::sensors
