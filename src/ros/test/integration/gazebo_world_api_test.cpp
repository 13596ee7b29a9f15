// gzserver mode as gazebo_ros' own tests use it (issue: Gazebo's own tests): an SDF world whose
// models carry sensors and model plugins, run before any spawn; what sdformat 12 refuses and
// Gazebo 11 reads; robots spawned twice from one description under two namespaces; a robot fixed
// to the world; gazebo_ros_api_plugin's exact list of topics and services (with and without
// enable_ros_network); lights, joint and link properties and the physics dynamic_reconfigure.
// Worlds and robots are the test's own, in the forms gazebo_ros' tests use.
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/DeleteLight.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLightProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/SetJointProperties.h>
#include <gazebo_msgs/SetLightProperties.h>
#include <gazebo_msgs/SetLinkProperties.h>
#include <gazebo_msgs/SetModelState.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>

#include "gazebo_world_fixture.hpp"

namespace mechsim::ros::test {
namespace {

// A world in the forms of gazebo_ros' test worlds: Gazebo's library models, an old-style material
// script by name, a static model with a laser and its ROS plugin, a box whose p3d plugin publishes
// its pose, a moving box, and a small diff-drive robot driven by its plugin (no <robotNamespace>:
// gazebo_plugins put it under the model's name, so its cmd_vel is /rover/cmd_vel).
const char* const kSensorWorld = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <include><uri>model://ground_plane</uri></include>
    <include><uri>model://sun</uri></include>
    <include><uri>model://checkerboard_plane</uri><pose>3 0 0 0 0 3.14159</pose></include>
    <model name="green_box">
      <pose>2 0 0.25 0 0 0</pose>
      <link name="link">
        <inertial><mass>1</mass><inertia><ixx>0.04</ixx><iyy>0.04</iyy><izz>0.04</izz></inertia></inertial>
        <collision name="collision"><geometry><box><size>0.5 0.5 0.5</size></box></geometry></collision>
        <visual name="visual"><geometry><box><size>0.5 0.5 0.5</size></box></geometry>
          <material><script>Gazebo/Green</script></material></visual>
      </link>
    </model>
    <model name="laser_post">
      <static>true</static>
      <pose>0 0 0.25 0 0 0</pose>
      <link name="link">
        <sensor name="post_laser" type="ray">
          <update_rate>20</update_rate>
          <ray>
            <scan><horizontal><samples>91</samples><min_angle>-0.785</min_angle><max_angle>0.785</max_angle></horizontal></scan>
            <range><min>0.1</min><max>10</max></range>
          </ray>
          <plugin name="post_laser_plugin" filename="libgazebo_ros_laser.so">
            <topicName>/post/scan</topicName>
            <frameName>post_laser_link</frameName>
          </plugin>
        </sensor>
      </link>
    </model>
    <model name="tracked_box">
      <pose>-2 1 0.1 0 0 0</pose>
      <link name="link">
        <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
        <collision name="collision"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      </link>
      <plugin name="p3d" filename="libgazebo_ros_p3d.so">
        <bodyName>link</bodyName>
        <topicName>/tracked_box/pose</topicName>
        <frameName>world</frameName>
        <updateRate>50</updateRate>
      </plugin>
    </model>
    <model name="rover">
      <pose>0 -2 0.06 0 0 0</pose>
      <link name="chassis">
        <inertial><mass>5</mass><inertia><ixx>0.05</ixx><iyy>0.05</iyy><izz>0.05</izz></inertia></inertial>
        <collision name="c"><pose>0 0 0.05 0 0 0</pose><geometry><box><size>0.4 0.3 0.05</size></box></geometry></collision>
        <collision name="caster"><pose>-0.15 0 -0.01 0 0 0</pose><geometry><sphere><radius>0.05</radius></sphere></geometry>
          <surface><friction><ode><mu>0</mu><mu2>0</mu2></ode></friction></surface></collision>
      </link>
      <link name="left_wheel">
        <pose>0.1 0.2 0 -1.5707963 0 0</pose>
        <inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial>
        <collision name="c"><geometry><cylinder><radius>0.06</radius><length>0.03</length></cylinder></geometry></collision>
      </link>
      <link name="right_wheel">
        <pose>0.1 -0.2 0 -1.5707963 0 0</pose>
        <inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial>
        <collision name="c"><geometry><cylinder><radius>0.06</radius><length>0.03</length></cylinder></geometry></collision>
      </link>
      <joint name="left_wheel_joint" type="revolute"><parent>chassis</parent><child>left_wheel</child>
        <axis><xyz>0 1 0</xyz><use_parent_model_frame>true</use_parent_model_frame></axis></joint>
      <joint name="right_wheel_joint" type="revolute"><parent>chassis</parent><child>right_wheel</child>
        <axis><xyz>0 1 0</xyz><use_parent_model_frame>true</use_parent_model_frame></axis></joint>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <leftJoint>left_wheel_joint</leftJoint>
        <rightJoint>right_wheel_joint</rightJoint>
        <wheelSeparation>0.4</wheelSeparation>
        <wheelDiameter>0.12</wheelDiameter>
        <wheelTorque>5</wheelTorque>
        <commandTopic>cmd_vel</commandTopic>
        <odometryTopic>odom</odometryTopic>
        <odometryFrame>odom</odometryFrame>
        <robotBaseFrame>chassis</robotBaseFrame>
        <updateRate>50</updateRate>
      </plugin>
    </model>
  </world>
</sdf>
)";

std::size_t index_of(const std::vector<std::string>& names, const std::string& name) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

TEST_F(GazeboWorldNode, AnSdfWorldsModelsRunTheirSensorsAndPluginsBeforeAnySpawn) {
  start(false, write_world("sensor_world.world", kSensorWorld));
  ModelStatesWatch models(nh_);
  ASSERT_TRUE(models.wait_for_more_than(0, 20.0)) << node_->log();
  const gazebo_msgs::ModelStates m = models.latest();
  for (const char* name : {"ground_plane", "checkerboard_plane", "green_box", "laser_post", "tracked_box", "rover"})
    EXPECT_LT(index_of(m.name, name), m.name.size()) << name << " not in /gazebo/model_states";

  // The laser of a static world model sees the green box 1.75 m ahead (its near face).
  Latest<sensor_msgs::LaserScan> scan(nh_, "/post/scan");
  ASSERT_TRUE(wait_until([&] { return scan.received() > 2; }, 20.0)) << "no /post/scan; log:\n" << node_->log();
  const sensor_msgs::LaserScan s = scan.get();
  ASSERT_EQ(s.ranges.size(), 91u);
  EXPECT_EQ(s.header.frame_id, "post_laser_link");
  EXPECT_NEAR(s.ranges[45], 1.75, 0.02);

  // p3d of a world model, and set_model_state moving that model before any robot is spawned.
  Latest<nav_msgs::Odometry> tracked(nh_, "/tracked_box/pose");
  ASSERT_TRUE(wait_until([&] { return tracked.received() > 2; }, 20.0)) << node_->log();
  EXPECT_NEAR(tracked.get().pose.pose.position.x, -2.0, 0.01);
  gazebo_msgs::SetModelState set;
  set.request.model_state.model_name = "tracked_box";
  set.request.model_state.pose = pose_at(-1.0, 3.0, 0.1);
  ASSERT_TRUE(call("/gazebo/set_model_state", set));
  ASSERT_TRUE(set.response.success) << set.response.status_message;
  EXPECT_TRUE(wait_until([&] { return std::abs(tracked.get().pose.pose.position.y - 3.0) < 0.02; }, 10.0))
      << "the p3d pose did not follow set_model_state: y = " << tracked.get().pose.pose.position.y;

  // The world model's diff drive plugin drives it from its command topic.
  ::ros::Publisher cmd = nh_.advertise<geometry_msgs::Twist>("/rover/cmd_vel", 1);
  Latest<nav_msgs::Odometry> odom(nh_, "/rover/odom");
  ASSERT_TRUE(wait_until([&] { return cmd.getNumSubscribers() > 0 && odom.received() > 0; }, 20.0))
      << "the rover's diff drive plugin has no cmd_vel subscriber or odom; log:\n" << node_->log();
  const double x0 = model_state("rover").response.pose.position.x;
  geometry_msgs::Twist forward;
  forward.linear.x = 0.3;
  const double t0 = clock_now();
  wait_until([&] {
    cmd.publish(forward);
    return clock_now() - t0 > 2.0;
  }, 30.0);
  const double moved = model_state("rover").response.pose.position.x - x0;
  EXPECT_GT(moved, 0.3) << "the rover moved " << moved << " m in 2 s at 0.3 m/s";
  EXPECT_NEAR(odom.get().pose.pose.position.x, moved, 0.1);
}

TEST_F(GazeboWorldNode, WhatSdformat12RefusesAndGazeboReadsLoadsWithWarnings) {
  // The checkerboard from Gazebo's library and a material script by name: no refusal.
  start(true, write_world("tolerant.world", R"(<?xml version="1.0"?>
<sdf version="1.5"><world name="default">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://checkerboard_plane</uri></include>
  <include><uri>model://no_such_model_anywhere</uri></include>
  <model name="m"><static>true</static><link name="l">
    <visual name="v"><geometry><box><size>1 1 1</size></box></geometry>
      <material><script><name>Gazebo/Green</name></script></material></visual>
    <collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision>
  </link></model>
</world></sdf>)"));
  gazebo_msgs::GetWorldProperties w;
  ASSERT_TRUE(call("/gazebo/get_world_properties", w));
  EXPECT_THAT(w.response.model_names, ::testing::IsSupersetOf({"ground_plane", "checkerboard_plane", "m"}));
  const std::string log = node_->log();
  EXPECT_THAT(log, ::testing::HasSubstr("model://no_such_model_anywhere"));
  EXPECT_THAT(log, ::testing::HasSubstr("the include is left out"));
}

// A Pioneer-like base: a diff-drive plugin with no <robotNamespace>, and a sonar link whose
// collision box has size zero (as the Pioneer 3-DX's description has).
const char* const kTwoWheeler = R"(<robot name="p2">
  <link name="base_link">
    <inertial><mass value="5"/><inertia ixx="0.05" iyy="0.05" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.05"/><geometry><box size="0.4 0.3 0.05"/></geometry></collision>
    <collision><origin xyz="-0.15 0 -0.01"/><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <gazebo reference="base_link"><mu1>0</mu1><mu2>0</mu2></gazebo>
  <link name="sonar"><collision><geometry><box size="0 0 0"/></geometry></collision></link>
  <joint name="sonar_joint" type="fixed"><parent link="base_link"/><child link="sonar"/><origin xyz="0.2 0 0.1"/></joint>
  <link name="left_wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963 0 0"/><geometry><cylinder radius="0.06" length="0.03"/></geometry></collision>
  </link>
  <link name="right_wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963 0 0"/><geometry><cylinder radius="0.06" length="0.03"/></geometry></collision>
  </link>
  <joint name="left_wheel_joint" type="continuous"><parent link="base_link"/><child link="left_wheel"/>
    <origin xyz="0.1 0.2 0"/><axis xyz="0 1 0"/></joint>
  <joint name="right_wheel_joint" type="continuous"><parent link="base_link"/><child link="right_wheel"/>
    <origin xyz="0.1 -0.2 0"/><axis xyz="0 1 0"/></joint>
  <gazebo>
    <plugin name="differential_drive_controller" filename="libgazebo_ros_diff_drive.so">
      <leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>
      <wheelSeparation>0.4</wheelSeparation><wheelDiameter>0.12</wheelDiameter><wheelTorque>5</wheelTorque>
      <commandTopic>cmd_vel</commandTopic><odometryTopic>odom</odometryTopic><odometryFrame>odom</odometryFrame>
      <robotBaseFrame>base_link</robotBaseFrame><updateRate>50</updateRate>
    </plugin>
  </gazebo>
</robot>)";

TEST_F(GazeboWorldNode, TwoRobotsFromOneDescriptionDriveOnTheirOwnNamespaces) {
  start(false);
  // As spawn_model in two launch-file groups calls it: the group's namespace is the request's.
  for (const auto& [name, ns, y] : {std::tuple{"r1", "/r1", 0.0}, std::tuple{"r2", "/r2", 2.0}}) {
    gazebo_msgs::SpawnModel s;
    s.request.model_name = name;
    s.request.model_xml = kTwoWheeler;
    s.request.robot_namespace = ns;
    s.request.initial_pose = pose_at(0.0, y, 0.06);
    ASSERT_TRUE(call("/gazebo/spawn_urdf_model", s));
    ASSERT_TRUE(s.response.success) << s.response.status_message << "\n" << node_->log();
  }
  EXPECT_THAT(node_->log(), ::testing::HasSubstr("a box of size zero"));
  ::ros::Publisher r1 = nh_.advertise<geometry_msgs::Twist>("/r1/cmd_vel", 1);
  ::ros::Publisher r2 = nh_.advertise<geometry_msgs::Twist>("/r2/cmd_vel", 1);
  ::ros::Publisher shared = nh_.advertise<geometry_msgs::Twist>("/cmd_vel", 1);
  ASSERT_TRUE(wait_until([&] { return r1.getNumSubscribers() > 0 && r2.getNumSubscribers() > 0; }, 10.0))
      << "each robot's diff drive subscribes under its own namespace";
  EXPECT_EQ(shared.getNumSubscribers(), 0u) << "no robot listens on the root /cmd_vel";
  const double r1_x0 = model_state("r1").response.pose.position.x, r2_x0 = model_state("r2").response.pose.position.x;
  geometry_msgs::Twist forward;
  forward.linear.x = 0.3;
  const double t0 = clock_now();
  wait_until([&] {
    r1.publish(forward);
    return clock_now() - t0 > 2.0;
  }, 30.0);
  EXPECT_GT(model_state("r1").response.pose.position.x - r1_x0, 0.3) << "r1 drove on /r1/cmd_vel";
  EXPECT_NEAR(model_state("r2").response.pose.position.x - r2_x0, 0.0, 0.01) << "r2 stood still";
}

// An rrbot-like arm fixed to the world: Gazebo's `world` link and a fixed joint to it.
const char* const kFixedArm = R"(<robot name="rrbot">
  <link name="world"/>
  <joint name="fixed" type="fixed"><parent link="world"/><child link="link1"/></joint>
  <link name="link1">
    <inertial><origin xyz="0 0 0.5"/><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.5"/><geometry><box size="0.1 0.1 1"/></geometry></collision>
  </link>
  <joint name="joint1" type="continuous"><parent link="link1"/><child link="link2"/><origin xyz="0 0.1 0.95"/><axis xyz="0 1 0"/>
    <dynamics damping="0.7"/></joint>
  <link name="link2">
    <inertial><origin xyz="0 0 0.45"/><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.45"/><geometry><box size="0.1 0.1 1"/></geometry></collision>
  </link>
</robot>)";

