// The sensors gazebo_plugins' own tests use, on a robot of their forms (URDF <gazebo reference>
// <sensor> blocks) in an SDF world, with a real master, published as the plugins publish them:
// - gazebo_ros_range: sensor_msgs/Range of the shortest ray, a box 0.225 m ahead (gazebo_ros' range
//   world: 0.20 < range < 0.25), exactly max_range when nothing is within it;
// - gazebo_ros_laser's intensities: the laser_retro of the SDF collision each ray hits;
// - gazebo_ros_block_laser: sensor_msgs/PointCloud, one unnamed intensity channel;
// - gazebo_ros_bumper: gazebo_msgs/ContactsState of a 1 kg box resting on a plate;
// - cameras: gazebo_ros_triggered_camera (one image per std_msgs/Empty on image_trigger, none
//   otherwise), gazebo_ros_depth_camera's ir/ and depth/ topics and points, 16-bit formats (mono16,
//   rgb16), gazebo_ros_multicamera's left/right topics with equal stamps, and CameraInfo's D and
//   distortion_model as gazebo_ros_camera_utils fills them.
// The node runs as fast as it can; wall-clock bounds are timeouts only.
#include <gmock/gmock.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>

#include <gazebo_msgs/ContactsState.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>
#include <std_msgs/Empty.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// The sensors sit on `base`, fixed 0.5 m above the world's origin; a plate 1.5 m ahead holds the
// falling weight.
const char* kRobot = R"(<?xml version="1.0"?>
<robot name="sensorbot">
  <link name="world"/>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0 0 0.5"/></joint>
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="plate_joint" type="fixed"><parent link="base"/><child link="plate"/><origin xyz="1.5 0 0"/></joint>
  <link name="plate"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><box size="0.6 0.6 0.1"/></geometry></collision></link>

  <gazebo reference="base">
    <sensor type="ray" name="sonar">
      <pose>0.25 0 0 0 0 0</pose><update_rate>5</update_rate>
      <ray><scan><horizontal><samples>5</samples><resolution>1.0</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></horizontal>
        <vertical><samples>5</samples><resolution>1</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></vertical></scan>
        <range><min>0.01</min><max>0.75</max><resolution>0.01</resolution></range></ray>
      <plugin filename="libgazebo_ros_range.so" name="gazebo_ros_range">
        <gaussianNoise>0.001</gaussianNoise><alwaysOn>true</alwaysOn><updateRate>5</updateRate>
        <topicName>sonar</topicName><frameName>sonar_link</frameName><fov>0.5</fov><radiation>ultrasound</radiation>
      </plugin>
    </sensor>
    <sensor type="ray" name="sonar2">
      <pose>0 0 0 0 0 3.14159</pose><update_rate>5</update_rate>
      <ray><scan><horizontal><samples>5</samples><resolution>1.0</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></horizontal>
        <vertical><samples>5</samples><resolution>1</resolution><min_angle>-0.25</min_angle><max_angle>0.25</max_angle></vertical></scan>
        <range><min>0.01</min><max>0.75</max><resolution>0.01</resolution></range></ray>
      <plugin filename="libgazebo_ros_range.so" name="gazebo_ros_range2">
        <gaussianNoise>0.005</gaussianNoise><topicName>sonar2</topicName><frameName>sonar_link2</frameName>
        <fov>0.5</fov><radiation>infrared</radiation>
      </plugin>
    </sensor>
    <sensor type="ray" name="laser">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>20</update_rate>
      <ray><scan><horizontal><samples>61</samples><min_angle>-0.5</min_angle><max_angle>0.5</max_angle></horizontal></scan>
        <range><min>0.1</min><max>5.0</max></range></ray>
      <plugin name="laser" filename="libgazebo_ros_laser.so"><topicName>scan</topicName><frameName>laser_link</frameName></plugin>
    </sensor>
    <sensor type="ray" name="block_laser">
      <pose>0 0 0 0 0 1.5708</pose><update_rate>10</update_rate>
      <ray><scan><horizontal><samples>5</samples><resolution>1</resolution><min_angle>-0.2</min_angle><max_angle>0.2</max_angle></horizontal>
        <vertical><samples>3</samples><resolution>1</resolution><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></vertical></scan>
        <range><min>0.1</min><max>5.0</max></range></ray>
      <plugin name="block" filename="libgazebo_ros_block_laser.so">
        <topicName>block_cloud</topicName><frameName>block_link</frameName><gaussianNoise>0.0</gaussianNoise>
      </plugin>
    </sensor>
    <sensor type="camera" name="trigger_camera">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>10</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height></image><clip><near>0.05</near><far>30</far></clip></camera>
      <plugin name="trig" filename="libgazebo_ros_triggered_camera.so"><cameraName>trig_cam</cameraName><frameName>trig_link</frameName></plugin>
    </sensor>
    <sensor type="depth" name="depth_camera">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>10</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height><format>B8G8R8</format></image><clip><near>0.05</near><far>30</far></clip></camera>
      <plugin name="depth" filename="libgazebo_ros_depth_camera.so"><cameraName>depth_cam</cameraName><frameName>depth_optical</frameName></plugin>
    </sensor>
    <sensor type="camera" name="mono16">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>10</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height><format>L16</format></image><clip><near>0.05</near><far>30</far></clip></camera>
      <plugin name="c16" filename="libgazebo_ros_camera.so"><cameraName>cam16</cameraName><frameName>cam16_link</frameName></plugin>
    </sensor>
    <sensor type="camera" name="rgb16">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>10</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height><format>R16G16B16</format></image><clip><near>0.05</near><far>30</far></clip></camera>
      <plugin name="c48" filename="libgazebo_ros_camera.so"><cameraName>camrgb16</cameraName></plugin>
    </sensor>
    <sensor type="multicamera" name="stereo_camera">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>10</update_rate>
      <camera name="left"><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height></image><clip><near>0.05</near><far>30</far></clip></camera>
      <camera name="right"><pose>0 -0.07 0 0 0 0</pose><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height></image><clip><near>0.05</near><far>30</far></clip></camera>
      <plugin name="stereo" filename="libgazebo_ros_multicamera.so"><cameraName>stereo/camera</cameraName><frameName>left_optical</frameName>
        <hackBaseline>0.07</hackBaseline></plugin>
    </sensor>
    <sensor type="camera" name="distorted_camera">
      <pose>0 0 0 0 0 -1.5708</pose><update_rate>10</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>64</height></image><clip><near>0.05</near><far>30</far></clip>
        <distortion><k1>-0.1</k1><k2>-0.1</k2><p1>0</p1><p2>0</p2><k3>-0.1</k3><center>0.5 0.5</center></distortion></camera>
      <plugin name="dist" filename="libgazebo_ros_camera.so"><cameraName>camera_distorted</cameraName>
        <distortionK1>-0.1</distortionK1><distortionK2>-0.1</distortionK2><distortionT1>0.0</distortionT1>
        <distortionT2>0.0</distortionT2><distortionK3>-0.1</distortionK3><borderCrop>false</borderCrop></plugin>
    </sensor>
  </gazebo>
  <gazebo reference="plate">
    <sensor type="contact" name="plate_contact"><update_rate>50</update_rate>
      <contact><collision>plate_collision</collision></contact>
      <plugin name="bumper" filename="libgazebo_ros_bumper.so"><bumperTopicName>plate_bumper</bumperTopicName><frameName>plate</frameName></plugin>
    </sensor>
  </gazebo>
