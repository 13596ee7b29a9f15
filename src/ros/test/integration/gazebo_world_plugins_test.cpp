// gzserver mode: the model plugins gazebo_plugins' tests and users' worlds use, in an SDF world's
// models and on spawned robots, on their gazebo_plugins topics (issue: Gazebo's own tests). One
// world per plugin group, the test's own:
//   - drives: skid steer, planar move, tricycle drive and Gazebo's own libDiffDrivePlugin.so in
//     world models, a tricycle and a libDiffDrivePlugin robot spawned from URDF;
//   - sensor-like plugins: p3d, the gazebo_ros_imu model plugin, an IMU sensor, a bumper (contact
//     sensor) and the joint state publisher.
#include <gmock/gmock.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <gazebo_msgs/ContactsState.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

#include "gazebo_world_fixture.hpp"

namespace mechsim::ros::test {
namespace {

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

const char* const kWheelInertia = "<inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial>";

// An SDF wheel link `name` at (x, y, z) of its model: a cylinder of radius 0.06 on its side.
std::string sdf_wheel(const std::string& name, double x, double y, double z = 0.0) {
  return "<link name=\"" + name + "\"><pose>" + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) +
         " -1.5707963 0 0</pose>" + kWheelInertia +
         "<collision name=\"c\"><geometry><cylinder><radius>0.06</radius><length>0.03</length></cylinder></geometry>"
         "</collision></link>";
}

std::string sdf_joint(const std::string& name, const std::string& parent, const std::string& child, const char* axis = "0 1 0") {
  return "<joint name=\"" + name + "\" type=\"revolute\"><parent>" + parent + "</parent><child>" + child + "</child><axis><xyz>" +
         axis + "</xyz><use_parent_model_frame>true</use_parent_model_frame></axis></joint>";
}

std::string chassis(double length, double width, double mass = 5.0) {
  return "<link name=\"chassis\"><inertial><mass>" + std::to_string(mass) +
         "</mass><inertia><ixx>0.05</ixx><iyy>0.05</iyy><izz>0.05</izz></inertia></inertial>"
         "<collision name=\"c\"><pose>0 0 0.05 0 0 0</pose><geometry><box><size>" +
         std::to_string(length) + " " + std::to_string(width) + " 0.05</size></box></geometry></collision></link>";
}

// A frictionless caster ball under the chassis at x.
std::string caster(double x) {
  return "<link name=\"caster\"><pose>" + std::to_string(x) +
         " 0 -0.01 0 0 0</pose><inertial><mass>0.1</mass><inertia><ixx>1e-4</ixx><iyy>1e-4</iyy><izz>1e-4</izz></inertia>"
         "</inertial><collision name=\"c\"><geometry><sphere><radius>0.05</radius></sphere></geometry><surface><friction><ode>"
         "<mu>0</mu><mu2>0</mu2></ode></friction></surface></collision></link>"
         "<joint name=\"caster_fix\" type=\"fixed\"><parent>chassis</parent><child>caster</child></joint>";
}

std::string drive_world() {
  std::string w = R"(<?xml version="1.0"?>
<sdf version="1.6"><world name="default">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://sun</uri></include>)";
  // Skid steer: four wheels, world odometry with its TF.
  w += "<model name=\"skid\"><pose>0 3 0.06 0 0 0</pose>" + chassis(0.4, 0.3) + sdf_wheel("lf", 0.12, 0.18) +
       sdf_wheel("rf", 0.12, -0.18) + sdf_wheel("lr", -0.12, 0.18) + sdf_wheel("rr", -0.12, -0.18) +
       sdf_joint("lf_joint", "chassis", "lf") + sdf_joint("rf_joint", "chassis", "rf") + sdf_joint("lr_joint", "chassis", "lr") +
       sdf_joint("rr_joint", "chassis", "rr") + R"(
    <plugin name="skid_steer" filename="libgazebo_ros_skid_steer_drive.so">
      <leftFrontJoint>lf_joint</leftFrontJoint><rightFrontJoint>rf_joint</rightFrontJoint>
      <leftRearJoint>lr_joint</leftRearJoint><rightRearJoint>rr_joint</rightRearJoint>
      <wheelSeparation>0.36</wheelSeparation><wheelDiameter>0.12</wheelDiameter><torque>5</torque>
      <commandTopic>skid/cmd_vel</commandTopic><odometryTopic>skid/odom</odometryTopic>
      <odometryFrame>skid_odom</odometryFrame><robotBaseFrame>chassis</robotBaseFrame><broadcastTF>1</broadcastTF>
    </plugin></model>)";
  // Planar move: a box moved by its velocity command.
  w += R"(<model name="planar"><pose>0 6 0.1 0 0 0</pose><link name="body">
      <inertial><mass>2</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link>
    <plugin name="object_controller" filename="libgazebo_ros_planar_move.so">
      <commandTopic>planar/cmd_vel</commandTopic><odometryTopic>planar/odom</odometryTopic>
      <odometryFrame>planar_odom</odometryFrame><odometryRate>20.0</odometryRate><robotBaseFrame>body</robotBaseFrame>
    </plugin></model>)";
  // Tricycle: a steered, driven front wheel 0.3 m ahead of two encoder wheels. No robotNamespace:
  // gazebo_plugins' GazeboRos helper puts a world model's plugin under the model's name (topics
  // /trike/..., frames trike/...), unlike the skid steer's and planar move's (the root).
  w += "<model name=\"trike\"><pose>0 -3 0.06 0 0 0</pose>" + chassis(0.45, 0.3) +
       R"(<link name="fork"><pose>0.2 0 0 0 0 0</pose><inertial><mass>0.2</mass><inertia><ixx>1e-4</ixx><iyy>1e-4</iyy>
       <izz>1e-4</izz></inertia></inertial></link>)" +
       sdf_wheel("front_wheel", 0.2, 0.0) + sdf_wheel("left_wheel", -0.1, 0.15) + sdf_wheel("right_wheel", -0.1, -0.15) +
       sdf_joint("front_steering_joint", "chassis", "fork", "0 0 1") + sdf_joint("front_wheel_joint", "fork", "front_wheel") +
       sdf_joint("left_wheel_joint", "chassis", "left_wheel") + sdf_joint("right_wheel_joint", "chassis", "right_wheel") + R"(
    <plugin name="tricycle_drive" filename="libgazebo_ros_tricycle_drive.so">
      <actuatedWheelDiameter>0.12</actuatedWheelDiameter><encoderWheelDiameter>0.12</encoderWheelDiameter>
      <encoderWheelSeparation>0.3</encoderWheelSeparation><odometrySource>encoder</odometrySource>
      <commandTopic>cmd_vel</commandTopic><odometryTopic>odom</odometryTopic>
      <odometryFrame>odom</odometryFrame><robotBaseFrame>chassis</robotBaseFrame>
      <publishWheelJointState>true</publishWheelJointState><updateRate>50</updateRate>
    </plugin></model>)";
  // Gazebo's own diff drive: no ROS, commanded on /gzdd/vel_cmd.
  w += "<model name=\"gzdd\"><pose>0 -6 0.06 0 0 0</pose>" + chassis(0.4, 0.3) + caster(-0.15) + sdf_wheel("left_wheel", 0.1, 0.2) +
       sdf_wheel("right_wheel", 0.1, -0.2) + sdf_joint("left_wheel_hinge", "chassis", "left_wheel") +
       sdf_joint("right_wheel_hinge", "chassis", "right_wheel") + R"(
    <plugin name="diff_drive" filename="libDiffDrivePlugin.so">
      <left_joint>left_wheel_hinge</left_joint><right_joint>right_wheel_hinge</right_joint><torque>5</torque>
    </plugin></model>