TEST_F(GazeboWorldNode, ARobotFixedToTheWorldIsWhereItsSpawnPutsIt) {
  start(true);
  ModelStatesWatch models(nh_);
  Latest<gazebo_msgs::LinkStates> links(nh_, "/gazebo/link_states");
  const gazebo_msgs::SpawnModel s = spawn("rrbot3", kFixedArm, pose_at(0.0, 2.0, 0.0));
  ASSERT_TRUE(s.response.success) << s.response.status_message;
  EXPECT_NEAR(model_state("rrbot3").response.pose.position.y, 2.0, 1e-9);
  ASSERT_TRUE(wait_until(
      [&] {
        step(1);
        return models.count() > 0 && links.received() > 0;
      },
      10.0));
  const gazebo_msgs::ModelStates m = models.latest();
  const std::size_t k = index_of(m.name, "rrbot3");
  ASSERT_LT(k, m.name.size());
  EXPECT_NEAR(m.pose[k].position.y, 2.0, 1e-9);
  const gazebo_msgs::LinkStates l = links.get();
  EXPECT_EQ(index_of(l.name, "rrbot3::world"), l.name.size()) << "Gazebo's world is no link of the model";
  const std::size_t link2 = index_of(l.name, "rrbot3::link2");
  ASSERT_LT(link2, l.name.size());
  EXPECT_NEAR(l.pose[link2].position.y, 2.1, 1e-6);

  // Joint and link properties, as set_joint_properties / set_link_properties change them.
  gazebo_msgs::GetJointProperties jp;
  jp.request.joint_name = "joint1";
  ASSERT_TRUE(call("/gazebo/get_joint_properties", jp));
  ASSERT_EQ(jp.response.damping.size(), 1u);
  EXPECT_NEAR(jp.response.damping[0], 0.7, 1e-12);
  gazebo_msgs::SetJointProperties sj;
  sj.request.joint_name = "joint1";
  sj.request.ode_joint_config.damping = {2.5};
  sj.request.ode_joint_config.hiStop = {0.5};
  sj.request.ode_joint_config.loStop = {-0.5};
  ASSERT_TRUE(call("/gazebo/set_joint_properties", sj));
  EXPECT_TRUE(sj.response.success) << sj.response.status_message;
  ASSERT_TRUE(call("/gazebo/get_joint_properties", jp));
  EXPECT_NEAR(jp.response.damping.at(0), 2.5, 1e-12);
  gazebo_msgs::SetLinkProperties sl;
  sl.request.link_name = "rrbot3::link2";
  sl.request.gravity_mode = true;
  sl.request.mass = 3.0;
  sl.request.com = pose_at(0.0, 0.0, 0.45);
  sl.request.ixx = sl.request.iyy = sl.request.izz = 0.5;
  ASSERT_TRUE(call("/gazebo/set_link_properties", sl));
  EXPECT_TRUE(sl.response.success) << sl.response.status_message;
  gazebo_msgs::GetLinkProperties lp;
  lp.request.link_name = "rrbot3::link2";
  ASSERT_TRUE(call("/gazebo/get_link_properties", lp));
  EXPECT_DOUBLE_EQ(lp.response.mass, 3.0);
  // The stops hold the arm: pushed hard, it stays within +-0.5 rad.
  gazebo_msgs::ApplyJointEffort push;
  push.request.joint_name = "joint1";
  push.request.effort = 200.0;
  push.request.duration = ::ros::Duration(1.0);
  ASSERT_TRUE(call("/gazebo/apply_joint_effort", push));
  step(1000);
  ASSERT_TRUE(call("/gazebo/get_joint_properties", jp));
  EXPECT_LT(jp.response.position.at(0), 0.6);
  EXPECT_GT(jp.response.position.at(0), 0.3) << "the effort turned the joint up to its stop";
}

