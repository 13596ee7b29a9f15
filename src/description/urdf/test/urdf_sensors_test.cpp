// Gazebo sensors in a description: <sensor> blocks and sensor model plugins read into specs, the
// ROS names the plugins would use, bad input named by file, line and sensor, and the sensors of
// the robots' own descriptions.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "description/robot_summary.hpp"
#include "description/urdf/sensor_reader.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

// A two-link robot around `gazebo`, so that line numbers in the tests are easy to count: the
// gazebo text starts at line 4.
std::string robot_with(const std::string& gazebo) {
  return "<robot name=\"r\">\n"
         "<link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>\n"
         "<link name=\"arm\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link><joint name=\"wrist\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/></joint>\n" +
         gazebo + "\n</robot>\n";
}

RobotModel parse(const std::string& gazebo) { return parse_urdf_string(robot_with(gazebo), "t.urdf", {}); }

// The error parse() throws, or "" when it does not throw.
std::string error_of(const std::string& gazebo) {
  try {
    parse(gazebo);
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "";
}

const char* kHokuyo = R"(<gazebo reference="base">
  <sensor type="ray" name="base_laser">
    <update_rate>20</update_rate>
    <pose>0.1 0 0.2 0 0 0</pose>
    <ray>
      <scan><horizontal><samples>640</samples><resolution>1</resolution>
        <min_angle>-2.2689</min_angle><max_angle>2.2689</max_angle></horizontal></scan>
      <range><min>0.08</min><max>10.0</max><resolution>0.01</resolution></range>
    </ray>
    <plugin name="gazebo_ros_base_laser_controller" filename="libgazebo_ros_laser.so">
      <gaussianNoise>0.005</gaussianNoise>
      <topicName>base_scan</topicName>
      <frameName>base_laser_link</frameName>
    </plugin>
  </sensor>
</gazebo>)";

TEST(UrdfSensors, ReadsARaySensorWithItsPlugin) {
  const RobotModel m = parse(kHokuyo);
  ASSERT_EQ(m.sensors.size(), 1u);
  const SensorSpec& s = m.sensors[0];
  EXPECT_EQ(s.name, "base_laser");
  EXPECT_EQ(s.type, "ray");
  EXPECT_STREQ(s.kind_name(), "ray");
  EXPECT_EQ(s.link, "base");
  EXPECT_EQ(s.line, 5);
  EXPECT_EQ(s.source, "t.urdf");
  EXPECT_DOUBLE_EQ(s.update_rate, 20.0);
  EXPECT_DOUBLE_EQ(s.pose.position.x, 0.1);
  EXPECT_DOUBLE_EQ(s.pose.position.z, 0.2);
  const auto& ray = std::get<RaySpec>(s.details);
  EXPECT_EQ(ray.horizontal.samples, 640);
  EXPECT_EQ(ray.horizontal.count(), 640);
  EXPECT_EQ(ray.vertical.count(), 1);
  EXPECT_DOUBLE_EQ(ray.horizontal.min_angle, -2.2689);
  EXPECT_DOUBLE_EQ(ray.horizontal.max_angle, 2.2689);
  EXPECT_DOUBLE_EQ(ray.range_min, 0.08);
  EXPECT_DOUBLE_EQ(ray.range_max, 10.0);
  EXPECT_DOUBLE_EQ(ray.range_resolution, 0.01);
  EXPECT_DOUBLE_EQ(ray.noise.stddev, 0.005);  // the plugin's gaussianNoise, no <noise> given
  ASSERT_TRUE(s.plugin.has_value());
  EXPECT_EQ(s.plugin->topic, "base_scan");
  EXPECT_EQ(s.plugin->frame, "base_laser_link");
  EXPECT_TRUE(s.plugin->unsupported.empty());
}

