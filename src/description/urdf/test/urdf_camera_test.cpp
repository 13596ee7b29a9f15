// Camera sensors in a description: <camera> elements and the ROS camera plugins' intrinsics and
// topics (as gazebo_ros_camera_utils resolves them), bad input named by file, line and sensor,
// and the cameras of the CC8 (ZED2) and the PR2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "description/camera_override.hpp"
#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

// The gazebo text starts at line 3.
std::string robot_with(const std::string& gazebo) {
  return "<robot name=\"r\">\n"
         "<link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>\n" +
         gazebo + "\n</robot>\n";
}

RobotModel parse(const std::string& gazebo) { return parse_urdf_string(robot_with(gazebo), "t.urdf", {}); }

std::string error_of(const std::string& gazebo) {
  try {
    parse(gazebo);
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "";
}

// The ZED2's left depth sensor as cc8_description writes it (robot_ns "cc8").
const char* kZedDepth = R"(<gazebo reference="base">
  <sensor type="depth" name="zed2_left_camera">
    <update_rate>15.0</update_rate>
    <camera name="zed2_left">
      <horizontal_fov>1.7633</horizontal_fov>
      <image><width>1280</width><height>720</height><format>R8G8B8</format></image>
      <clip><near>0.02</near><far>300</far></clip>
      <noise><type>gaussian</type><mean>0.0</mean><stddev>0.007</stddev></noise>
    </camera>
    <plugin name="camera_controller" filename="libgazebo_ros_openni_kinect.so">
      <robotNamespace>cc8</robotNamespace>
      <cameraName>zed2</cameraName>
      <imageTopicName>left/image_rect_color</imageTopicName>
      <cameraInfoTopicName>left/camera_info</cameraInfoTopicName>
      <depthImageTopicName>depth/depth_registered</depthImageTopicName>
      <depthImageInfoTopicName>depth/camera_info</depthImageInfoTopicName>
      <pointCloudTopicName>point_cloud/cloud_registered</pointCloudTopicName>
      <pointCloudCutoff>0.3</pointCloudCutoff>
      <pointCloudCutoffMax>20.0</pointCloudCutoffMax>
      <frameName>zed2_left_camera_optical_frame</frameName>
      <CxPrime>658.8206787109375</CxPrime>
      <Cx>658.8206787109375</Cx>
      <Cy>372.25787353515625</Cy>
      <hackBaseline>0.0</hackBaseline>
    </plugin>
  </sensor>
</gazebo>)";

TEST(UrdfCamera, ReadsTheZed2DepthSensorWithItsTopics) {
  const RobotModel m = parse(kZedDepth);
  ASSERT_EQ(m.sensors.size(), 1u);
  const SensorSpec& s = m.sensors[0];
  ASSERT_TRUE(s.simulated());
  EXPECT_STREQ(s.kind_name(), "camera");
  const auto& c = std::get<CameraSpec>(s.details);
  ASSERT_EQ(c.lenses.size(), 1u);
  EXPECT_TRUE(c.depth);
  EXPECT_EQ(c.lenses[0].width, 1280);
  EXPECT_EQ(c.lenses[0].height, 720);
  EXPECT_DOUBLE_EQ(c.lenses[0].horizontal_fov, 1.7633);
  EXPECT_DOUBLE_EQ(c.lenses[0].near, 0.02);
  EXPECT_DOUBLE_EQ(c.lenses[0].far, 300.0);
  EXPECT_DOUBLE_EQ(c.lenses[0].noise.stddev, 0.007);
  EXPECT_DOUBLE_EQ(c.cx, 658.8206787109375);
  EXPECT_DOUBLE_EQ(c.cy, 372.25787353515625);
  EXPECT_DOUBLE_EQ(c.point_cloud_cutoff, 0.3);
  EXPECT_DOUBLE_EQ(c.point_cloud_cutoff_max, 20.0);
  EXPECT_EQ(c.image_topics.at(0), "/cc8/zed2/left/image_rect_color");
  EXPECT_EQ(c.info_topics.at(0), "/cc8/zed2/left/camera_info");
  EXPECT_EQ(c.depth_topic, "/cc8/zed2/depth/depth_registered");
  // The package spells the info topic's parameter depthImageInfoTopicName, which the plugin does
  // not read: the default name stays (as in Gazebo).
  EXPECT_EQ(c.depth_info_topic, "/cc8/zed2/depth/camera_info");
  EXPECT_EQ(c.points_topic, "/cc8/zed2/point_cloud/cloud_registered");
  EXPECT_EQ(s.plugin->frame, "zed2_left_camera_optical_frame");
}

