// The sensors gazebo_plugins' own tests use, read as Gazebo and the plugins read them: range and
// block laser plugins on ray sensors, laser_retro, contact sensors' collision names, sonar, the
// camera plugins' formats, distortion crop, triggered, depth and multi cameras.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

// The gazebo text starts at line 4.
std::string robot_with(const std::string& gazebo) {
  return "<robot name=\"r\">\n"
         "<link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>"
         "<collision name=\"shell\"><geometry><box size=\"1 1 1\"/></geometry></collision>"
         "<collision><geometry><sphere radius=\"0.1\"/></geometry></collision></link>\n"
         "<link name=\"arm\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>"
         "<collision><geometry><box size=\"1 1 1\"/></geometry></collision></link><joint name=\"j\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/></joint>\n" +
         gazebo + "\n</robot>\n";
}

RobotModel parse(const std::string& gazebo, std::vector<std::string>* warnings = nullptr) {
  return parse_urdf_string(robot_with(gazebo), "t.urdf", {}, warnings);
}

std::string error_of(const std::string& gazebo) {
  try {
    parse(gazebo);
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "";
}

// A ray sensor of 5 x 5 rays with `plugin` inside, as gazebo_ros' range world writes its sonars.
std::string ray_sensor(const std::string& plugin) {
  return R"(<gazebo reference="base"><sensor type="ray" name="sonar"><update_rate>10</update_rate>
    <ray><scan><horizontal><samples>5</samples><resolution>1</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></horizontal>
      <vertical><samples>5</samples><resolution>2</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></vertical></scan>
      <range><min>0.01</min><max>0.75</max></range></ray>)" +
         plugin + "</sensor></gazebo>";
}

TEST(GazeboPluginSensors, RangePluginOnARaySensorGivesARange) {
  const RobotModel m = parse(ray_sensor(R"(<plugin name="p" filename="libgazebo_ros_range.so">
      <robotNamespace>bot</robotNamespace><gaussianNoise>0.005</gaussianNoise><updateRate>5</updateRate>
      <topicName>sonar</topicName><frameName>sonar_link</frameName><fov>0.5</fov><radiation>infrared</radiation></plugin>)"));
  ASSERT_EQ(m.sensors.size(), 1u);
  const SensorSpec& s = m.sensors[0];
  ASSERT_TRUE(s.simulated());
  const auto& ray = std::get<RaySpec>(s.details);
  EXPECT_EQ(ray.output, RayOutput::Range);
  EXPECT_DOUBLE_EQ(ray.plugin_noise, 0.005);
  EXPECT_DOUBLE_EQ(ray.fov, 0.5);
  EXPECT_EQ(ray.radiation, 1);
  EXPECT_DOUBLE_EQ(s.update_rate, 5.0) << "the plugin's updateRate throttles the sensor's 10 Hz";
  ASSERT_TRUE(s.plugin);
  EXPECT_TRUE(s.plugin->unsupported.empty()) << s.plugin->unsupported;
  EXPECT_EQ(s.plugin->full_topic(), "/bot/sonar");
  EXPECT_EQ(s.plugin->frame, "sonar_link");
}

TEST(GazeboPluginSensors, RangePluginDefaultsAreThePlugins) {
  const RobotModel m = parse(ray_sensor(R"(<plugin name="p" filename="libgazebo_ros_range.so"/>)"));
  const SensorSpec& s = m.sensors.at(0);
  const auto& ray = std::get<RaySpec>(s.details);
  EXPECT_DOUBLE_EQ(ray.fov, 0.05);
  EXPECT_EQ(ray.radiation, 0);  // ultrasound
  EXPECT_DOUBLE_EQ(ray.plugin_noise, 0.0);
  EXPECT_DOUBLE_EQ(s.update_rate, 10.0);
  EXPECT_EQ(s.plugin->full_topic(), "/range");
  EXPECT_EQ(s.plugin->frame, "/world");
}

TEST(GazeboPluginSensors, BlockLaserPluginGivesAPointCloud) {
  const RobotModel m = parse(ray_sensor(R"(<plugin name="b" filename="libgazebo_ros_block_laser.so">
      <gaussianNoise>0.02</gaussianNoise><hokuyoMinIntensity>101</hokuyoMinIntensity></plugin>)"));
  const SensorSpec& s = m.sensors.at(0);
  const auto& ray = std::get<RaySpec>(s.details);
  EXPECT_EQ(ray.output, RayOutput::PointCloud);
  EXPECT_DOUBLE_EQ(ray.plugin_noise, 0.02);
  EXPECT_FALSE(ray.noise.active()) << "the plugin's noise is its own, not the ranges'";
  EXPECT_TRUE(s.plugin->unsupported.empty());
  EXPECT_EQ(s.plugin->full_topic(), "/world");
  EXPECT_EQ(s.plugin->frame, "/world");
}

TEST(GazeboPluginSensors, LaserRetroOfALinkInBothSpellings) {
  const RobotModel m = parse(R"(<gazebo reference="base"><laserRetro>2000</laserRetro></gazebo>
<gazebo reference="arm"><laser_retro>150.5</laser_retro></gazebo>)");
  EXPECT_DOUBLE_EQ(m.gazebo_links.at("base").laser_retro.value_or(0.0), 2000.0);
  EXPECT_DOUBLE_EQ(m.gazebo_links.at("arm").laser_retro.value_or(0.0), 150.5);
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><laserRetro>shiny</laserRetro></gazebo>)"),
              HasSubstr("t.urdf:4: link 'base' (gazebo): <laserRetro> is not a number"));
}