TEST(UrdfSensors, ReadsAnImuSensorWithSdfNoiseAndThePluginsOffsets) {
  const RobotModel m = parse(R"(<gazebo reference="arm">
  <sensor type="imu" name="zed2_imu_sensor">
    <update_rate>200</update_rate>
    <imu><angular_velocity><z><noise type="gaussian"><mean>0</mean><stddev>0.002</stddev>
      <bias_mean>0.001</bias_mean><bias_stddev>0.0001</bias_stddev></noise></z></angular_velocity></imu>
    <plugin filename="libgazebo_ros_imu_sensor.so" name="imu_plugin">
      <robotNamespace></robotNamespace>
      <topicName>zed2/imu/data</topicName>
      <frameName>zed2_imu_link</frameName>
      <updateRateHZ>100.0</updateRateHZ>
      <gaussianNoise>0.01</gaussianNoise>
      <initialOrientationAsReference>false</initialOrientationAsReference>
      <xyzOffset>-0.002 -0.023 -0.002</xyzOffset>
      <rpyOffset>0.0014025 -0.0000012 -0.0016915</rpyOffset>
    </plugin>
  </sensor>
</gazebo>)");
  ASSERT_EQ(m.sensors.size(), 1u);
  const SensorSpec& s = m.sensors[0];
  EXPECT_STREQ(s.kind_name(), "imu");
  EXPECT_DOUBLE_EQ(s.update_rate, 100.0);  // the plugin's rate limits the sensor's
  const auto& imu = std::get<ImuSpec>(s.details);
  EXPECT_DOUBLE_EQ(imu.rate_noise[0].stddev, 0.01);
  EXPECT_NEAR(imu.rate_noise[2].stddev, std::hypot(0.002, 0.01), 1e-15);
  EXPECT_DOUBLE_EQ(imu.rate_noise[2].bias_mean, 0.001);
  EXPECT_DOUBLE_EQ(imu.accel_noise[1].stddev, 0.01);
  EXPECT_FALSE(imu.initial_orientation_as_reference);
  EXPECT_NEAR(imu.offset.orientation.z, -0.0016915 / 2, 1e-6);
  EXPECT_EQ(s.plugin->topic, "zed2/imu/data");
  EXPECT_EQ(s.plugin->frame, "zed2_imu_link");
  EXPECT_EQ(s.plugin->robot_namespace, "");
}

TEST(UrdfSensors, ReadsContactSensorsAndSensorModelPlugins) {
  const RobotModel m = parse(R"(<gazebo reference="base">
  <sensor type="contact" name="base_contact_sensor">
    <update_rate>100.0</update_rate>
    <contact><collision>base_collision</collision></contact>
    <plugin name="bumper" filename="libgazebo_ros_bumper.so"><bumperTopicName>base_bumper</bumperTopicName></plugin>
  </sensor>
</gazebo>
<gazebo>
  <plugin name="imu_controller" filename="libgazebo_ros_imu.so">
    <updateRate>100.0</updateRate><bodyName>arm</bodyName><topicName>torso_lift_imu/data</topicName>
    <gaussianNoise>2.89e-08</gaussianNoise><rpyOffset>0 -180.0 0</rpyOffset>
  </plugin>
  <plugin name="p3d_base_controller" filename="libgazebo_ros_p3d.so">
    <updateRate>100.0</updateRate><bodyName>base</bodyName><topicName>base_pose_ground_truth</topicName>
    <gaussianNoise>0.01</gaussianNoise><frameName>map</frameName>
  </plugin>
  <plugin name="ft" filename="libgazebo_ros_ft_sensor.so">
    <updateRate>50</updateRate><topicName>ft_sensor</topicName><jointName>wrist</jointName>
  </plugin>
  <plugin name="f3d" filename="libgazebo_ros_f3d.so"><bodyName>arm</bodyName><topicName>f</topicName></plugin>
  <plugin name="drive" filename="libgazebo_ros_diff_drive.so"/>
</gazebo>)");
  ASSERT_EQ(m.sensors.size(), 5u);
  EXPECT_STREQ(m.sensors[0].kind_name(), "contact");
  EXPECT_EQ(std::get<ContactSpec>(m.sensors[0].details).collisions, std::vector<std::string>{"base_collision"});
  EXPECT_EQ(m.sensors[0].plugin->topic, "base_bumper");
  EXPECT_EQ(m.sensors[0].plugin->frame, "world");  // the bumper plugin's default

  const SensorSpec& imu = m.sensors[1];
  EXPECT_EQ(imu.name, "imu_controller");
  EXPECT_STREQ(imu.kind_name(), "imu");
  EXPECT_EQ(imu.link, "arm");
  EXPECT_DOUBLE_EQ(imu.update_rate, 100.0);
  EXPECT_EQ(imu.plugin->frame, "arm");  // gazebo_ros_imu: frameName defaults to bodyName
  EXPECT_DOUBLE_EQ(std::get<ImuSpec>(imu.details).rate_noise[1].stddev, 2.89e-08);
  EXPECT_EQ(std::get<ImuSpec>(imu.details).service_name, "/default_imu");  // gazebo_ros_imu's default

  const auto& gt = std::get<GroundTruthSpec>(m.sensors[2].details);
  EXPECT_EQ(gt.frame, "map");
  EXPECT_DOUBLE_EQ(gt.gaussian_noise, 0.01);
  EXPECT_EQ(m.sensors[2].plugin->topic, "base_pose_ground_truth");

  const auto& ft = std::get<ForceTorqueSpec>(m.sensors[3].details);
  EXPECT_EQ(ft.joint, "wrist");
  EXPECT_EQ(m.sensors[3].link, "arm");  // the joint's child
  EXPECT_TRUE(ft.parent_to_child);
  EXPECT_DOUBLE_EQ(m.sensors[3].update_rate, 50.0);

  EXPECT_FALSE(m.sensors[4].simulated());  // f3d: named, not simulated
  EXPECT_EQ(m.plugins.size(), 6u);         // model plugins are all still listed
}

