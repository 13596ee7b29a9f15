// Gazebo model plugins as controllers: their elements read with sdformat's conventions and errors
// naming file, line and plugin; which plugins mechsim simulates; and each plugin's behaviour on the
// test robot (ideal servos) through the manager's add_model_plugin: the diff drive's update rate,
// acceleration ramp, legacy mode and encoder odometry; the skid steer's four wheels; the planar
// move's base command and timeout; the joint state publisher; the mimic joint's PID; conflicts with
// ros_control controllers.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller_manager.hpp"
#include "control/params_xml.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/plugins/diff_drive_plugin.hpp"
#include "controllers/plugins/mimic_joint_plugin.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "controllers/plugins/plugin_params.hpp"
#include "controllers/plugins/test/plugin_rig.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;
using plugin_test::PluginRig;
using plugin_test::robot_with;

std::string build_error(const std::string& plugins) {
  try {
    build_model_plugins(robot_with(plugins), PluginContext{"bot", Params()});
  } catch (const ControllerConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

constexpr const char* kDiffDrive = R"(<gazebo>
  <plugin name="dd" filename="libgazebo_ros_diff_drive.so">
    <leftJoint>left</leftJoint>
    <rightJoint>right</rightJoint>
    <wheelSeparation>0.4</wheelSeparation>
    <wheelDiameter>0.2</wheelDiameter>
    <updateRate>50</updateRate>
    <odometrySource>encoder</odometrySource>
    <publishWheelJointState>true</publishWheelJointState>
    <robotNamespace>/bot</robotNamespace>
    EXTRA
  </plugin>
</gazebo>
)";

std::string diff_drive(const std::string& extra = "") {
  std::string s = kDiffDrive;
  s.replace(s.find("EXTRA"), 5, extra);
  return s;
}

// The diff drive with element `key`'s text replaced by `value`.
std::string diff_drive_with(const std::string& key, const std::string& value) {
  std::string s = diff_drive();
  const std::size_t open = s.find("<" + key + ">") + key.size() + 2;
  s.replace(open, s.find("</" + key + ">") - open, value);
  return s;
}

TEST(PluginParams, ElementsWithSdfConventionsAndLocatedErrors) {
  const description::RobotModel robot = robot_with(diff_drive("<legacyMode>1</legacyMode><wheelTorque>abc</wheelTorque>"));
  const Params p = params_from_xml(robot.plugins[0].xml, "bot.urdf", "dd");
  EXPECT_EQ(p.path(), "/dd");
  const PluginParams pp(p);
  EXPECT_TRUE(pp.boolean("legacyMode", false));
  EXPECT_DOUBLE_EQ(pp.number("wheelSeparation", 0.0), 0.4);
  EXPECT_DOUBLE_EQ(pp.number("wheelAcceleration", 1.5), 1.5);  // the plugin's default when absent
  EXPECT_EQ(pp.text("commandTopic", "cmd_vel"), "cmd_vel");
  try {
    pp.number("wheelTorque", 5.0);
    FAIL();
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bot.urdf:"));
    EXPECT_THAT(e.what(), HasSubstr("<wheelTorque> is not a number: \"abc\""));
  }
}

TEST(ModelPlugins, BadParametersNameFileLineAndPlugin) {
  EXPECT_THAT(build_error(diff_drive("").replace(diff_drive("").find("<leftJoint>left"), 15, "<leftJoint>nope")),
              HasSubstr("gazebo plugin 'dd' (libgazebo_ros_diff_drive.so): <leftJoint> (bot.urdf:"));
  EXPECT_THAT(build_error(diff_drive("").replace(diff_drive("").find("<leftJoint>left"), 15, "<leftJoint>nope")),
              HasSubstr("names joint 'nope', which robot 'bot' does not have"));
  // A plugin whose joint element is absent names its default joint, which the robot lacks.
  EXPECT_THAT(build_error("<gazebo><plugin name=\"skid\" filename=\"libgazebo_ros_skid_steer_drive.so\"/></gazebo>\n"),
              HasSubstr("'skid' (libgazebo_ros_skid_steer_drive.so): the plugin names joint 'left_front_joint'"));
  EXPECT_THAT(build_error("<gazebo><plugin name=\"jsp\" filename=\"libgazebo_ros_joint_state_publisher.so\"/></gazebo>\n"),
              HasSubstr("<jointName> is missing"));
  EXPECT_THAT(build_error("<gazebo><plugin name=\"m\" filename=\"libroboticsgroup_gazebo_mimic_joint_plugin.so\">"
                          "<joint>finger_a</joint></plugin></gazebo>\n"),
              HasSubstr("<mimicJoint> is missing"));
}

TEST(ModelPlugins, InitErrorsNameFileLineAndPlugin) {
  const auto error_of = [](const std::string& plugins) {
    PluginRig rig;
    return rig.add(plugins);
  };
  EXPECT_THAT(error_of(diff_drive_with("wheelDiameter", "0")), HasSubstr("Gazebo model plugin 'dd' (libgazebo_ros_diff_drive.so, bot.urdf:"));
  EXPECT_THAT(error_of(diff_drive_with("wheelDiameter", "0")), HasSubstr("<wheelDiameter> must be > 0 (got 0)"));
  EXPECT_THAT(error_of(diff_drive_with("updateRate", "-5")), HasSubstr("<updateRate> is a rate in Hz and must be >= 0"));
  EXPECT_THAT(error_of(diff_drive_with("odometrySource", "gps")), HasSubstr("<odometrySource> must be world or encoder"));
  EXPECT_THAT(error_of(diff_drive("<legacyMode>maybe</legacyMode>")), HasSubstr("<legacyMode> is not a boolean"));
}

TEST(ModelPlugins, CheckListsEveryModelPluginOnce) {
  const description::RobotModel robot = robot_with(
      diff_drive() + "<gazebo><plugin name=\"rc\" filename=\"libgazebo_ros_control.so\"/>"
                     "<plugin name=\"weird\" filename=\"libsomething_else.so\"><x>1</x></plugin></gazebo>\n");
  const std::vector<ModelPluginStatus> s = model_plugin_status(robot);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].handling, PluginHandling::Controller);
  EXPECT_EQ(s[1].handling, PluginHandling::ControllerManager);
  EXPECT_EQ(s[2].handling, PluginHandling::NotSimulated);
  EXPECT_FALSE(s[2].simulated());
  EXPECT_THAT(describe(s[2]), HasSubstr("gazebo plugin 'weird' (libsomething_else.so) at bot.urdf:"));
  EXPECT_THAT(describe(s[2]), HasSubstr("NOT SIMULATED"));
  // Only the simulated kinds become controllers; the unknown one is not fatal.
  EXPECT_EQ(build_model_plugins(robot, PluginContext{"bot", Params()}).size(), 1u);
}