</robot>
)";

// A box 0.5 m ahead of the base (as gazebo_ros' range world has it), walls to the sides that the
// lasers see, with laser_retro on their collisions, and the 1 kg weight above the plate.
const char* kWorld = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <gravity>0 0 -9.81</gravity>
    <model name="sonar_target"><static>true</static><pose>0.5 0 0.5 0 0 0</pose>
      <link name="link"><collision name="collision"><geometry><box><size>0.05 0.05 0.05</size></box></geometry>
        <laser_retro>100.0</laser_retro></collision></link></model>
    <model name="retro_wall"><static>true</static><pose>0 -2 0.5 0 0 0</pose>
      <link name="link"><collision name="collision"><geometry><box><size>4 0.2 2</size></box></geometry>
        <laser_retro>1000</laser_retro></collision>
        <visual name="visual"><geometry><box><size>4 0.2 2</size></box></geometry></visual></link></model>
    <model name="block_wall"><static>true</static><pose>0 2 0.5 0 0 0</pose>
      <link name="link"><collision name="collision"><geometry><box><size>4 0.2 2</size></box></geometry>
        <laser_retro>250</laser_retro></collision></link></model>
    <model name="weight"><pose>1.5 0 0.66 0 0 0</pose>
      <link name="link"><inertial><mass>1.0</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
        <collision name="collision"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>
  </world>
</sdf>
)";