TEST(UrdfCamera, PluginDefaultsDistortionAndAbsoluteTopics) {
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="camera" name="cam">
    <camera><distortion><k1>-0.04</k1><p2>0.001</p2><center>0.5 0.5</center></distortion></camera>
    <plugin name="c" filename="libgazebo_ros_camera.so"><cameraName>wide_stereo/left</cameraName>
      <cameraInfoTopicName>/abs/info</cameraInfoTopicName><hackBaseline>0.09</hackBaseline>
      <distortionK1>-0.04</distortionK1></plugin></sensor></gazebo>)");
  const auto& c = std::get<CameraSpec>(m.sensors.at(0).details);
  EXPECT_EQ(c.lenses[0].width, 320);  // SDF's defaults
  EXPECT_EQ(c.lenses[0].height, 240);
  EXPECT_DOUBLE_EQ(c.lenses[0].horizontal_fov, 1.047);
  EXPECT_DOUBLE_EQ(c.lenses[0].distortion.k1, -0.04);
  EXPECT_DOUBLE_EQ(c.lenses[0].distortion.p2, 0.001);
  EXPECT_DOUBLE_EQ(c.ros_distortion[0], -0.04);
  EXPECT_DOUBLE_EQ(c.hack_baseline, 0.09);
  EXPECT_EQ(c.image_topics.at(0), "/wide_stereo/left/image_raw");
  EXPECT_EQ(c.info_topics.at(0), "/abs/info");
  EXPECT_EQ(m.sensors[0].plugin->frame, "/world");  // gazebo_ros_camera_utils' default
  EXPECT_FALSE(c.depth);
}

TEST(UrdfCamera, MulticameraHasOneLensAndTopicPerCamera) {
  const RobotModel m = parse(R"(<gazebo reference="base"><sensor type="multicamera" name="stereo">
    <camera name="left"><image><width>64</width><height>48</height></image></camera>
    <camera name="right"><pose>0 -0.07 0 0 0 0</pose><image><width>64</width><height>48</height></image></camera>
    <plugin name="s" filename="libgazebo_ros_multicamera.so"><cameraName>stereo</cameraName></plugin></sensor></gazebo>)");
  const auto& c = std::get<CameraSpec>(m.sensors.at(0).details);
  ASSERT_EQ(c.lenses.size(), 2u);
  EXPECT_EQ(c.lenses[1].name, "right");
  EXPECT_DOUBLE_EQ(c.lenses[1].pose.position.y, -0.07);
  EXPECT_EQ(c.image_topics, (std::vector<std::string>{"/stereo/left/image_raw", "/stereo/right/image_raw"}));
}