TEST(GazeboPluginSensors, ContactCollisionsResolveToTheLinksShapes) {
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="contact" name="bumper">
    <contact><collision>shell</collision><collision>arm_collision</collision></contact>
    <plugin name="b" filename="libgazebo_ros_bumper.so"><bumperTopicName>bumps</bumperTopicName></plugin></sensor></gazebo>)");
  const auto& c = std::get<ContactSpec>(m.sensors.at(0).details);
  ASSERT_EQ(c.targets.size(), 2u);
  EXPECT_EQ(c.targets[0].link, "base");
  EXPECT_EQ(c.targets[0].index, 0) << "a collision by its own name: that shape only";
  EXPECT_EQ(c.targets[1].link, "arm");
  EXPECT_EQ(c.targets[1].index, -1) << "Gazebo's URDF name: the link's shapes";
  EXPECT_EQ(m.sensors[0].plugin->full_topic(), "/bumps");
  EXPECT_EQ(m.sensors[0].plugin->frame, "world");
}

TEST(GazeboPluginSensors, ContactCollisionAsAnAttributeIsTakenWithAWarning) {
  std::vector<std::string> warnings;
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="contact" name="bumper">
    <contact><collision name="shell"/></contact></sensor></gazebo>)",
                             &warnings);
  const auto& c = std::get<ContactSpec>(m.sensors.at(0).details);
  EXPECT_EQ(c.collisions, std::vector<std::string>{"shell"});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("t.urdf:5: sensor 'bumper': <contact><collision name=\"shell\"/> taken as"));
}

TEST(GazeboPluginSensors, SonarIsReadAndNamedAsNotSimulated) {
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="sonar" name="s">
    <sonar><min>0.1</min><max>2</max><radius>0.3</radius></sonar>
    <plugin name="r" filename="libgazebo_ros_range.so"/></sensor></gazebo>)");
  const SensorSpec& s = m.sensors.at(0);
  EXPECT_FALSE(s.simulated());
  EXPECT_THAT(std::get<UnsupportedSpec>(s.details).reason, HasSubstr("does not simulate sonar"));
  EXPECT_THAT(s.plugin->unsupported, HasSubstr("needs a ray sensor"));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="sonar" name="s">
    <sonar><min>3</min><max>2</max><radius>0.3</radius></sonar></sensor></gazebo>)"),
              HasSubstr("t.urdf:5: sensor 's': <sonar> min 3"));
}

std::string camera(const std::string& image, const std::string& plugin, const std::string& type = "camera") {
  return R"(<gazebo reference="base"><sensor type=")" + type + R"(" name="camera1"><camera name="head">)" + image +
         "</camera>" + plugin + "</sensor></gazebo>";
}

TEST(GazeboPluginSensors, EveryImageFormatGazeboTakesIsTaken) {
  for (const char* format : {"L16", "L_INT16", "R16G16B16", "RGB_INT16", "FLOAT32", "BAYER_GRBG8", "B8G8R8"}) {
    std::vector<std::string> warnings;
    const RobotModel m = parse(camera(std::string("<image><format>") + format + "</format></image>", ""), &warnings);
    EXPECT_EQ(std::get<CameraSpec>(m.sensors.at(0).details).lenses.at(0).format, format);
    EXPECT_TRUE(warnings.empty()) << format << ": " << ::testing::PrintToString(warnings);
  }
  std::vector<std::string> warnings;
  const RobotModel m = parse(camera("<image><format>RGBA_MAGIC</format></image>", ""), &warnings);
  EXPECT_EQ(std::get<CameraSpec>(m.sensors.at(0).details).lenses.at(0).format, "RGBA_MAGIC");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("t.urdf:4: sensor 'camera1': <camera><image><format> \"RGBA_MAGIC\" is not one of Gazebo's"));
}