TEST(DiffDrivePlugin, UpdatesAtItsRateWithinItsAccelerationLimit) {
  PluginRig rig;
  ASSERT_EQ(rig.add(diff_drive("<wheelAcceleration>1.0</wheelAcceleration><wheelTorque>3</wheelTorque>")), "");
  auto* dd = rig.plugin<DiffDrivePlugin>("dd");
  ASSERT_NE(dd, nullptr);
  EXPECT_EQ(dd->ros_interface().robot_namespace, "/bot");
  EXPECT_DOUBLE_EQ(rig.robot->joint("left").effort_limit, 3.0);  // wheelTorque: the motor's bound
  rig.send("dd", 0.5, 0.0, 0.0);
  rig.run(5);  // the first update is 20 ms after the start
  EXPECT_DOUBLE_EQ(rig.robot->joint("left").commanded_velocity, 0.0);
  rig.run(20);
  // One update so far: 1 m/s^2 over its 20 ms: 0.02 m/s at the rim, 0.2 rad/s.
  EXPECT_NEAR(rig.robot->joint("left").commanded_velocity, 0.2, 1e-9);
  rig.run(1000);
  EXPECT_NEAR(rig.robot->joint("left").commanded_velocity, 5.0, 1e-9);  // 0.5 m/s after 0.5 s
  EXPECT_NEAR(rig.robot->joint("right").commanded_velocity, 5.0, 1e-9);
}