TEST(UrdfSensors, ImuPluginsTopicAndServiceDefaultsAreThePlugins) {
  // gazebo_ros_imu: /default_imu for both; hector's: imu and <topicName>/calibrate.
  const RobotModel m = parse(R"(<gazebo>
  <plugin name="a" filename="libgazebo_ros_imu.so"><bodyName>arm</bodyName></plugin>
  <plugin name="b" filename="libhector_gazebo_ros_imu.so"><bodyName>arm</bodyName></plugin>
  <plugin name="c" filename="libhector_gazebo_ros_imu.so"><bodyName>arm</bodyName><topicName>raw</topicName></plugin>
</gazebo>)");
  ASSERT_EQ(m.sensors.size(), 3u);
  EXPECT_EQ(m.sensors[0].plugin->topic, "/default_imu");
  EXPECT_EQ(std::get<ImuSpec>(m.sensors[0].details).service_name, "/default_imu");
  EXPECT_EQ(m.sensors[1].plugin->topic, "imu");
  EXPECT_EQ(std::get<ImuSpec>(m.sensors[1].details).service_name, "imu/calibrate");
  EXPECT_EQ(std::get<ImuSpec>(m.sensors[2].details).service_name, "raw/calibrate");
}

TEST(UrdfSensors, OtherCameraTypesAreReadAndNamedAsNotSimulated) {
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="thermal" name="cam"><update_rate>15</update_rate>
    <camera><image><width>64</width><height>48</height></image></camera></sensor></gazebo>)");
  ASSERT_EQ(m.sensors.size(), 1u);
  EXPECT_FALSE(m.sensors[0].simulated());
  EXPECT_THAT(std::get<UnsupportedSpec>(m.sensors[0].details).reason, HasSubstr("not thermal"));
}

