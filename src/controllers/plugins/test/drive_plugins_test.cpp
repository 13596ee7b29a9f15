// The tricycle drive (libgazebo_ros_tricycle_drive.so) and Gazebo's own differential drive
// (libDiffDrivePlugin.so) as model plugin controllers on the test robot (ideal servos): their
// elements' defaults, what a command does to the joints (speed and steering angle, the ramps,
// steering by speed), their odometry, their ROS interface, and their errors; the diff drive's
// publishWheelTF without a joint_states topic.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "controllers/plugins/diff_drive_plugin.hpp"
#include "controllers/plugins/gazebo_diff_drive_plugin.hpp"
#include "control/params_xml.hpp"
#include "controllers/plugins/gazebo_ros_names.hpp"
#include "controllers/plugins/test/plugin_rig.hpp"
#include "controllers/plugins/tricycle_drive_plugin.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;
using plugin_test::PluginRig;

// The test robot's joints as a tricycle: pan steers finger_a, the driven wheel; rl and rr are the
// encoder wheels.
std::string tricycle(const std::string& extra = "") {
  return "<gazebo><plugin name=\"trike\" filename=\"libgazebo_ros_tricycle_drive.so\">"
         "<steeringJoint>pan</steeringJoint><actuatedWheelJoint>finger_a</actuatedWheelJoint>"
         "<encoderWheelLeftJoint>rl</encoderWheelLeftJoint><encoderWheelRightJoint>rr</encoderWheelRightJoint>" +
         extra + "</plugin></gazebo>\n";
}

const ModelPlugin* plugin_of(PluginRig& rig, const std::string& name) {
  return dynamic_cast<const ModelPlugin*>(rig.manager->controller(name));
}

OdometrySnapshot odometry(PluginRig& rig, const std::string& name) {
  return dynamic_cast<StatePort<OdometrySnapshot>*>(rig.manager->controller(name)->port("odom"))->read();
}