</world></sdf>)";
  return w;
}

// A tricycle in URDF, spawned: gazebo_plugins' default joint names, its topics under the spawn's
// robot namespace.
const char* const kTricycleUrdf = R"(<robot name="tricycle">
  <link name="base_link">
    <inertial><mass value="5"/><inertia ixx="0.05" iyy="0.05" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0.05 0 0.05"/><geometry><box size="0.45 0.3 0.05"/></geometry></collision>
  </link>
  <link name="fork"><inertial><mass value="0.2"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="front_steering_joint" type="revolute"><parent link="base_link"/><child link="fork"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 0 1"/><limit lower="-1.6" upper="1.6" effort="20" velocity="5"/></joint>
  <link name="front_wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963 0 0"/><geometry><cylinder radius="0.06" length="0.03"/></geometry></collision>
  </link>
  <joint name="front_wheel_joint" type="continuous"><parent link="fork"/><child link="front_wheel"/><axis xyz="0 1 0"/></joint>
  <link name="left_wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963 0 0"/><geometry><cylinder radius="0.06" length="0.03"/></geometry></collision>
  </link>
  <joint name="left_wheel_joint" type="continuous"><parent link="base_link"/><child link="left_wheel"/>
    <origin xyz="-0.1 0.15 0"/><axis xyz="0 1 0"/></joint>
  <link name="right_wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963 0 0"/><geometry><cylinder radius="0.06" length="0.03"/></geometry></collision>
  </link>
  <joint name="right_wheel_joint" type="continuous"><parent link="base_link"/><child link="right_wheel"/>
    <origin xyz="-0.1 -0.15 0"/><axis xyz="0 1 0"/></joint>
  <gazebo>
    <plugin name="tricycle_drive" filename="libgazebo_ros_tricycle_drive.so">
      <actuatedWheelDiameter>0.12</actuatedWheelDiameter><encoderWheelDiameter>0.12</encoderWheelDiameter>
      <encoderWheelSeparation>0.3</encoderWheelSeparation>
    </plugin>
  </gazebo>