TEST(DiffDrivePlugin, TurnsTheRightWayAndLegacyModeSwapsTheWheels) {
  for (const bool legacy : {false, true}) {
    PluginRig rig;
    ASSERT_EQ(rig.add(diff_drive(legacy ? "<legacyMode>true</legacyMode>" : "")), "");
    rig.send("dd", 0.0, 0.0, 1.0);
    rig.run(30);
    const double left = rig.robot->joint("left").commanded_velocity, right = rig.robot->joint("right").commanded_velocity;
    EXPECT_NEAR(legacy ? left : right, 2.0, 1e-12) << legacy;  // 1 rad/s * 0.2 m / 0.1 m
    EXPECT_NEAR(legacy ? right : left, -2.0, 1e-12) << legacy;
  }
}

TEST(DiffDrivePlugin, EncoderOdometryAndWheelJointStates) {
  PluginRig rig;
  ASSERT_EQ(rig.add(diff_drive()), "");
  rig.send("dd", 0.2, 0.0, 0.5);
  rig.run(2020);
  const auto* odom = dynamic_cast<StatePort<OdometrySnapshot>*>(rig.manager->controller("dd")->port("odom"));
  const auto* joints = dynamic_cast<StatePort<JointStateSnapshot>*>(rig.manager->controller("dd")->port("joint_states"));
  ASSERT_NE(odom, nullptr);
  ASSERT_NE(joints, nullptr);
  const OdometrySnapshot o = odom->read();
  // Driven 2 s along a circle of radius 0.4 m (the first 20 ms at rest).
  EXPECT_NEAR(o.yaw, 1.0, 0.02);
  EXPECT_NEAR(o.x, 0.4 * std::sin(o.yaw), 2e-3);
  EXPECT_NEAR(o.y, 0.4 * (1.0 - std::cos(o.yaw)), 2e-3);
  EXPECT_NEAR(o.angular.z, 0.5, 1e-9);
  EXPECT_EQ(o.frame_id, "bot/odom");  // the namespace /bot is the frames' TF prefix, as GazeboRos::resolveTF
  EXPECT_EQ(o.child_frame_id, "bot/base_footprint");
  EXPECT_DOUBLE_EQ(o.pose_covariance[0], 1e-5);
  EXPECT_DOUBLE_EQ(o.pose_covariance[14], 1e12);
  const JointStateSnapshot js = joints->read();
  ASSERT_EQ(js.names.size(), 2u);
  EXPECT_EQ(js.names[0], "left");
  EXPECT_GT(js.position[1], 0.0);  // the right wheel has turned forwards
  EXPECT_LE(js.position[1], rig.robot->joint("right").position);
  EXPECT_NEAR(std::fmod(js.stamp + 1e-9, 0.02), 0.0, 1e-6);  // published at 50 Hz
}

TEST(SkidSteerPlugin, DrivesFourWheelsAndPublishesWorldOdometry) {
  PluginRig rig;
  ASSERT_EQ(rig.add(R"(<gazebo><plugin name="skid" filename="libgazebo_ros_skid_steer_drive.so">
    <leftFrontJoint>left</leftFrontJoint><rightFrontJoint>right</rightFrontJoint>
    <leftRearJoint>rl</leftRearJoint><rightRearJoint>rr</rightRearJoint>
    <wheelSeparation>0.5</wheelSeparation><wheelDiameter>0.2</wheelDiameter><torque>7</torque>
    <covariance_yaw>0.5</covariance_yaw>
  </plugin></gazebo>)"),
            "");
  rig.robot->state.base.X_WB.position = {3.0, 4.0, 0.1};
  rig.send("skid", 0.0, 0.0, 2.0);
  rig.run(30);
  for (const char* j : {"left", "rl"}) EXPECT_NEAR(rig.robot->joint(j).commanded_velocity, -5.0, 1e-12) << j;
  for (const char* j : {"right", "rr"}) EXPECT_NEAR(rig.robot->joint(j).commanded_velocity, 5.0, 1e-12) << j;
  EXPECT_DOUBLE_EQ(rig.robot->joint("rr").effort_limit, 7.0);
  const OdometrySnapshot o = dynamic_cast<StatePort<OdometrySnapshot>*>(rig.manager->controller("skid")->port("odom"))->read();
  EXPECT_TRUE(o.in_world);
  EXPECT_DOUBLE_EQ(o.x, 3.0);
  EXPECT_DOUBLE_EQ(o.z, 0.0);  // the plugin sets x and y only
  EXPECT_DOUBLE_EQ(o.pose_covariance[35], 0.5);
  EXPECT_DOUBLE_EQ(o.twist_covariance[0], 0.0001);
}