// gazebo_ros_api_plugin's topics and services under /gazebo (noetic-devel: advertiseServices(),
// the physics dynamic_reconfigure server on the node's handle, and roscpp's logger services).
const std::set<std::string> kGazeboServices = {
    "/gazebo/apply_body_wrench", "/gazebo/apply_joint_effort", "/gazebo/clear_body_wrenches",
    "/gazebo/clear_joint_forces", "/gazebo/delete_light", "/gazebo/delete_model", "/gazebo/get_joint_properties",
    "/gazebo/get_light_properties", "/gazebo/get_link_properties", "/gazebo/get_link_state",
    "/gazebo/get_loggers", "/gazebo/get_model_properties", "/gazebo/get_model_state",
    "/gazebo/get_physics_properties", "/gazebo/get_world_properties", "/gazebo/pause_physics",
    "/gazebo/reset_simulation", "/gazebo/reset_world", "/gazebo/set_joint_properties",
    "/gazebo/set_light_properties", "/gazebo/set_link_properties", "/gazebo/set_link_state",
    "/gazebo/set_logger_level", "/gazebo/set_model_configuration", "/gazebo/set_model_state",
    "/gazebo/set_parameters", "/gazebo/set_physics_properties", "/gazebo/spawn_sdf_model",
    "/gazebo/spawn_urdf_model", "/gazebo/unpause_physics"};