</robot>)";

TEST_F(GazeboWorldNode, DrivePluginsOfWorldModelsAndSpawnedRobotsDriveOnGazebosTopics) {
  start(false, write_world("drive_plugins.world", drive_world()));
  gazebo_msgs::SpawnModel s;
  s.request.model_name = "t2";
  s.request.model_xml = kTricycleUrdf;
  s.request.robot_namespace = "/t2";
  s.request.initial_pose = pose_at(3.0, -3.0, 0.07);
  ASSERT_TRUE(call("/gazebo/spawn_urdf_model", s));
  ASSERT_TRUE(s.response.success) << s.response.status_message << "\n" << node_->log();

  // Spawned with an empty robot_namespace, gazebo_plugins' GazeboRos puts it under its model name.
  gazebo_msgs::SpawnModel bare;
  bare.request.model_name = "t3";
  bare.request.model_xml = kTricycleUrdf;
  bare.request.initial_pose = pose_at(3.0, -6.0, 0.07);
  ASSERT_TRUE(call("/gazebo/spawn_urdf_model", bare));
  ASSERT_TRUE(bare.response.success) << bare.response.status_message;
  ::ros::Publisher t3_cmd = nh_.advertise<geometry_msgs::Twist>("/t3/cmd_vel", 1);
  Latest<nav_msgs::Odometry> t3_odom(nh_, "/t3/odom");

  ::ros::Publisher skid_cmd = nh_.advertise<geometry_msgs::Twist>("/skid/cmd_vel", 1);
  ::ros::Publisher planar_cmd = nh_.advertise<geometry_msgs::Twist>("/planar/cmd_vel", 1);
  ::ros::Publisher trike_cmd = nh_.advertise<geometry_msgs::Twist>("/trike/cmd_vel", 1);
  ::ros::Publisher t2_cmd = nh_.advertise<geometry_msgs::Twist>("/t2/cmd_vel", 1);
  ::ros::Publisher gzdd_cmd = nh_.advertise<geometry_msgs::Pose>("/gzdd/vel_cmd", 1);
  Latest<nav_msgs::Odometry> skid_odom(nh_, "/skid/odom"), planar_odom(nh_, "/planar/odom"), trike_odom(nh_, "/trike/odom"),
      t2_odom(nh_, "/t2/odom");
  Latest<sensor_msgs::JointState> trike_joints(nh_, "/trike/joint_states");
  ASSERT_TRUE(wait_until(
      [&] {
        return skid_cmd.getNumSubscribers() > 0 && planar_cmd.getNumSubscribers() > 0 && trike_cmd.getNumSubscribers() > 0 &&
               t2_cmd.getNumSubscribers() > 0 && gzdd_cmd.getNumSubscribers() > 0 && skid_odom.received() > 0 &&
               planar_odom.received() > 0 && trike_odom.received() > 0 && t2_odom.received() > 0;
      },
      20.0))
      << "a drive plugin has no command subscriber or odometry; log:\n" << node_->log();
  EXPECT_EQ(skid_odom.get().header.frame_id, "skid_odom");
  EXPECT_EQ(skid_odom.get().child_frame_id, "chassis");
  EXPECT_EQ(t2_odom.get().header.frame_id, "t2/odom");  // the spawn's namespace is the TF prefix
  EXPECT_EQ(t2_odom.get().child_frame_id, "t2/base_link");  // the tricycle's default robotBaseFrame
  EXPECT_TRUE(wait_until([&] { return t3_cmd.getNumSubscribers() > 0 && t3_odom.received() > 0; }, 10.0))
      << "the tricycle spawned without a namespace is not on /t3/cmd_vel, /t3/odom";
  EXPECT_EQ(t3_odom.get().child_frame_id, "t3/base_link");
  EXPECT_EQ(trike_odom.get().header.frame_id, "trike/odom");
  EXPECT_EQ(trike_odom.get().child_frame_id, "trike/chassis");

  // Libdiffdriveplugin: nothing moves it before its first command.
  const auto start_of = [&](const char* m) { return model_state(m).response.pose; };
  const geometry_msgs::Pose skid0 = start_of("skid"), planar0 = start_of("planar"), trike0 = start_of("trike"),
                            t20 = start_of("t2"), gzdd0 = start_of("gzdd");
  const double t_idle = clock_now();
  wait_until([&] { return clock_now() - t_idle > 0.5; }, 10.0);
  EXPECT_NEAR(model_state("gzdd").response.pose.position.x, gzdd0.position.x, 0.005) << "libDiffDrivePlugin moved without a command";

  geometry_msgs::Twist forward;  // skid steer: 0.3 m/s ahead
  forward.linear.x = 0.3;
  geometry_msgs::Twist sideways;  // planar move: 0.2 m/s to its left, holonomic
  sideways.linear.y = 0.2;
  geometry_msgs::Twist steer_left;  // tricycle: the front wheel at 0.3 m/s, steered 0.4 rad left
  steer_left.linear.x = 0.3;
  steer_left.angular.z = 0.4;
  geometry_msgs::Twist straight;  // the spawned tricycle: straight ahead at 0.25 m/s
  straight.linear.x = 0.25;
  geometry_msgs::Pose gz;  // Gazebo's vel_cmd pose: 0.2 m/s, yaw rate 0.5 rad/s (clockwise)
  gz.position.x = 0.2;
  gz.orientation.z = std::sin(0.25);
  gz.orientation.w = std::cos(0.25);
  // 2 s of simulated time, the commands repeated as a teleop node does.
  const double t0 = clock_now();
  wait_until([&] {
    skid_cmd.publish(forward);
    planar_cmd.publish(sideways);
    trike_cmd.publish(steer_left);
    t2_cmd.publish(straight);
    gzdd_cmd.publish(gz);
    return clock_now() - t0 > 2.0;
  }, 30.0);
  const geometry_msgs::Pose skid1 = model_state("skid").response.pose, planar1 = model_state("planar").response.pose,
                            trike1 = model_state("trike").response.pose, t21 = model_state("t2").response.pose, gzdd1 = model_state("gzdd").response.pose;

  const double skid_moved = skid1.position.x - skid0.position.x;
  EXPECT_GT(skid_moved, 0.4) << "the skid steer moved " << skid_moved << " m in 2 s at 0.3 m/s";
  EXPECT_NEAR(skid_odom.get().pose.pose.position.x, skid1.position.x, 0.05);  // world odometry

  EXPECT_NEAR(planar1.position.y - planar0.position.y, 0.4, 0.08) << "planar move, 2 s at 0.2 m/s along y";
  EXPECT_NEAR(planar1.position.x, planar0.position.x, 0.02);
  EXPECT_NEAR(planar_odom.get().pose.pose.position.y, planar1.position.y, 0.03);

  // The tricycle turns left (yaw rate v sin(0.4) / 0.3 = 0.39 rad/s at the front wheel's 0.3 m/s),
  // and its encoder odometry turns the same way.
  const double trike_yaw = yaw_of(trike1.orientation) - yaw_of(trike0.orientation);
  EXPECT_GT(trike_yaw, 0.3) << "the tricycle turned " << trike_yaw << " rad";
  EXPECT_GT(trike1.position.x - trike0.position.x, 0.25);
  EXPECT_NEAR(yaw_of(trike_odom.get().pose.pose.orientation), trike_yaw, 0.25);
  EXPECT_GT(trike_odom.get().twist.twist.angular.z, 0.1);
  const sensor_msgs::JointState js = trike_joints.get();
  ASSERT_EQ(js.name.size(), 4u) << "the tricycle's publishWheelJointState";
  EXPECT_EQ(js.name[0], "front_steering_joint");
  EXPECT_NEAR(js.position[0], 0.4, 0.05);

  const double t2_moved = t21.position.x - t20.position.x;
  EXPECT_GT(t2_moved, 0.3) << "the spawned tricycle moved " << t2_moved << " m at 0.25 m/s for 2 s";
  EXPECT_NEAR(std::abs(yaw_of(t21.orientation)), 0.0, 0.1);
  EXPECT_NEAR(t2_odom.get().pose.pose.position.x, t21.position.x, 0.05);  // world odometry (the default)

  std::printf("[ figures  ] world models, 2 s: skid steer %.3f m at 0.3 m/s; planar move %.3f m along y at 0.2 m/s; "
              "tricycle (0.3 m/s, steered 0.4 rad) turned %.3f rad, its encoder odometry %.3f rad; spawned tricycle "
              "%.3f m at 0.25 m/s; libDiffDrivePlugin turned %.3f rad (0.5 rad/s clockwise)\n",
              skid_moved, planar1.position.y - planar0.position.y, trike_yaw, yaw_of(trike_odom.get().pose.pose.orientation),
              t21.position.x - t20.position.x, yaw_of(gzdd1.orientation) - yaw_of(gzdd0.orientation));
  // libDiffDrivePlugin: forward and clockwise.
  const double gzdd_yaw = yaw_of(gzdd1.orientation) - yaw_of(gzdd0.orientation);
  EXPECT_LT(gzdd_yaw, -0.4) << "libDiffDrivePlugin's positive yaw rate turns clockwise; it turned " << gzdd_yaw;
  EXPECT_GT(std::hypot(gzdd1.position.x - gzdd0.position.x, gzdd1.position.y - gzdd0.position.y), 0.2);
}