TEST(TricycleDrivePlugin, DefaultsAndTopicsAreGazeboPlugins) {
  PluginRig rig;
  ASSERT_EQ(rig.add(tricycle()), "");
  auto* t = rig.plugin<TricycleDrivePlugin>("trike");
  ASSERT_NE(t, nullptr);
  EXPECT_DOUBLE_EQ(t->actuated_wheel_diameter(), 0.15);
  EXPECT_DOUBLE_EQ(t->encoder_wheel_diameter(), 0.15);
  EXPECT_DOUBLE_EQ(t->encoder_wheel_separation(), 0.5);
  EXPECT_DOUBLE_EQ(t->wheel_torque(), 5.0);
  EXPECT_DOUBLE_EQ(t->wheel_acceleration(), 0.0);
  EXPECT_DOUBLE_EQ(t->wheel_deceleration(), 0.0);
  EXPECT_DOUBLE_EQ(t->steering_speed(), 0.0);
  EXPECT_DOUBLE_EQ(t->update_rate(), 100.0);
  EXPECT_FALSE(t->encoder_odometry());  // odometrySource world
  const PluginRosInterface& ros = t->ros_interface();
  EXPECT_EQ(ros.robot_namespace, "");
  ASSERT_EQ(ros.topics.size(), 2u);  // no joint_states unless asked for
  EXPECT_EQ(ros.topics[0].port, "cmd_vel");
  EXPECT_EQ(ros.topics[0].topic, "cmd_vel");
  EXPECT_EQ(ros.topics[1].port, "odom");
  EXPECT_EQ(ros.topics[1].topic, "odom");
  EXPECT_TRUE(ros.odom_tf);  // the plugin always broadcasts odom -> base
  EXPECT_TRUE(ros.wheel_tf_joints.empty());
  EXPECT_DOUBLE_EQ(rig.robot->joint("finger_a").effort_limit, 5.0);  // wheelTorque bounds the driven wheel
  EXPECT_DOUBLE_EQ(rig.robot->joint("pan").effort_limit, 0.0);       // a set position: the joint's own
  rig.robot->state.base.X_WB.position = {3.0, 4.0, 0.2};
  rig.run(15);
  const OdometrySnapshot o = odometry(rig, "trike");
  EXPECT_EQ(o.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_link");  // the tricycle's default, not base_footprint
  EXPECT_TRUE(o.in_world);
  EXPECT_DOUBLE_EQ(o.x, 3.0);
  EXPECT_DOUBLE_EQ(o.z, 0.2);
  EXPECT_DOUBLE_EQ(o.pose_covariance[0], 1e-5);
  EXPECT_DOUBLE_EQ(o.pose_covariance[35], 1e-3);
  EXPECT_DOUBLE_EQ(o.twist_covariance[0], 0.0);
}

TEST(TricycleDrivePlugin, CmdVelIsTheWheelsSpeedAndTheSteeringAngle) {
  PluginRig rig;
  rig.without_velocity_limit("pan");
  ASSERT_EQ(rig.add(tricycle("<actuatedWheelDiameter>0.2</actuatedWheelDiameter><updateRate>50</updateRate>"
                             "<commandTopic>trike/cmd</commandTopic><robotNamespace>/t</robotNamespace>")),
            "");
  const PluginRosInterface& ros = plugin_of(rig, "trike")->ros_interface();
  EXPECT_EQ(ros.robot_namespace, "/t");
  EXPECT_EQ(ros.topics[0].topic, "trike/cmd");
  rig.send("trike", 0.3, 0.0, 0.4);  // 0.3 m/s, steering 0.4 rad
  rig.run(10);
  EXPECT_DOUBLE_EQ(rig.robot->joint("finger_a").commanded_velocity, 0.0);  // the first update is 20 ms on
  rig.run(11);
  EXPECT_NEAR(rig.robot->joint("finger_a").commanded_velocity, 3.0, 1e-12);  // 0.3 m/s over a 0.1 m radius
  EXPECT_EQ(rig.robot->joint("finger_a").command_mode, HardwareInterface::Velocity);
  EXPECT_NEAR(rig.robot->joint("pan").commanded_position, 0.4, 1e-12);
  EXPECT_EQ(rig.robot->joint("pan").command_mode, HardwareInterface::Position);
  // The steering angle is clamped to +-pi/2; the command is held (no timeout).
  rig.send("trike", -0.1, 0.0, -3.0);
  rig.run(2000);
  EXPECT_NEAR(rig.robot->joint("pan").commanded_position, -M_PI_2, 1e-12);
  EXPECT_NEAR(rig.robot->joint("finger_a").commanded_velocity, -1.0, 1e-12);
}

TEST(TricycleDrivePlugin, RampsWithThePluginsAccelerationAndDeceleration) {
  PluginRig rig;
  // 100 Hz: 0.01 s between updates. Rising set points step by wheelDeceleration, falling ones by
  // wheelAcceleration (the plugin's assignment); within the tolerance the set point stays.
  ASSERT_EQ(rig.add(tricycle("<actuatedWheelDiameter>0.2</actuatedWheelDiameter><wheelAcceleration>2</wheelAcceleration>"
                             "<wheelDeceleration>10</wheelDeceleration><wheelSpeedTolerance>0.05</wheelSpeedTolerance>")),
            "");
  EXPECT_DOUBLE_EQ(rig.plugin<TricycleDrivePlugin>("trike")->wheel_deceleration(), 10.0);
  rig.send("trike", 0.4, 0.0, 0.0);  // target 4 rad/s
  rig.run(11);                       // one update
  EXPECT_NEAR(rig.robot->joint("finger_a").commanded_velocity, 0.1, 1e-9);
  rig.run(50);  // five more
  EXPECT_NEAR(rig.robot->joint("finger_a").commanded_velocity, 0.6, 1e-9);
  rig.run(400);
  EXPECT_NEAR(rig.robot->joint("finger_a").commanded_velocity, 4.0, 1e-9);  // reached, not passed
  rig.send("trike", 0.0, 0.0, 0.0);
  rig.run(10);
  EXPECT_NEAR(rig.robot->joint("finger_a").commanded_velocity, 3.98, 1e-9);
  rig.run(2000);
  // It stops stepping 0.05 rad/s (the tolerance) short of zero, or lands on it.
  EXPECT_LT(std::abs(rig.robot->joint("finger_a").commanded_velocity), 0.05);
}

TEST(TricycleDrivePlugin, SteersBySpeedTowardsTheTargetWithSteeringSpeed) {
  PluginRig rig;
  ASSERT_EQ(rig.add(tricycle("<steeringSpeed>0.5</steeringSpeed><steeringAngleTolerance>0.02</steeringAngleTolerance>"
                             "<wheelTorque>4</wheelTorque>")),
            "");
  EXPECT_DOUBLE_EQ(rig.robot->joint("pan").effort_limit, 4.0);  // the velocity motor is bounded by wheelTorque
  rig.send("trike", 0.2, 0.0, 0.3);
  rig.run(11);
  EXPECT_EQ(rig.robot->joint("pan").command_mode, HardwareInterface::Velocity);
  EXPECT_DOUBLE_EQ(rig.robot->joint("pan").commanded_velocity, 0.5);
  rig.run(1000);  // the ideal servo turns it at 0.5 rad/s: within 0.02 rad of 0.3 it holds
  EXPECT_NEAR(rig.robot->joint("pan").position, 0.3, 0.02 + 0.5 * 0.01);
  EXPECT_DOUBLE_EQ(rig.robot->joint("pan").commanded_velocity, 0.0);
  // Back the other way, whatever the wheel's speed.
  rig.send("trike", 2.0, 0.0, -0.2);
  rig.run(20);
  EXPECT_DOUBLE_EQ(rig.robot->joint("pan").commanded_velocity, -0.5);
}

TEST(TricycleDrivePlugin, EncoderOdometryFromTheEncoderWheelsTurnsAsRep103) {
  PluginRig rig;
  ASSERT_EQ(rig.add(tricycle("<odometrySource>encoder</odometrySource><encoderWheelDiameter>0.2</encoderWheelDiameter>"
                             "<encoderWheelSeparation>0.4</encoderWheelSeparation><odometryFrame>odo</odometryFrame>"
                             "<robotBaseFrame>chassis</robotBaseFrame>")),
            "");
  // The encoder wheels roll at 0.1 m/s (left) and 0.3 m/s (right): 0.2 m/s forward turning left
  // at 0.5 rad/s, on a circle of radius 0.4 m.
  rig.set_velocity("rl", 1.0);
  rig.set_velocity("rr", 3.0);
  rig.run(2001);
  const OdometrySnapshot o = odometry(rig, "trike");
  EXPECT_FALSE(o.in_world);
  EXPECT_EQ(o.frame_id, "odo");
  EXPECT_EQ(o.child_frame_id, "chassis");
  EXPECT_NEAR(o.yaw, 1.0, 0.01);
  EXPECT_NEAR(o.x, 0.4 * std::sin(o.yaw), 1e-3);
  EXPECT_NEAR(o.y, 0.4 * (1.0 - std::cos(o.yaw)), 1e-3);
  EXPECT_NEAR(o.linear.x, 0.2, 1e-6);  // in the base frame
  EXPECT_NEAR(o.angular.z, 0.5, 1e-9);
  EXPECT_NEAR(o.stamp, 2.0, 1e-9);  // the latest 100 Hz update
}

TEST(TricycleDrivePlugin, WheelJointStatesAndWheelTf) {
  PluginRig rig;
  ASSERT_EQ(rig.add(tricycle("<publishWheelJointState>true</publishWheelJointState><publishWheelTF>true</publishWheelTF>"
                             "<updateRate>20</updateRate>")),
            "");
  const PluginRosInterface& ros = plugin_of(rig, "trike")->ros_interface();
  ASSERT_EQ(ros.topics.size(), 3u);
  EXPECT_EQ(ros.topics[2].port, "joint_states");
  EXPECT_EQ(ros.topics[2].topic, "joint_states");
  EXPECT_EQ(ros.wheel_tf_joints, (std::vector<std::string>{"pan", "finger_a", "rl", "rr"}));
  rig.set_position("rl", 0.7);
  rig.set_velocity("rr", 2.0);
  auto* port = dynamic_cast<StatePort<JointStateSnapshot>*>(rig.manager->controller("trike")->port("joint_states"));
  rig.run(60);
  EXPECT_EQ(port->sequence(), 1u);  // 20 Hz
  const JointStateSnapshot s = port->read();
  ASSERT_EQ(s.names, (std::vector<std::string>{"pan", "finger_a", "rl", "rr"}));
  EXPECT_DOUBLE_EQ(s.position[2], 0.7);
  EXPECT_DOUBLE_EQ(s.velocity[3], 2.0);
  ASSERT_EQ(s.effort.size(), 4u);
  EXPECT_NEAR(s.stamp, 0.05, 1e-9);

  // publishWheelTF alone: the transforms, no joint_states topic (as the plugin).
  PluginRig tf_only;
  ASSERT_EQ(tf_only.add(tricycle("<publishWheelTF>true</publishWheelTF>")), "");
  const PluginRosInterface& r = plugin_of(tf_only, "trike")->ros_interface();
  ASSERT_EQ(r.topics.size(), 3u);
  EXPECT_EQ(r.topics[2].topic, "");
  EXPECT_EQ(r.wheel_tf_joints.size(), 4u);
}

TEST(TricycleDrivePlugin, ErrorsNameTheElement) {
  const auto error_of = [](const std::string& plugins, bool floating = true) {
    PluginRig rig;
    rig.robot->state.base.floating = floating;
    try {
      return rig.add(plugins);
    } catch (const ControllerConfigError& e) {  // found while building, before init
      return std::string(e.what());
    }
  };
  EXPECT_THAT(error_of(tricycle("<odometrySource>gps</odometrySource>")), HasSubstr("<odometrySource> must be world or encoder"));
  EXPECT_THAT(error_of(tricycle("<steeringSpeed>-1</steeringSpeed>")), HasSubstr("<steeringSpeed> must be >= 0"));
  EXPECT_THAT(error_of(tricycle("<actuatedWheelDiameter>0</actuatedWheelDiameter>")),
              HasSubstr("<actuatedWheelDiameter> must be > 0"));
  EXPECT_THAT(error_of(tricycle(), false), HasSubstr("<odometrySource> is world, but the robot is fixed to the world"));
  EXPECT_EQ(error_of(tricycle("<odometrySource>encoder</odometrySource>"), false), "");
  std::string same = tricycle();
  same.replace(same.find("<actuatedWheelJoint>finger_a"), 28, "<actuatedWheelJoint>pan");
  EXPECT_THAT(error_of(same), HasSubstr("<actuatedWheelJoint> names the same joint as <steeringJoint> ('pan')"));
  // Absent joint elements name gazebo_plugins' defaults, which the test robot lacks.
  EXPECT_THAT(error_of("<gazebo><plugin name=\"t\" filename=\"libgazebo_ros_tricycle_drive.so\"/></gazebo>\n"),
              HasSubstr("the plugin names joint 'front_steering_joint', which robot 'bot' does not have"));
}

// The test robot's description with geometry: wheels 0.34 m apart, a cylinder tyre of radius 0.11
// on its side (axle along y) on the left and a box tilted 45 degrees about the axle on the right.
description::RobotModel wheeled(const std::string& plugin, const std::string& left_collision = "") {
  const std::string inertial =
      "<inertial><mass value=\"0.1\"/><inertia ixx=\"1e-4\" ixy=\"0\" ixz=\"0\" iyy=\"1e-4\" iyz=\"0\" izz=\"1e-4\"/></inertial>";
  const std::string tyre = left_collision.empty()
                               ? "<collision><origin rpy=\"1.5707963 0 0\"/><geometry><cylinder radius=\"0.11\" length=\"0.05\"/>"
                                 "</geometry></collision>"
                               : left_collision;
  std::string text = "<robot name=\"bot\"><link name=\"base\">" + inertial + "</link>" +
                     "<joint name=\"left\" type=\"continuous\"><parent link=\"base\"/><child link=\"left_link\"/>"
                     "<origin xyz=\"0.1 0.17 0.05\"/><axis xyz=\"0 1 0\"/></joint><link name=\"left_link\">" +
                     inertial + tyre + "</link>" +
                     "<joint name=\"right\" type=\"continuous\"><parent link=\"base\"/><child link=\"right_link\"/>"
                     "<origin xyz=\"0.1 -0.17 0.05\"/><axis xyz=\"0 1 0\"/></joint><link name=\"right_link\">" +
                     inertial +
                     "<collision><origin rpy=\"0 0.7853982 0\"/><geometry><box size=\"0.3 0.05 0.2\"/></geometry></collision>"
                     "</link>" +
                     plugin + "</robot>";
  return description::parse_urdf_string(text, "wheeled.urdf", {});
}

const char* const kGazeboDiffDrive =
    "<gazebo><plugin name=\"diff_drive\" filename=\"libDiffDrivePlugin.so\">"
    "<left_joint>left</left_joint><right_joint>right</right_joint>TORQUE</plugin></gazebo>";

std::string gazebo_diff_drive(const std::string& torque = "") {
  std::string s = kGazeboDiffDrive;
  s.replace(s.find("TORQUE"), 6, torque);
  return s;
}

TEST(GazeboDiffDrivePlugin, MeasuresTheWheelsAsGazebosInit) {
  const description::RobotModel robot = wheeled(gazebo_diff_drive());
  const GazeboDiffDriveGeometry g = gazebo_diff_drive_geometry(robot, "left", "right");
  EXPECT_NEAR(g.separation, 0.34, 1e-9);
  EXPECT_NEAR(g.radius, 0.11, 1e-6);
  // The right wheel's tilted box: 0.3 and 0.2 m edges at 45 degrees span (0.3 + 0.2) / sqrt(2).
  EXPECT_NEAR(gazebo_diff_drive_geometry(robot, "right", "left").radius, 0.25 / std::sqrt(2.0), 1e-6);
  // A sphere tyre offset from the joint counts where it is.
  EXPECT_NEAR(gazebo_diff_drive_geometry(wheeled(gazebo_diff_drive(), "<collision><origin xyz=\"0 0.3 0\"/><geometry>"
                                                                      "<sphere radius=\"0.09\"/></geometry></collision>"),
                                         "left", "right")
                  .radius,
              0.09, 1e-9);
  EXPECT_THAT(
      [] {
        try {
          gazebo_diff_drive_geometry(wheeled(gazebo_diff_drive(), "<collision><geometry><mesh filename=\"tyre.stl\"/>"
                                                                  "</geometry></collision>"),
                                     "left", "right");
        } catch (const ControllerConfigError& e) {
          return std::string(e.what());
        }
        return std::string("(no error)");
      }(),
      HasSubstr("wheel link 'left_link' has a mesh collision"));
}

TEST(GazeboDiffDrivePlugin, VelCmdDrivesTheWheelsEveryTickFromZero) {
  PluginRig rig;
  ASSERT_EQ(rig.add(wheeled(gazebo_diff_drive())), "");
  auto* dd = rig.plugin<GazeboDiffDrivePlugin>("diff_drive");
  ASSERT_NE(dd, nullptr);
  EXPECT_DOUBLE_EQ(dd->torque(), 0.0);                               // none given: the joints' own limits
  EXPECT_DOUBLE_EQ(rig.robot->joint("left").effort_limit, 0.0);
  const PluginRosInterface& ros = dd->ros_interface();
  ASSERT_EQ(ros.topics.size(), 1u);
  EXPECT_EQ(ros.topics[0].port, "vel_cmd");
  EXPECT_EQ(ros.topics[0].topic, "/bot/vel_cmd");  // Gazebo's ~/<model>/vel_cmd
  EXPECT_EQ(ros.topics[0].message, "geometry_msgs/Pose");
  rig.run(5);
  EXPECT_DOUBLE_EQ(rig.robot->joint("left").commanded_velocity, 0.0);  // zero until a command comes
  EXPECT_EQ(rig.robot->joint("left").command_mode, HardwareInterface::Velocity);
  auto* port = dynamic_cast<TwistCommandPort*>(dd->port("vel_cmd"));
  ASSERT_NE(port, nullptr);
  Twist t;
  t.linear.x = 0.5;
  t.angular.z = 1.0;  // Gazebo's yaw rate: clockwise, the left wheel faster
  ASSERT_TRUE(port->write(t));
  rig.run(1);
  EXPECT_NEAR(rig.robot->joint("left").commanded_velocity, (0.5 + 0.17) / 0.11, 1e-6);
  EXPECT_NEAR(rig.robot->joint("right").commanded_velocity, (0.5 - 0.17) / 0.11, 1e-6);

  PluginRig with_torque;
  ASSERT_EQ(with_torque.add(wheeled(gazebo_diff_drive("<torque>5</torque>"))), "");
  EXPECT_DOUBLE_EQ(with_torque.robot->joint("right").effort_limit, 5.0);
}

TEST(GazeboDiffDrivePlugin, CheckSaysHowToCommandItAndErrorsNameTheElement) {
  const std::vector<ModelPluginStatus> s = model_plugin_status(wheeled(gazebo_diff_drive()));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].handling, PluginHandling::Controller);
  EXPECT_THAT(s[0].detail, HasSubstr("Gazebo's own differential drive"));
  EXPECT_THAT(s[0].detail, HasSubstr("no Gazebo transport"));
  EXPECT_THAT(s[0].detail, HasSubstr("ROS topic /bot/vel_cmd (geometry_msgs/Pose"));
  const auto error_of = [](const description::RobotModel& robot) {
    try {
      build_model_plugins(robot, PluginContext{"bot", Params()});
    } catch (const ControllerConfigError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_THAT(error_of(wheeled("<gazebo><plugin name=\"dd\" filename=\"libDiffDrivePlugin.so\"><left_joint>left</left_joint>"
                               "</plugin></gazebo>")),
              HasSubstr("gazebo plugin 'dd' (libDiffDrivePlugin.so): wheeled.urdf:1: <right_joint> is missing (required)"));
  EXPECT_THAT(error_of(wheeled(gazebo_diff_drive(), "<visual><geometry><box size=\"1 1 1\"/></geometry></visual>")),
              HasSubstr("wheel link 'left_link' has no collision shape"));
  PluginRig rig;
  EXPECT_THAT(rig.add(wheeled(gazebo_diff_drive("<torque>0</torque>"))), HasSubstr("<torque> must be > 0"));
}

TEST(DiffDrivePlugin, PublishWheelTfAloneHasNoJointStatesTopic) {
  PluginRig rig;
  ASSERT_EQ(rig.add("<gazebo><plugin name=\"dd\" filename=\"libgazebo_ros_diff_drive.so\"><leftJoint>left</leftJoint>"
                    "<rightJoint>right</rightJoint><publishWheelTF>true</publishWheelTF></plugin></gazebo>\n"),
            "");
  const PluginRosInterface& ros = plugin_of(rig, "dd")->ros_interface();
  ASSERT_EQ(ros.topics.size(), 3u);
  EXPECT_EQ(ros.topics[2].port, "joint_states");
  EXPECT_EQ(ros.topics[2].topic, "");  // gazebo_ros_diff_drive advertises joint_states only with publishWheelJointState
  EXPECT_EQ(ros.wheel_tf_joints, (std::vector<std::string>{"left", "right"}));
}

TEST(ModelPlugins, WorldModelsTakeTheirNameAsGazeboRosNamespace) {
  // What Gazebo does with a model it loads without a spawn namespace: the GazeboRos-based plugins
  // without <robotNamespace> are under the model's name, their frames prefixed with it; the
  // others (planar move) and those that name one keep theirs.
  description::RobotModel robot = plugin_test::robot_with(
      "<gazebo><plugin name=\"dd\" filename=\"libgazebo_ros_diff_drive.so\"><leftJoint>left</leftJoint>"
      "<rightJoint>right</rightJoint></plugin>"
      "<plugin name=\"jsp\" filename=\"libgazebo_ros_joint_state_publisher.so\"><jointName>pan</jointName>"
      "<robotNamespace>/own</robotNamespace></plugin>"
      "<plugin name=\"pm\" filename=\"libgazebo_ros_planar_move.so\"/></gazebo>\n");
  robot.name = "rover";
  add_model_name_namespaces(robot);
  PluginRig rig;
  ASSERT_EQ(rig.add(robot), "");
  EXPECT_EQ(plugin_of(rig, "dd")->ros_interface().robot_namespace, "rover");
  EXPECT_EQ(plugin_of(rig, "dd")->ros_interface().tf_prefix, "rover");
  rig.run(15);
  EXPECT_EQ(odometry(rig, "dd").frame_id, "rover/odom");
  EXPECT_EQ(odometry(rig, "dd").child_frame_id, "rover/base_footprint");
  EXPECT_EQ(plugin_of(rig, "jsp")->ros_interface().robot_namespace, "/own");
  EXPECT_EQ(plugin_of(rig, "pm")->ros_interface().robot_namespace, "");
  // A spawn namespace "/" (spawn_model at the root): no prefix; a leading '/' frame is absolute.
  const Params root = params_from_xml(plugin_test::robot_with("<gazebo><plugin name=\"dd\" filename=\"x.so\">"
                                                              "<robotNamespace>/</robotNamespace></plugin></gazebo>\n")
                                          .plugins[0]
                                          .xml,
                                      "bot.urdf", "dd");
  EXPECT_EQ(gazebo_ros_names(PluginParams(root), "bot").robot_namespace, "/");
  EXPECT_EQ(gazebo_ros_names(PluginParams(root), "bot").frame("odom"), "odom");
  EXPECT_EQ(tf_resolve("/r1", "odom"), "r1/odom");
  EXPECT_EQ(tf_resolve("r1", "/map"), "map");
}

}  // namespace
}  // namespace mechsim::control