const std::set<std::string> kGazeboPublished = {"/gazebo/link_states", "/gazebo/model_states",
                                                "/gazebo/parameter_descriptions", "/gazebo/parameter_updates",
                                                "/gazebo/performance_metrics"};
const std::set<std::string> kGazeboSubscribed = {"/gazebo/set_link_state", "/gazebo/set_model_state",
                                                 "/gazebo/set_model_states"};

struct Graph {
  std::set<std::string> services, published, subscribed;
};

// What the master says the node /gazebo offers under /gazebo.
Graph gazebo_graph() {
  Graph g;
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ::ros::this_node::getName();
  if (!::ros::master::execute("getSystemState", args, result, payload, true)) return g;
  auto collect = [&](int kind, std::set<std::string>& out) {
    for (int i = 0; i < payload[kind].size(); ++i) {
      const std::string name = payload[kind][i][0];
      for (int j = 0; j < payload[kind][i][1].size(); ++j)
        if (std::string(payload[kind][i][1][j]) == "/gazebo" && name.rfind("/gazebo/", 0) == 0) out.insert(name);
    }
  };
  collect(0, g.published);
  collect(1, g.subscribed);
  collect(2, g.services);
  return g;
}

TEST_F(GazeboWorldNode, OffersExactlyGazeboRosApi) {
  start(true);
  ASSERT_TRUE(wait_until([&] { return gazebo_graph().published.count("/gazebo/parameter_updates") > 0; }, 10.0))
      << "no physics dynamic_reconfigure; log:\n" << node_->log();
  const Graph g = gazebo_graph();
  EXPECT_EQ(g.services, kGazeboServices);
  EXPECT_EQ(g.published, kGazeboPublished);
  EXPECT_EQ(g.subscribed, kGazeboSubscribed);

  // The physics over dynamic_reconfigure, as dynparam changes it: the configuration the server
  // published (the world's: 1 ms, 1000 steps/s, its gravity), one value changed, sent whole.
  Latest<dynamic_reconfigure::Config> updates(nh_, "/gazebo/parameter_updates");
  ASSERT_TRUE(wait_until([&] { return updates.received() > 0; }, 10.0));
  dynamic_reconfigure::Reconfigure r;
  r.request.config = updates.get();
  auto value = [&](const std::string& name) {
    for (const auto& d : updates.get().doubles)
      if (d.name == name) return d.value;
    return std::nan("");
  };
  EXPECT_DOUBLE_EQ(value("time_step"), 0.001);
  EXPECT_DOUBLE_EQ(value("max_update_rate"), 1000.0);
  EXPECT_DOUBLE_EQ(value("gravity_z"), -9.81);
  for (auto& d : r.request.config.doubles)
    if (d.name == "gravity_z") d.value = -5.0;
  ASSERT_TRUE(call("/gazebo/set_parameters", r));
  EXPECT_TRUE(wait_until([&] { return value("gravity_z") == -5.0; }, 5.0)) << "parameter_updates has the change";
  gazebo_msgs::GetPhysicsProperties p;
  ASSERT_TRUE(call("/gazebo/get_physics_properties", p));
  EXPECT_DOUBLE_EQ(p.response.gravity.z, -5.0);
  EXPECT_DOUBLE_EQ(p.response.time_step, 0.001);

  // The world's light (mechsim's worlds have Gazebo's sun): read, changed, deleted.
  gazebo_msgs::GetLightProperties gl;
  gl.request.light_name = "sun";
  ASSERT_TRUE(call("/gazebo/get_light_properties", gl));
  EXPECT_TRUE(gl.response.success);
  EXPECT_NEAR(gl.response.diffuse.r, 0.8, 1e-6);
  gazebo_msgs::SetLightProperties sl;
  sl.request.light_name = "sun";
  sl.request.diffuse.r = 0.5;
  sl.request.diffuse.a = 1.0;
  sl.request.attenuation_constant = 0.5;
  sl.request.pose.orientation.w = 1.0;
  ASSERT_TRUE(call("/gazebo/set_light_properties", sl));
  EXPECT_TRUE(sl.response.success) << sl.response.status_message;
  ASSERT_TRUE(call("/gazebo/get_light_properties", gl));
  EXPECT_NEAR(gl.response.diffuse.r, 0.5, 1e-6);
  EXPECT_DOUBLE_EQ(gl.response.attenuation_constant, 0.5);
  gazebo_msgs::DeleteLight dl;
  dl.request.light_name = "sun";
  ASSERT_TRUE(call("/gazebo/delete_light", dl));
  EXPECT_TRUE(dl.response.success);
  ASSERT_TRUE(call("/gazebo/get_light_properties", gl));
  EXPECT_FALSE(gl.response.success);
}

class GazeboWorldWithoutRosNetwork : public GazeboWorldNode {};

TEST_F(GazeboWorldWithoutRosNetwork, OffersOnlyTheClockAndTheLoggers) {
  const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  node_ = std::make_unique<ChildProcess>(
      std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=gazebo", "_gazebo:=true", "_enable_ros_network:=false"},
      log_dir() + "/gazebo_" + name + ".log");
  ASSERT_TRUE(wait_until([&] { return gazebo_graph().services.count("/gazebo/get_loggers") > 0; }, 20.0))
      << node_->log();
  Latest<rosgraph_msgs::Clock> clock(nh_, "/clock");
  EXPECT_TRUE(wait_until([&] { return clock.received() > 5; }, 10.0)) << "no /clock";
  const Graph g = gazebo_graph();
  EXPECT_EQ(g.services, (std::set<std::string>{"/gazebo/get_loggers", "/gazebo/set_logger_level"}));
  EXPECT_TRUE(g.published.empty());
  EXPECT_TRUE(g.subscribed.empty());
}

}  // namespace
}  // namespace mechsim::ros::test