// Sensor-like plugins in world models, each in the form gazebo_plugins' test worlds use.
const char* const kSensorPluginWorld = R"(<?xml version="1.0"?>
<sdf version="1.6"><world name="default">
  <include><uri>model://ground_plane</uri></include>
  <model name="imu_box">
    <pose>0 0 0.1 0 0 0.5</pose>
    <link name="link">
      <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="collision"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      <sensor name="imu_sensor" type="imu">
        <always_on>true</always_on><update_rate>100</update_rate>
        <plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so">
          <topicName>/imu_box/sensor</topicName><bodyName>link</bodyName><updateRateHZ>100</updateRateHZ>
          <gaussianNoise>0</gaussianNoise><frameName>imu_sensor_link</frameName>
        </plugin>
      </sensor>
    </link>
    <plugin name="imu" filename="libgazebo_ros_imu.so">
      <bodyName>link</bodyName><topicName>imu_box/data</topicName><serviceName>imu_box/calibrate</serviceName>
      <updateRate>50</updateRate><frameName>imu_box_link</frameName><gaussianNoise>0</gaussianNoise>
    </plugin>
  </model>
  <model name="bumper_box">
    <pose>2 0 0.1 0 0 0</pose>
    <link name="link">
      <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="collision"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      <sensor name="bumper" type="contact">
        <always_on>true</always_on><update_rate>50</update_rate>
        <contact><collision>collision</collision></contact>
        <plugin name="bumper_plugin" filename="libgazebo_ros_bumper.so">
          <bumperTopicName>/bumper_box/bumper</bumperTopicName><frameName>world</frameName>
        </plugin>
      </sensor>
    </link>
  </model>
  <model name="p3d_box">
    <pose>-2 0 0.1 0 0 0</pose>
    <link name="link">
      <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="collision"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    </link>
    <plugin name="p3d" filename="libgazebo_ros_p3d.so">
      <alwaysOn>true</alwaysOn><updateRate>50</updateRate><bodyName>link</bodyName>
      <topicName>p3d_box/odom</topicName><frameName>world</frameName><gaussianNoise>0</gaussianNoise>
    </plugin>
  </model>
  <model name="pendulum">
    <pose>0 3 0 0 0 0</pose>
    <link name="post">
      <pose>0 0 1 0 0 0</pose>
      <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    </link>
    <joint name="fix" type="fixed"><parent>world</parent><child>post</child></joint>
    <link name="arm">
      <pose>0.25 0 1 0 0 0</pose>
      <inertial><mass>0.5</mass><inertia><ixx>0.0001</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>0.5 0.02 0.02</size></box></geometry></collision>
    </link>
    <joint name="hinge" type="revolute"><parent>post</parent><child>arm</child><pose>-0.25 0 0 0 0 0</pose>
      <axis><xyz>0 1 0</xyz></axis></joint>
    <plugin name="joint_state_publisher" filename="libgazebo_ros_joint_state_publisher.so">
      <jointName>hinge</jointName><updateRate>50</updateRate>
    </plugin>
  </model>