TEST(PlanarMovePlugin, SetsTheBaseVelocityInTheWorldAndTimesOut) {
  PluginRig rig;
  ASSERT_EQ(rig.add("<gazebo><plugin name=\"pm\" filename=\"libgazebo_ros_planar_move.so\"><cmdTimeout>0.1</cmdTimeout>"
                    "</plugin></gazebo>\n"),
            "");
  // The base heading 90 degrees: a forward command moves it along the world's +y.
  rig.robot->state.base.X_WB.orientation = {std::cos(M_PI / 4), 0.0, 0.0, std::sin(M_PI / 4)};
  rig.send("pm", 0.5, 0.2, 0.3);
  rig.run(2);
  const mechanism::BaseVelocityCommand& c = rig.robot->state.base_command;
  ASSERT_TRUE(c.active);
  EXPECT_NEAR(c.vx, -0.2, 1e-12);
  EXPECT_NEAR(c.vy, 0.5, 1e-12);
  EXPECT_NEAR(c.wz, 0.3, 1e-12);
  rig.run(150);  // over cmdTimeout: stopped
  EXPECT_NEAR(c.vy, 0.0, 1e-12);
  EXPECT_NEAR(c.wz, 0.0, 1e-12);
  // A second plugin moving the base is refused, naming both.
  EXPECT_THAT(rig.add("<gazebo><plugin name=\"pm2\" filename=\"libgazebo_ros_planar_move.so\"/></gazebo>\n"),
              HasSubstr("the floating base is claimed by both Gazebo model plugin 'pm'"));
}

TEST(PlanarMovePlugin, RefusesARobotFixedToTheWorld) {
  PluginRig rig;
  rig.robot->state.base.floating = false;
  EXPECT_THAT(rig.add("<gazebo><plugin name=\"pm\" filename=\"libgazebo_ros_planar_move.so\"/></gazebo>\n"),
              HasSubstr("fixed to the world"));
}

TEST(JointStatePublisherPlugin, PublishesItsJointsAtItsRate) {
  PluginRig rig;
  ASSERT_EQ(rig.add("<gazebo><plugin name=\"jsp\" filename=\"libgazebo_ros_joint_state_publisher.so\">"
                    "<jointName>pan, finger_a</jointName><updateRate>10</updateRate></plugin></gazebo>\n"),
            "");
  rig.set_position("pan", 0.25);
  auto* port = dynamic_cast<StatePort<JointStateSnapshot>*>(rig.manager->controller("jsp")->port("joint_states"));
  rig.run(50);
  EXPECT_EQ(port->sequence(), 0u);  // nothing before the first 0.1 s
  rig.run(60);
  const JointStateSnapshot s = port->read();
  EXPECT_EQ(port->sequence(), 1u);
  ASSERT_EQ(s.names, (std::vector<std::string>{"pan", "finger_a"}));
  EXPECT_DOUBLE_EQ(s.position[0], 0.25);
  EXPECT_TRUE(s.effort.empty());
  // Without <robotNamespace>: the root, where spawn_model at the root puts it (an SDF world's
  // model gets the model's name written in: WorldModelsTakeTheirNameAsGazeboRosNamespace).
  EXPECT_EQ(dynamic_cast<ModelPlugin*>(rig.manager->controller("jsp"))->ros_interface().robot_namespace, "");
  // An empty one is the model's name (GazeboRos).
  PluginRig empty;
  ASSERT_EQ(empty.add("<gazebo><plugin name=\"jsp\" filename=\"libgazebo_ros_joint_state_publisher.so\">"
                      "<jointName>pan</jointName><robotNamespace></robotNamespace></plugin></gazebo>\n"),
            "");
  EXPECT_EQ(dynamic_cast<ModelPlugin*>(empty.manager->controller("jsp"))->ros_interface().robot_namespace, "bot");
}