std::string write(const std::string& name, const char* text) {
  const std::string path = log_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// The last message of a topic and how many came.
template <class M>
class Last {
 public:
  Last(::ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue = 10) {
    sub_ = nh.subscribe<M>(topic, queue, [this](const typename M::ConstPtr& m) {
      std::lock_guard<std::mutex> l(mutex_);
      last_ = *m;
      ++count_;
    });
  }
  ~Last() { sub_.shutdown(); }
  std::size_t count() {
    std::lock_guard<std::mutex> l(mutex_);
    return count_;
  }
  M last() {
    std::lock_guard<std::mutex> l(mutex_);
    return last_;
  }

 private:
  ::ros::Subscriber sub_;
  std::mutex mutex_;
  M last_;
  std::size_t count_ = 0;
};

class GazeboPluginSensors : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
    clock_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 1, [this](const rosgraph_msgs::Clock::ConstPtr& c) {
      now_.store(c->clock.toSec());
    });
    node_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=mechsim_sensorbot", "_model:=" + write("sensorbot.urdf", kRobot),
                                 "_world:=" + write("sensors.world", kWorld)},
        log_dir() + "/node_sensorbot.log");
    ASSERT_TRUE(wait_until([] { return ::ros::topic::waitForMessage<sensor_msgs::Range>("/sonar2", ::ros::Duration(0.5)) != nullptr; },
                           60.0))
        << "the node did not come up; its log:\n" << node_->log();
  }
  void TearDown() override {
    if (node_) {
      EXPECT_EQ(node_->stop(10.0), 0) << "mechsim_node did not stop cleanly; its log:\n" << node_->log();
    }
    clock_.shutdown();
  }
  double clock_seconds() const { return now_.load(); }
  template <class M>
  M wait_for(Last<M>& topic, std::size_t count = 1, double timeout = 30.0) {
    EXPECT_TRUE(wait_until([&] { return topic.count() >= count; }, timeout)) << "the node's log:\n" << node_->log();
    return topic.last();
  }
  std::unique_ptr<ChildProcess> node_;
  ::ros::NodeHandle nh_;
  ::ros::Subscriber clock_;
  std::atomic<double> now_{-1.0};
};

TEST_F(GazeboPluginSensors, RangeOfTheShortestRayAndMaxRangeWhenNothingIsThere) {
  Last<sensor_msgs::Range> sonar(nh_, "/sonar"), sonar2(nh_, "/sonar2");
  const sensor_msgs::Range near = wait_for(sonar, 3), far = wait_for(sonar2, 3);
  // gazebo_plugins' test_range.py, on our world: nominal 0.225 (the box's face 0.475 m, the
  // sensor 0.25 m ahead of the base).
  EXPECT_GT(near.range, 0.20);
  EXPECT_LT(near.range, 0.25);
  EXPECT_NEAR(near.range, 0.225, 0.005);
  EXPECT_EQ(near.header.frame_id, "sonar_link");
  EXPECT_EQ(near.radiation_type, sensor_msgs::Range::ULTRASOUND);
  EXPECT_FLOAT_EQ(near.field_of_view, 0.5f);
  EXPECT_FLOAT_EQ(near.min_range, 0.01f);
  EXPECT_FLOAT_EQ(near.max_range, 0.75f);
  EXPECT_EQ(far.range, far.max_range) << "test_range.py's assertAlmostEqual(range, max_range)";
  EXPECT_EQ(far.radiation_type, sensor_msgs::Range::INFRARED);
  EXPECT_EQ(far.header.frame_id, "sonar_link2");
}