</world></sdf>)";

TEST_F(GazeboWorldNode, SensorPluginsOfWorldModelsPublishOnGazebosTopics) {
  start(false, write_world("sensor_plugins.world", kSensorPluginWorld));
  Latest<sensor_msgs::Imu> imu_plugin(nh_, "/imu_box/data"), imu_sensor(nh_, "/imu_box/sensor");
  Latest<gazebo_msgs::ContactsState> bumper(nh_, "/bumper_box/bumper");
  Latest<nav_msgs::Odometry> p3d(nh_, "/p3d_box/odom");
  std::mutex js_mutex;
  std::vector<sensor_msgs::JointState> js;
  // A world model's joint state publisher is under the model's name (gazebo_plugins' GazeboRos).
  ::ros::Subscriber js_sub = nh_.subscribe<sensor_msgs::JointState>("/pendulum/joint_states", 100,
                                                                    [&](const sensor_msgs::JointState::ConstPtr& m) {
                                                                      std::lock_guard<std::mutex> l(js_mutex);
                                                                      js.push_back(*m);
                                                                    });
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(js_mutex);
        return imu_plugin.received() > 5 && imu_sensor.received() > 5 && bumper.received() > 5 && p3d.received() > 5 &&
               js.size() > 25;
      },
      20.0))
      << "imu plugin " << imu_plugin.received() << ", imu sensor " << imu_sensor.received() << ", bumper " << bumper.received()
      << ", p3d " << p3d.received() << ", joint states " << js.size() << "; log:\n"
      << node_->log();

  // gazebo_ros_imu: the body's world orientation (yawed 0.5 rad), in its frameName. (Its linear
  // acceleration is not asserted: gazebo_ros_imu differentiates the body's world velocity, 0 at
  // rest, where mechsim's sensors/ reports the specific force, 9.8 m/s^2 up.)
  const sensor_msgs::Imu a = imu_plugin.get();
  EXPECT_EQ(a.header.frame_id, "imu_box_link");
  EXPECT_NEAR(yaw_of(a.orientation), 0.5, 0.01);
  // An IMU sensor feels gravity's reaction at rest.
  const sensor_msgs::Imu b = imu_sensor.get();
  EXPECT_EQ(b.header.frame_id, "imu_sensor_link");
  EXPECT_NEAR(b.linear_acceleration.z, 9.8, 0.3);

  // The bumper: the box's contacts with the ground, their forces in the world frame bearing its
  // weight.
  const gazebo_msgs::ContactsState c = bumper.get();
  EXPECT_EQ(c.header.frame_id, "world");
  ASSERT_FALSE(c.states.empty()) << "the box resting on the ground touches nothing";
  double fz = 0.0;
  for (const gazebo_msgs::ContactState& st : c.states) fz += st.total_wrench.force.z;
  EXPECT_NEAR(std::abs(fz), 9.81, 3.0);
  EXPECT_THAT(c.states[0].collision1_name, ::testing::HasSubstr("collision"));

  // p3d: the body's pose in the world frame.
  const nav_msgs::Odometry o = p3d.get();
  EXPECT_EQ(o.header.frame_id, "world");
  EXPECT_EQ(o.child_frame_id, "link");
  EXPECT_NEAR(o.pose.pose.position.x, model_state("p3d_box").response.pose.position.x, 1e-3);
  EXPECT_NEAR(o.pose.pose.position.z, 0.1, 0.01);

  // The joint state publisher: the pendulum's hinge at 50 Hz, swinging.
  std::lock_guard<std::mutex> l(js_mutex);
  ASSERT_EQ(js.back().name, std::vector<std::string>{"hinge"});
  ASSERT_EQ(js.back().position.size(), 1u);
  EXPECT_NEAR((js.back().header.stamp - js[js.size() - 2].header.stamp).toSec(), 0.02, 1e-6);
  double lowest = 0.0, highest = 0.0;
  for (const sensor_msgs::JointState& m : js) {
    lowest = std::min(lowest, m.position[0]);
    highest = std::max(highest, m.position[0]);
  }
  EXPECT_GT(highest - lowest, 0.5) << "the pendulum did not swing";
}

}  // namespace
}  // namespace mechsim::ros::test