TEST(MimicJointPlugin, PidDrivesTheFollowerWithinMaxEffort) {
  PluginRig rig;
  const Params server = Params::from_yaml_string("gazebo_ros_control: {pid_gains: {finger_b: {p: 100.0, d: 0.0}}}\n");
  ASSERT_EQ(rig.add("<gazebo><plugin name=\"mimic\" filename=\"libroboticsgroup_gazebo_mimic_joint_plugin.so\">"
                    "<joint>finger_a</joint><mimicJoint>finger_b</mimicJoint><multiplier>-2</multiplier><offset>0.1</offset>"
                    "<maxEffort>3</maxEffort><sensitiveness>0.001</sensitiveness><hasPID/></plugin></gazebo>\n",
                    server),
            "");
  auto* m = rig.plugin<MimicJointPlugin>("mimic");
  ASSERT_NE(m, nullptr);
  EXPECT_TRUE(m->has_pid());
  rig.set_position("finger_a", 0.2);  // target -0.4 + 0.1 = -0.3
  rig.run(1);
  EXPECT_DOUBLE_EQ(rig.robot->joint("finger_b").commanded_effort, -3.0);  // 100 * -0.3, clamped to 3
  auto* state = dynamic_cast<StatePort<JointControllerState>*>(m->port("state"));
  EXPECT_NEAR(state->read().set_point, -0.3, 1e-12);
  // Within sensitiveness: no effort.
  rig.robot->joint("finger_b").velocity = 0.0;
  rig.set_position("finger_b", -0.2995);
  rig.run(1);
  EXPECT_DOUBLE_EQ(rig.robot->joint("finger_b").commanded_effort, 0.0);
}

TEST(MimicJointPlugin, PidWithoutGainsIsAnErrorAndUpatrasDefaultsToTheEffortLimit) {
  PluginRig rig;
  EXPECT_THAT(rig.add("<gazebo><plugin name=\"mimic\" filename=\"libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so\">"
                      "<joint>finger_a</joint><mimicJoint>finger_b</mimicJoint><hasPID/></plugin></gazebo>\n"),
              HasSubstr("no gains at /gazebo_ros_control/pid_gains/finger_b"));
  PluginRig plain;
  ASSERT_EQ(plain.add("<gazebo><plugin name=\"mimic\" filename=\"libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so\">"
                      "<joint>finger_a</joint><mimicJoint>finger_b</mimicJoint></plugin></gazebo>\n"),
            "");
  auto* m = plain.plugin<MimicJointPlugin>("mimic");
  EXPECT_FALSE(m->has_pid());
  EXPECT_DOUBLE_EQ(m->max_effort(), 100.0);  // the test robot's effort limit
}

TEST(ModelPlugins, AJointClaimedByAPluginAndAControllerIsAnErrorNamingBoth) {
  PluginRig rig("bot:\n  wheel_velocity: {type: velocity_controllers/JointVelocityController, joint: left}\n"
                "  jsc: {type: joint_state_controller/JointStateController, publish_rate: 10}\n");
  ASSERT_EQ(rig.add(diff_drive()), "");
  const ControlResult r = rig.manager->load_controller("wheel_velocity");
  ASSERT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("joint 'left' is claimed by both Gazebo model plugin 'dd' (libgazebo_ros_diff_drive.so, bot.urdf:"));
  EXPECT_THAT(r.error, HasSubstr("and controller 'wheel_velocity'"));
  EXPECT_TRUE(rig.manager->load_controller("jsc").ok);  // reading joints claims nothing
  // The plugin runs for the life of the simulation.
  EXPECT_THAT(rig.manager->unload_controller("dd").error, HasSubstr("runs for the life of the simulation"));
  EXPECT_THAT(rig.manager->switch_controllers({}, {"dd"}, SwitchStrictness::Strict).error,
              HasSubstr("runs for the life of the simulation"));
  EXPECT_TRUE(rig.manager->switch_controllers({"dd"}, {"dd"}, SwitchStrictness::Strict).ok);  // a restart (reset)
  const auto info = rig.manager->controller_info("dd");
  ASSERT_TRUE(info);
  EXPECT_TRUE(info->model_plugin);
  EXPECT_EQ(info->state, ControllerLifecycle::Running);
}

}  // namespace
}  // namespace mechsim::control