TEST_F(GazeboPluginSensors, LaserIntensitiesAndBlockLaserCloudFromLaserRetro) {
  Last<sensor_msgs::LaserScan> scan(nh_, "/scan");
  Last<sensor_msgs::PointCloud> block(nh_, "/block_cloud");
  const sensor_msgs::LaserScan s = wait_for(scan, 2);
  ASSERT_EQ(s.ranges.size(), 61u);
  ASSERT_EQ(s.intensities.size(), 61u);
  for (std::size_t i = 0; i < s.ranges.size(); ++i) {
    EXPECT_NEAR(s.ranges[i], 1.9 / std::cos(-0.5 + static_cast<double>(i) / 60.0), 1e-3) << i;
    EXPECT_FLOAT_EQ(s.intensities[i], 1000.0f) << "the wall's laser_retro, ray " << i;
  }
  const sensor_msgs::PointCloud c = wait_for(block, 2);
  EXPECT_EQ(c.header.frame_id, "block_link");
  ASSERT_EQ(c.points.size(), 15u);
  ASSERT_EQ(c.channels.size(), 1u);
  EXPECT_EQ(c.channels[0].name, "");
  ASSERT_EQ(c.channels[0].values.size(), 15u);
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    EXPECT_FLOAT_EQ(c.channels[0].values[k], 250.0f) << k;
    // Ray (i, j)'s range to the wall 1.9 m ahead, put half-way towards the next ray (the plugin's way).
    const int i = static_cast<int>(k % 5), j = static_cast<int>(k / 5);
    const double r = 1.9 / (std::cos(-0.2 + 0.1 * i) * std::cos(-0.1 + 0.1 * j));
    const double yaw = -0.2 + 0.05 * (i + std::min(i + 1, 4)), pitch = -0.1 + 0.05 * (j + std::min(j + 1, 2));
    EXPECT_NEAR(c.points[k].x, r * std::cos(pitch) * std::cos(yaw), 2e-5) << "point " << k;
    EXPECT_NEAR(c.points[k].y, r * std::cos(pitch) * std::sin(yaw), 2e-5) << "point " << k;
    EXPECT_NEAR(c.points[k].z, -r * std::sin(pitch), 2e-5) << "point " << k;
  }
  // The plugin's vertical sign: the top row of rays (positive angle) comes out below.
  EXPECT_LT(c.points.back().z, 0.0f);
  EXPECT_GT(c.points.front().z, 0.0f);
}

TEST_F(GazeboPluginSensors, BumperReportsTheWeightOnThePlate) {
  Last<gazebo_msgs::ContactsState> bumper(nh_, "/plate_bumper", 100);
  // The weight falls 1 cm and settles within a second of simulated time.
  ASSERT_TRUE(wait_until([&] { return bumper.count() > 100; }, 60.0)) << node_->log();
  const gazebo_msgs::ContactsState m = bumper.last();
  EXPECT_EQ(m.header.frame_id, "plate");
  ASSERT_EQ(m.states.size(), 1u);
  const gazebo_msgs::ContactState& s = m.states[0];
  EXPECT_EQ(s.collision1_name, "sensorbot::plate::plate_collision");
  EXPECT_EQ(s.collision2_name, "weight::link::collision");
  EXPECT_THAT(s.info, StartsWith("Debug:  i:(0/1)     my geom:sensorbot::plate::plate_collision   other geom:weight::link::collision         time:"));
  EXPECT_NEAR(s.total_wrench.force.z, -9.81, 0.03 * 9.81) << "the weight pushes the plate down";
  ASSERT_FALSE(s.contact_positions.empty());
  EXPECT_EQ(s.contact_positions.size(), s.wrenches.size());
  EXPECT_EQ(s.contact_positions.size(), s.contact_normals.size());
  EXPECT_EQ(s.contact_positions.size(), s.depths.size());
  for (std::size_t i = 0; i < s.contact_positions.size(); ++i) {
    EXPECT_NEAR(s.contact_positions[i].z, 0.55, 0.003) << "world frame: the plate's top";
    EXPECT_NEAR(s.contact_positions[i].x, 1.5, 0.11);
    EXPECT_NEAR(s.contact_normals[i].z, -1.0, 1e-3) << "pushing the plate away from the weight";
  }
}