// Bad input: impossible parameters are errors naming the file, the line and the sensor.
TEST(UrdfCamera, ZeroWidthIsAnError) {
  const std::string e = error_of(R"(<gazebo reference="base"><sensor type="camera" name="cam"><camera><image>
    <width>0</width></image></camera></sensor></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:4: sensor 'cam': <camera><image><width> must be a whole number of pixels"));
}

TEST(UrdfCamera, FieldOfViewOfPiOrMoreIsAnError) {
  const std::string e = error_of(R"(<gazebo reference="base"><sensor type="camera" name="cam"><camera>
    <horizontal_fov>3.2</horizontal_fov></camera></sensor></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:4: sensor 'cam': <camera><horizontal_fov> must be in (0, pi)"));
}

TEST(UrdfCamera, NearAtOrBeyondFarIsAnError) {
  const std::string e = error_of(R"(<gazebo reference="base"><sensor type="depth" name="kinect"><camera>
    <clip><near>5</near><far>5</far></clip></camera></sensor></gazebo>)");
  EXPECT_THAT(e, HasSubstr("t.urdf:4: sensor 'kinect': <camera><clip> needs 0 < near < far"));
}

TEST(UrdfCamera, MissingCameraAndWrongPluginAreErrors) {
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="camera" name="cam"/></gazebo>)"),
              HasSubstr("t.urdf:3: sensor 'cam': a camera sensor needs a <camera> element"));
  EXPECT_THAT(error_of(R"(<gazebo reference="base"><sensor type="camera" name="cam"><camera/>
    <plugin name="k" filename="libgazebo_ros_openni_kinect.so"/></sensor></gazebo>)"),
              HasSubstr("t.urdf:4: sensor 'cam': libgazebo_ros_openni_kinect.so needs a sensor of type depth"));
  // A format Gazebo's camera takes (FLOAT32) or does not know (it renders 8-bit colour then) loads.
  EXPECT_EQ(error_of(R"(<gazebo reference="base"><sensor type="camera" name="cam"><camera>
    <image><format>FLOAT32</format></image></camera></sensor></gazebo>)"),
            "");
}

std::map<std::string, const SensorSpec*> cameras_of(const RobotModel& m) {
  std::map<std::string, const SensorSpec*> out;
  for (const SensorSpec& s : m.sensors)
    if (std::holds_alternative<CameraSpec>(s.details)) out[s.name] = &s;
  return out;
}

TEST(UrdfCamera, Cc8Zed2Topics) {
  const std::string path = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/cc8.urdf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs ../shared (robots/reference/cc8.urdf)";
  UrdfOptions options;
  options.lenient = true;
  const RobotModel m = parse_urdf_file(path, options);
  const auto cams = cameras_of(m);
  ASSERT_EQ(cams.size(), 4u);
  const auto& depth = std::get<CameraSpec>(cams.at("zed2_left_camera")->details);
  EXPECT_TRUE(depth.depth);
  EXPECT_THAT(depth.image_topics.at(0), HasSubstr("zed2/left/image_rect_color"));
  EXPECT_THAT(depth.points_topic, HasSubstr("zed2/point_cloud/cloud_registered"));
  const auto& right = std::get<CameraSpec>(cams.at("zed2_right_camera")->details);
  EXPECT_DOUBLE_EQ(right.hack_baseline, 0.12);
  const auto& raw = std::get<CameraSpec>(cams.at("zed2_left_raw_camera")->details);
  EXPECT_DOUBLE_EQ(raw.lenses[0].distortion.k1, -0.043693598);
}

TEST(UrdfCamera, Pr2HeadCameras) {
  const std::string path = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/pr2.urdf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs ../shared (robots/reference/pr2.urdf)";
  UrdfOptions options;
  options.lenient = true;
  const RobotModel m = parse_urdf_file(path, options);
  const auto cams = cameras_of(m);
  ASSERT_TRUE(cams.count("wide_stereo_l_stereo_camera_sensor"));
  const auto& wide = std::get<CameraSpec>(cams.at("wide_stereo_l_stereo_camera_sensor")->details);
  EXPECT_EQ(wide.image_topics.at(0), "/wide_stereo/left/image_raw");
  EXPECT_EQ(wide.lenses[0].width, 640);
  ASSERT_TRUE(cams.count("wide_stereo_r_stereo_camera_sensor"));
  EXPECT_EQ(std::get<CameraSpec>(cams.at("wide_stereo_r_stereo_camera_sensor")->details).image_topics.at(0),
            "/wide_stereo/right/image_raw");
  ASSERT_TRUE(cams.count("high_def_sensor"));  // the Prosilica
  EXPECT_EQ(std::get<CameraSpec>(cams.at("high_def_sensor")->details).image_topics.at(0), "/prosilica/image_raw");
}