// Bad input: each error names the file, the line and the sensor.
TEST(UrdfSensors, NegativeRateIsAnErrorNamingFileLineAndSensor) {
  const std::string e = error_of(R"(<gazebo reference="base"><sensor type="imu" name="imu1">
    <update_rate>-5</update_rate></sensor></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:5: sensor 'imu1': <update_rate> must be >= 0"));
}

TEST(UrdfSensors, MinRangeAboveMaxIsAnError) {
  const std::string e = error_of(R"(<gazebo reference="base"><sensor type="ray" name="laser">
  <ray><scan><horizontal><samples>10</samples><min_angle>-1</min_angle><max_angle>1</max_angle></horizontal></scan>
  <range><min>5</min><max>1</max></range></ray></sensor></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:6: sensor 'laser': <ray><range> min 5"));
  EXPECT_THAT(e, HasSubstr("must be below max 1"));
}

TEST(UrdfSensors, ZeroSamplesIsAnError) {
  const std::string e = error_of(R"(<gazebo reference="base"><sensor type="ray" name="laser">
  <ray><scan><horizontal>
  <samples>0</samples></horizontal></scan><range><min>0.1</min><max>1</max></range></ray></sensor></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:6: sensor 'laser': <ray><scan><horizontal><samples> must be a whole number >= 1"));
}

TEST(UrdfSensors, UnknownTypeIsAnError) {
  const std::string e = error_of(R"(<gazebo reference="base">
  <sensor type="radar" name="r1"/></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:5: sensor 'r1': unknown sensor type \"radar\""));
}

// Gazebo ignores a sensor in a <gazebo reference> that names nothing of the robot (a camera macro
// used on a robot without its link): it is left out with a warning naming it and why, its plugin
// with it.
TEST(UrdfSensors, ASensorOnALinkTheRobotLacksIsLeftOutWithAWarning) {
  std::vector<std::string> warnings;
  const RobotModel m = parse_urdf_string(robot_with(R"(<gazebo reference="camera_link"><sensor type="camera" name="front_cam">
  <camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height></image></camera>
  <plugin name="cam" filename="libgazebo_ros_camera.so"><cameraName>front</cameraName></plugin></sensor></gazebo>)"),
                                         "t.urdf", {}, &warnings);
  EXPECT_TRUE(m.sensors.empty());
  EXPECT_TRUE(m.plugins.empty());
  EXPECT_THAT(::testing::PrintToString(warnings),
              HasSubstr("t.urdf:4: sensor 'front_cam' left out: <gazebo reference=\\\"camera_link\\\"> names no link or joint "
                        "of the robot (Gazebo ignores it too)"));
}

TEST(UrdfSensors, OtherBadValuesAreErrors) {
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="ray" name="l"/></gazebo>)"),
              HasSubstr("sensor 'l': a ray sensor needs a <ray> element"));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="imu" name="i"><update_rate>fast</update_rate></sensor></gazebo>)"),
              HasSubstr("sensor 'i': <update_rate> is not a number: \"fast\""));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="contact" name="c"/></gazebo>)"),
              HasSubstr("sensor 'c': a contact sensor needs <contact><collision>"));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="imu" name="i"><imu><angular_velocity><x>
    <noise type="gaussian"><stddev>-1</stddev></noise></x></angular_velocity></imu></sensor></gazebo>)"),
              HasSubstr("t.urdf:5: sensor 'i': <imu><angular_velocity><x><noise><stddev> must be >= 0"));
  EXPECT_THAT(error_of(R"(<gazebo><plugin name="p" filename="libgazebo_ros_p3d.so"><bodyName>nope</bodyName></plugin></gazebo>)"),
              HasSubstr("sensor 'p': <bodyName> names no link of the robot: 'nope'"));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="force_torque" name="ft"/></gazebo>)"),
              HasSubstr("a force_torque sensor must sit in a <gazebo reference=\"JOINT\">"));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor name="x"/></gazebo>)"), HasSubstr("has no 'type' attribute"));
}

TEST(UrdfSensors, ForceTorqueSensorOnAJoint) {
  const RobotModel m = parse(R"(<gazebo reference="wrist"><sensor type="force_torque" name="ft">
    <update_rate>100</update_rate><force_torque><frame>parent</frame><measure_direction>parent_to_child</measure_direction></force_torque>
  </sensor></gazebo>)");
  const auto& ft = std::get<ForceTorqueSpec>(m.sensors.at(0).details);
  EXPECT_EQ(ft.joint, "wrist");
  EXPECT_EQ(ft.frame, ForceTorqueSpec::Frame::Parent);
  EXPECT_TRUE(ft.parent_to_child);
  EXPECT_EQ(m.sensors[0].link, "arm");
}

TEST(SensorReader, ReadsBlocksWithLinesCountedFromTheScenario) {
  const RobotModel robot = parse("");
  const auto specs = read_sensor_blocks(kHokuyo, robot, "scenario.yaml", 20);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].line, 21);
  EXPECT_EQ(specs[0].source, "scenario.yaml");
  try {
    read_sensor_blocks("<gazebo reference=\"base\">\n<sensor type=\"ray\" name=\"x\"><update_rate>-1</update_rate></sensor></gazebo>",
                       robot, "scenario.yaml", 30);
    FAIL() << "no error";
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("scenario.yaml:31: sensor 'x': <update_rate> must be >= 0"));
  }
  EXPECT_THROW(read_sensor_blocks("<gazebo reference=\"base\"><sensor", robot, "s.yaml", 1), DescriptionError);
  EXPECT_THROW(read_sensor_blocks("<link name=\"x\"/>", robot, "s.yaml", 1), DescriptionError);
  // A name the robot already uses.
  const RobotModel with = parse(kHokuyo);
  EXPECT_THROW(read_sensor_blocks(kHokuyo, with, "s.yaml", 1), DescriptionError);
}