TEST(GazeboPluginSensors, BarrelDistortionIsCroppedUnlessBorderCropIsFalse) {
  const std::string barrel = "<distortion><k1>-0.1</k1><k2>-0.1</k2><k3>-0.1</k3><center>0.4 0.5</center></distortion>";
  const auto lens = [](const RobotModel& m) { return std::get<CameraSpec>(m.sensors.at(0).details).lenses.at(0); };
  EXPECT_TRUE(lens(parse(camera(barrel, ""))).distortion.crop);
  EXPECT_TRUE(lens(parse(camera(barrel, R"(<plugin name="c" filename="libgazebo_ros_camera.so"/>)"))).distortion.crop);
  const CameraLens off = lens(parse(camera(
      barrel, R"(<plugin name="c" filename="libgazebo_ros_camera.so"><borderCrop>false</borderCrop></plugin>)")));
  EXPECT_FALSE(off.distortion.crop);
  EXPECT_DOUBLE_EQ(off.distortion.center_x, 0.4);
  EXPECT_FALSE(lens(parse(camera("<distortion><k1>0.1</k1></distortion>", ""))).distortion.crop)
      << "Gazebo crops only a barrel";
}

TEST(GazeboPluginSensors, TriggeredCameraListensOnItsTriggerTopic) {
  const RobotModel m = parse(camera("", R"(<plugin name="c" filename="libgazebo_ros_triggered_camera.so">
      <cameraName>camera1</cameraName><frameName>camera_link</frameName></plugin>)"));
  const SensorSpec& s = m.sensors.at(0);
  const auto& c = std::get<CameraSpec>(s.details);
  EXPECT_TRUE(s.plugin->unsupported.empty()) << s.plugin->unsupported;
  EXPECT_EQ(c.image_topics.at(0), "/camera1/image_raw");
  EXPECT_EQ(c.trigger_topic, "/camera1/image_trigger");
  const RobotModel named = parse(camera("", R"(<plugin name="c" filename="libgazebo_ros_triggered_camera.so">
      <robotNamespace>ns</robotNamespace><cameraName>cam</cameraName><triggerTopicName>shoot</triggerTopicName></plugin>)"));
  EXPECT_EQ(std::get<CameraSpec>(named.sensors.at(0).details).trigger_topic, "/ns/cam/shoot");
  EXPECT_TRUE(std::get<CameraSpec>(parse(camera("", "")).sensors.at(0).details).trigger_topic.empty());
}

TEST(GazeboPluginSensors, DepthPluginsDefaultTopicsAndCutoffs) {
  const RobotModel d = parse(camera("", R"(<plugin name="d" filename="libgazebo_ros_depth_camera.so">
      <cameraName>camera1</cameraName></plugin>)",
                                    "depth"));
  const auto& depth = std::get<CameraSpec>(d.sensors.at(0).details);
  EXPECT_EQ(depth.image_topics.at(0), "/camera1/ir/image_raw");
  EXPECT_EQ(depth.info_topics.at(0), "/camera1/ir/camera_info");
  EXPECT_EQ(depth.depth_topic, "/camera1/depth/image_raw");
  EXPECT_EQ(depth.depth_info_topic, "/camera1/depth/camera_info");
  EXPECT_EQ(depth.points_topic, "/camera1/points");
  EXPECT_DOUBLE_EQ(depth.point_cloud_cutoff, 0.4);
  EXPECT_EQ(depth.point_cloud_cutoff_max, std::numeric_limits<double>::infinity()) << "gazebo_ros_depth_camera has no maximum";
  const RobotModel k = parse(camera("", R"(<plugin name="k" filename="libgazebo_ros_openni_kinect.so">
      <cameraName>kinect</cameraName><imageTopicName>rgb/image_raw</imageTopicName></plugin>)",
                                    "depth"));
  const auto& kinect = std::get<CameraSpec>(k.sensors.at(0).details);
  EXPECT_EQ(kinect.image_topics.at(0), "/kinect/rgb/image_raw");
  EXPECT_EQ(kinect.info_topics.at(0), "/kinect/ir/camera_info");
  EXPECT_DOUBLE_EQ(kinect.point_cloud_cutoff_max, 5.0);
}

TEST(GazeboPluginSensors, MulticameraNamesItsCamerasLeftAndRight) {
  std::vector<std::string> warnings;
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="multicamera" name="stereo">
    <camera name="left_eye"><image><width>64</width><height>48</height></image></camera>
    <camera name="cam_right"><image><width>64</width><height>48</height></image></camera>
    <camera name="middle"><image><width>64</width><height>48</height></image></camera>
    <plugin name="s" filename="libgazebo_ros_multicamera.so"><cameraName>stereo/camera</cameraName>
      <hackBaseline>0.07</hackBaseline></plugin></sensor></gazebo>)",
                             &warnings);
  const auto& c = std::get<CameraSpec>(m.sensors.at(0).details);
  EXPECT_EQ(c.image_topics,
            (std::vector<std::string>{"/stereo/camera/left/image_raw", "/stereo/camera/right/image_raw", ""}));
  EXPECT_EQ(c.info_topics,
            (std::vector<std::string>{"/stereo/camera/left/camera_info", "/stereo/camera/right/camera_info", ""}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("publishes only cameras whose name holds left or right, not camera 'middle'"));
}

}  // namespace
}  // namespace mechsim::description