// ---- camera overrides (description/camera_override.hpp)

TEST(CameraOverride, ARateAndAWidthKeepTheAspectRatioAndScaleThePluginsIntrinsics) {
  RobotModel m = parse(kZedDepth);
  CameraOverride o;
  o.rate = 5.0;
  o.width = 640;
  const std::vector<std::string> notes = apply_camera_overrides(m, {{"zed2_left_camera", o}});
  const SensorSpec& s = m.sensors[0];
  const auto& c = std::get<CameraSpec>(s.details);
  EXPECT_DOUBLE_EQ(s.update_rate, 5.0);
  EXPECT_EQ(c.lenses[0].width, 640);
  EXPECT_EQ(c.lenses[0].height, 360);
  EXPECT_DOUBLE_EQ(c.lenses[0].horizontal_fov, 1.7633);  // the field of view stays
  // Pixel centres: c' = (c - 0.5) * 0.5 + 0.5.
  EXPECT_NEAR(c.cx, (658.8206787109375 - 0.5) * 0.5 + 0.5, 1e-9);
  EXPECT_NEAR(c.cx_prime, (658.8206787109375 - 0.5) * 0.5 + 0.5, 1e-9);
  EXPECT_NEAR(c.cy, (372.25787353515625 - 0.5) * 0.5 + 0.5, 1e-9);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "sensor 'zed2_left_camera': 15 Hz 1280x720 -> 5 Hz 640x360 (camera override 'zed2_left_camera')");
}

TEST(CameraOverride, AllAppliesToEveryCameraAndANamedOneWins) {
  const std::string two = std::string(kZedDepth) + R"(
<gazebo reference="base"><sensor type="camera" name="cam2"><update_rate>30</update_rate>
  <camera><horizontal_fov>1.0</horizontal_fov><image><width>640</width><height>480</height></image></camera></sensor></gazebo>)";
  RobotModel m = parse(two);
  ASSERT_EQ(m.sensors.size(), 2u);
  CameraOverride all, named;
  all.height = 120;
  named.rate = 1.0;
  apply_camera_overrides(m, {{"all", all}, {"cam2", named}});
  EXPECT_EQ(std::get<CameraSpec>(m.sensors[0].details).lenses[0].width, 213);  // 120 * 16 / 9 rounded
  EXPECT_EQ(std::get<CameraSpec>(m.sensors[0].details).lenses[0].height, 120);
  EXPECT_DOUBLE_EQ(m.sensors[0].update_rate, 15.0);
  EXPECT_EQ(std::get<CameraSpec>(m.sensors[1].details).lenses[0].width, 640);  // the named override only
  EXPECT_DOUBLE_EQ(m.sensors[1].update_rate, 1.0);
}

TEST(CameraOverride, AnUnknownCameraOrAnImpossibleValueIsAnErrorNamingWhere) {
  RobotModel m = parse(kZedDepth);
  CameraOverride o;
  o.rate = 5.0;
  o.origin = "s.yaml:7";
  try {
    apply_camera_overrides(m, {{"zed2_right", o}});
    FAIL() << "expected an error";
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("s.yaml:7: camera override 'zed2_right': the robot has no camera sensor of that name "
                                    "(its cameras: zed2_left_camera)"));
  }
  o.rate = -1.0;
  try {
    apply_camera_overrides(m, {{"all", o}});
    FAIL() << "expected an error";
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("s.yaml:7: camera override 'all': rate must be > 0 Hz"));
  }
  CameraOverride zero;
  zero.width = 0;
  EXPECT_THROW(apply_camera_overrides(m, {{"all", zero}}), DescriptionError);
  EXPECT_EQ(std::get<CameraSpec>(m.sensors[0].details).lenses[0].width, 1280);  // nothing changed
}

}  // namespace
}  // namespace mechsim::description