// gazebo_plugins' triggered_camera test: no image without a trigger, the node listens on
// image_trigger, one image per trigger (two quick triggers: two images).
TEST_F(GazeboPluginSensors, TriggeredCameraPublishesOneImagePerTrigger) {
  Last<sensor_msgs::Image> image(nh_, "/trig_cam/image_raw", 5);
  ASSERT_TRUE(wait_until([&] { return clock_seconds() > 1.0; }, 30.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_EQ(image.count(), 0u);
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ::ros::this_node::getName();
  ASSERT_TRUE(::ros::master::execute("getSystemState", args, result, payload, true));
  int listeners = 0;
  for (int i = 0; i < payload[1].size(); ++i)
    if (std::string(payload[1][i][0]) == "/trig_cam/image_trigger") listeners += payload[1][i][1].size();
  EXPECT_EQ(listeners, 1);

  ::ros::Publisher trigger = nh_.advertise<std_msgs::Empty>("/trig_cam/image_trigger", 1, true);
  ASSERT_TRUE(wait_until([&] { return trigger.getNumSubscribers() > 0; }, 10.0));
  trigger.publish(std_msgs::Empty());
  ASSERT_TRUE(wait_until([&] { return image.count() >= 1; }, 10.0)) << node_->log();
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  EXPECT_EQ(image.count(), 1u);
  const sensor_msgs::Image im = image.last();
  EXPECT_EQ(im.width, 64u);
  EXPECT_EQ(im.header.frame_id, "trig_link");
  trigger.publish(std_msgs::Empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  trigger.publish(std_msgs::Empty());
  ASSERT_TRUE(wait_until([&] { return image.count() >= 3; }, 10.0)) << image.count() << " images";
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  EXPECT_EQ(image.count(), 3u);
}

TEST_F(GazeboPluginSensors, DepthCameraTopicsAndSixteenBitImages) {
  Last<sensor_msgs::Image> ir(nh_, "/depth_cam/ir/image_raw"), depth(nh_, "/depth_cam/depth/image_raw");
  Last<sensor_msgs::PointCloud2> points(nh_, "/depth_cam/points");
  Last<sensor_msgs::CameraInfo> ir_info(nh_, "/depth_cam/ir/camera_info"), depth_info(nh_, "/depth_cam/depth/camera_info");
  Last<sensor_msgs::Image> mono16(nh_, "/cam16/image_raw"), rgb16(nh_, "/camrgb16/image_raw");
  const sensor_msgs::Image d = wait_for(depth, 2);
  EXPECT_EQ(d.encoding, "32FC1");
  ASSERT_EQ(d.data.size(), 64u * 48 * 4);
  float centre = 0;
  std::memcpy(&centre, &d.data[(24 * 64 + 32) * 4], 4);
  EXPECT_NEAR(centre, 1.9, 0.01) << "the wall 1.9 m ahead along the optical axis";
  const sensor_msgs::Image colour = wait_for(ir, 2);
  EXPECT_EQ(colour.encoding, "bgr8");
  EXPECT_EQ(colour.header.frame_id, "depth_optical");
  const sensor_msgs::PointCloud2 cloud = wait_for(points, 2);
  EXPECT_EQ(cloud.width, 64u);
  EXPECT_EQ(cloud.height, 48u);
  EXPECT_EQ(cloud.point_step, 32u);
  EXPECT_EQ(wait_for(ir_info).width, 64u);
  EXPECT_EQ(wait_for(depth_info).height, 48u);

  const sensor_msgs::Image m = wait_for(mono16, 2);
  EXPECT_EQ(m.encoding, "mono16");
  EXPECT_EQ(m.step, 64u * 2);
  ASSERT_EQ(m.data.size(), 64u * 48 * 2);
  const sensor_msgs::Image c = wait_for(rgb16, 2);
  EXPECT_EQ(c.encoding, "rgb16");
  EXPECT_EQ(c.step, 64u * 6);
  ASSERT_EQ(c.data.size(), 64u * 48 * 6);
  // 8-bit levels spread over 16 bits: each value is a multiple of 257; the lit wall fills the view.
  for (std::size_t k = 0; k + 1 < m.data.size(); k += 2) ASSERT_EQ((m.data[k] | (m.data[k + 1] << 8)) % 257, 0) << k;
  for (std::size_t k = 0; k + 1 < c.data.size(); k += 2) ASSERT_EQ((c.data[k] | (c.data[k + 1] << 8)) % 257, 0) << k;
  EXPECT_GT(m.data[2 * (24 * 64 + 32)], 0) << "not a black image";
}

TEST_F(GazeboPluginSensors, MulticameraLeftAndRightAndDistortionInCameraInfo) {
  Last<sensor_msgs::Image> left(nh_, "/stereo/camera/left/image_raw", 20), right(nh_, "/stereo/camera/right/image_raw", 20);
  Last<sensor_msgs::CameraInfo> right_info(nh_, "/stereo/camera/right/camera_info");
  Last<sensor_msgs::CameraInfo> dist_info(nh_, "/camera_distorted/camera_info");
  Last<sensor_msgs::Image> dist(nh_, "/camera_distorted/image_raw");
  const sensor_msgs::Image l = wait_for(left, 3), r = wait_for(right, 3);
  EXPECT_EQ(l.header.stamp, r.header.stamp) << "one sensor, one instant";
  EXPECT_EQ(l.width, 64u);
  const sensor_msgs::CameraInfo ri = wait_for(right_info);
  EXPECT_NEAR(ri.P[3], -ri.P[0] * 0.07, 1e-9);
  const sensor_msgs::CameraInfo di = wait_for(dist_info);
  EXPECT_EQ(di.distortion_model, "plumb_bob");
  ASSERT_EQ(di.D.size(), 5u);
  EXPECT_EQ(di.D, (std::vector<double>{-0.1, -0.1, 0.0, 0.0, -0.1}));
  EXPECT_EQ(wait_for(dist).width, 64u);
}

}  // namespace
}  // namespace mechsim::ros::test