TEST(UrdfSensors, Pr2DescriptionSensors) {
  const std::string path = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/pr2.urdf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs ../shared (robots/reference/pr2.urdf)";
  UrdfOptions options;
  options.lenient = true;
  const RobotModel m = parse_urdf_file(path, options);
  std::map<std::string, const SensorSpec*> by_name;
  for (const SensorSpec& s : m.sensors) by_name[s.name] = &s;
  ASSERT_TRUE(by_name.count("base_laser"));
  ASSERT_TRUE(by_name.count("laser_tilt"));
  ASSERT_TRUE(by_name.count("imu_controller"));
  const SensorSpec& base = *by_name["base_laser"];
  EXPECT_EQ(base.link, "base_laser_link");
  EXPECT_DOUBLE_EQ(base.update_rate, 20.0);
  EXPECT_EQ(std::get<RaySpec>(base.details).horizontal.count(), 640);
  EXPECT_EQ(base.plugin->topic, "base_scan");
  const SensorSpec& tilt = *by_name["laser_tilt"];
  EXPECT_DOUBLE_EQ(tilt.update_rate, 40.0);
  EXPECT_NEAR(std::get<RaySpec>(tilt.details).horizontal.max_angle, 1.396, 1e-3);
  EXPECT_EQ(tilt.plugin->topic, "tilt_scan");
  EXPECT_EQ(by_name["imu_controller"]->plugin->topic, "torso_lift_imu/data");
  EXPECT_EQ(by_name["imu_controller"]->link, "imu_link");
  EXPECT_TRUE(by_name.count("base_contact_sensor"));
  EXPECT_TRUE(by_name.count("p3d_base_controller"));
  int cameras = 0;
  for (const SensorSpec& s : m.sensors) cameras += s.type == "camera";
  EXPECT_EQ(cameras, 7);
}

TEST(UrdfSensors, Cc8DescriptionImu) {
  const std::string path = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/cc8.urdf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs ../shared (robots/reference/cc8.urdf)";
  UrdfOptions options;
  options.lenient = true;
  const RobotModel m = parse_urdf_file(path, options);
  const SensorSpec* imu = nullptr;
  for (const SensorSpec& s : m.sensors)
    if (s.name == "zed2_imu_sensor") imu = &s;
  ASSERT_NE(imu, nullptr);
  EXPECT_DOUBLE_EQ(imu->update_rate, 100.0);
  EXPECT_DOUBLE_EQ(std::get<ImuSpec>(imu->details).rate_noise[0].stddev, 0.01);
  EXPECT_EQ(imu->plugin->topic, "zed2/imu/data");
  EXPECT_EQ(imu->link, "zed2_left_camera_frame");
}

TEST(UrdfSensors, SummaryListsSensorsTopicsAndWhatIsNotSimulated) {
  const RobotModel m = parse(std::string(kHokuyo) + R"(<gazebo reference="arm"><sensor type="thermal" name="cam"/>
    <sensor type="imu" name="imu"><plugin name="i" filename="libgazebo_ros_imu_sensor.so"><robotNamespace>cc8</robotNamespace>
      <topicName>zed2/imu/data</topicName><frameName>imu</frameName></plugin></sensor>
    <sensor type="contact" name="c"><contact><collision>arm_collision</collision></contact>
      <plugin name="x" filename="libsomething_else.so"/></sensor></gazebo>)");
  const std::string s = summarize_robot(m);
  EXPECT_THAT(s, HasSubstr("sensors:         4 (3 simulated)"));
  EXPECT_THAT(s, HasSubstr("base_laser: ray on base, 20 Hz, topic /base_scan (frame base_laser_link)"));
  EXPECT_THAT(s, HasSubstr("cam: thermal on arm, every step, NOT SIMULATED: mechsim simulates camera, depth, multicamera and wideanglecamera, not thermal"));
  EXPECT_THAT(s, HasSubstr("imu: imu on arm, every step, topic /cc8/zed2/imu/data (frame imu)"));
  EXPECT_THAT(s, HasSubstr("c: contact on arm, every step, not published: mechsim has no ROS output for libsomething_else.so"));
}

}  // namespace
}  // namespace mechsim::description
