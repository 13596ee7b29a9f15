// ros2_controllers' types over a ros2_control robot's mechanism, configured from a ROS 2
// parameter file: what each reads, claims, commands and publishes, the controller manager's
// hold_joints and per-controller rates, and the errors bad parameters get (the path named).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "control/controller_check.hpp"
#include "control/controller_manager.hpp"
#include "control/ros2_params.hpp"
#include "control/sensor_hardware.hpp"
#include "controllers/drive/diff_drive_controller.hpp"
#include "controllers/ros2_control/imu_sensor_broadcaster.hpp"
#include "controllers/ros2_control/joint_state_broadcaster.hpp"
#include "controllers/ros2_control/ros2_controllers.hpp"
#include "controllers/ros2_control/tricycle_controller.hpp"
#include "controllers/trajectory/trajectory_controller.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

// An arm joint on position and velocity commands, one on effort, two wheels, a steering joint and
// a traction wheel, a state-only joint, and an IMU.
constexpr const char* kUrdf = R"(<robot name="bot">
  <link name="base"/>
  <link name="l1"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="l2"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="wl"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="wr"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="st"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="tw"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="pj"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="arm1" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="10" velocity="100"/></joint>
  <joint name="arm2" type="revolute"><parent link="l1"/><child link="l2"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="10" velocity="100"/></joint>
  <joint name="left_wheel" type="continuous"><parent link="base"/><child link="wl"/><axis xyz="0 1 0"/></joint>
  <joint name="right_wheel" type="continuous"><parent link="base"/><child link="wr"/><axis xyz="0 1 0"/></joint>
  <joint name="steer" type="revolute"><parent link="base"/><child link="st"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="10" velocity="100"/></joint>
  <joint name="traction" type="continuous"><parent link="st"/><child link="tw"/><axis xyz="0 1 0"/></joint>
  <joint name="passive" type="continuous"><parent link="base"/><child link="pj"/><axis xyz="0 1 0"/></joint>
  <gazebo reference="base"><sensor name="imu" type="imu"><update_rate>100</update_rate></sensor></gazebo>
  <ros2_control name="Bot" type="system">
    <hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin></hardware>
    <joint name="arm1"><command_interface name="position"/><command_interface name="velocity"/>
      <state_interface name="position"/><state_interface name="velocity"/><state_interface name="effort"/></joint>
    <joint name="arm2"><command_interface name="effort"/><state_interface name="position"/><state_interface name="velocity"/></joint>
    <joint name="left_wheel"><command_interface name="velocity"/><state_interface name="position"/><state_interface name="velocity"/></joint>
    <joint name="right_wheel"><command_interface name="velocity"/><state_interface name="position"/><state_interface name="velocity"/></joint>
    <joint name="steer"><command_interface name="position"/><state_interface name="position"/></joint>
    <joint name="traction"><command_interface name="velocity"/><state_interface name="velocity"/></joint>
    <joint name="passive"><state_interface name="position"/></joint>
    <sensor name="imu"><state_interface name="orientation.w"/><state_interface name="angular_velocity.z"/></sensor>
  </ros2_control>
</robot>)";

constexpr const char* kYaml = R"(controller_manager:
  ros__parameters:
    update_rate: 1000
    jsb: {type: joint_state_broadcaster/JointStateBroadcaster}
    jsb_some: {type: joint_state_broadcaster/JointStateBroadcaster}
    jsb_slow: {type: joint_state_broadcaster/JointStateBroadcaster}
    forward: {type: forward_command_controller/ForwardCommandController}
    group_effort: {type: effort_controllers/JointGroupEffortController}
    jtc_position: {type: joint_trajectory_controller/JointTrajectoryController}
    jtc_velocity: {type: joint_trajectory_controller/JointTrajectoryController}
    base: {type: diff_drive_controller/DiffDriveController}
    tricycle: {type: tricycle_controller/TricycleController}
    imu_broadcaster: {type: imu_sensor_broadcaster/IMUSensorBroadcaster}
jsb_some:
  ros__parameters:
    joints: [arm1, left_wheel]
    interfaces: [position, velocity]
    extra_joints: [caster]
jsb_slow:
  ros__parameters:
    update_rate: 100
forward:
  ros__parameters:
    joints: [arm1, steer]
    interface_name: position
group_effort:
  ros__parameters:
    joints: [arm2]
jtc_position:
  ros__parameters:
    joints: [arm1]
    command_interfaces: [position, velocity]
    state_interfaces: [position, velocity]
jtc_velocity:
  ros__parameters:
    joints: [arm1]
    command_interfaces: [velocity]
    state_interfaces: [position, velocity]
    gains:
      arm1: {p: 4.0, i: 0.5, d: 0.1, i_clamp: 2.0, ff_velocity_scale: 0.8}
base:
  ros__parameters:
    left_wheel_names: [left_wheel]
    right_wheel_names: [right_wheel]
    wheel_separation: 0.4
    wheel_radius: 0.1
    linear.x.has_velocity_limits: true
    linear.x.max_velocity: 0.5
tricycle:
  ros__parameters:
    traction_joint_name: traction
    steering_joint_name: steer
    wheelbase: 0.5
    wheel_radius: 0.1
imu_broadcaster:
  ros__parameters:
    sensor_name: imu
    frame_id: imu_frame
    static_covariance_orientation: [1, 0, 0, 0, 2, 0, 0, 0, 3]
)";

class Ros2Controllers : public ::testing::Test {
 protected:
  Ros2Controllers()
      : robot_(description::parse_urdf_string(kUrdf, "bot.urdf", {})),
        model_(mechanism::build_mechanism(robot_)),
        state_(mechanism::make_state(model_)),
        sensors_(make_sensor_hardware(robot_.sensors)) {}

  // A manager over `yaml` (kYaml by default), at the controller manager's update_rate.
  std::unique_ptr<ControllerManager> manager(const std::string& yaml = kYaml) {
    Ros2ParameterSet set;
    set.add_yaml(yaml, "bot_controllers.yaml");
    const Ros2ControlSetup setup = ros2_control_setup(set, "/controller_manager");
    auto m = std::make_unique<ControllerManager>(model_, state_, setup.controllers, ros2_controller_registry(ControllerPluginSet{}));
    m->set_sensor_hardware(sensors_.get());
    m->set_update_rate(setup.update_rate);
    return m;
  }
  // Loads and starts `names`, then runs `ticks` 1 ms ticks from `time`.
  void start(ControllerManager& m, const std::vector<std::string>& names) {
    for (const std::string& n : names) ASSERT_TRUE(m.load_controller(n)) << m.load_controller(n).error;
    ASSERT_TRUE(m.switch_controllers(names, {}, SwitchStrictness::Strict));
  }
  void run(ControllerManager& m, int ticks) {
    for (int i = 0; i < ticks; ++i) {
      m.update(time_, 0.001);
      time_ += 0.001;
    }
  }
  mechanism::JointState& joint(const std::string& name) { return state_.joints[static_cast<std::size_t>(model_.joint_index(name))]; }
  // Sets a joint's measured state (what the physics would report), through its actuator.
  void measure(const std::string& name, double position, double velocity) {
    mechanism::JointState& j = joint(name);
    j.position = position;
    j.velocity = velocity;
    mechanism::propagate_joint_to_actuator_position(model_, state_);
  }
  std::string load_error(const std::string& yaml, const std::string& name) {
    auto m = manager(yaml);
    const ControlResult r = m->load_controller(name);
    return r.ok ? "loaded" : r.error;
  }

  description::RobotModel robot_;
  mechanism::MechanismModel model_;
  mechanism::MechanismState state_;
  std::unique_ptr<SensorHardware> sensors_;
  double time_ = 0.0;
};

TEST_F(Ros2Controllers, JointStateBroadcasterPublishesEveryRos2JointWithNanForMissingInterfaces) {
  auto m = manager();
  start(*m, {"jsb"});
  measure("arm1", 0.3, -0.2);
  measure("passive", 1.25, 4.0);
  run(*m, 1);
  auto* jsb = dynamic_cast<JointStateBroadcaster*>(m->controller("jsb"));
  const JointStateSnapshot s = jsb->joint_states_port().read();
  EXPECT_EQ(s.names, (std::vector<std::string>{"arm1", "arm2", "left_wheel", "right_wheel", "steer", "traction", "passive"}));
  EXPECT_DOUBLE_EQ(s.position[0], 0.3);
  EXPECT_DOUBLE_EQ(s.velocity[0], -0.2);
  EXPECT_TRUE(std::isnan(s.effort[1]));      // arm2 has no effort state interface
  EXPECT_TRUE(std::isnan(s.position[5]));    // traction: velocity only
  EXPECT_DOUBLE_EQ(s.position[6], 1.25);
  EXPECT_TRUE(std::isnan(s.velocity[6]));    // passive: position only
  // It claims nothing, and publishes every update (the manager's rate).
  EXPECT_TRUE(m->controller_info("jsb")->claims.empty());
  const std::uint64_t before = jsb->joint_states_port().sequence();
  run(*m, 10);
  EXPECT_EQ(jsb->joint_states_port().sequence() - before, 10u);
}

TEST_F(Ros2Controllers, JointStateBroadcasterFiltersByJointsAndInterfacesAndAddsExtraJoints) {
  auto m = manager();
  start(*m, {"jsb_some"});
  measure("left_wheel", 2.0, 3.0);
  run(*m, 1);
  const JointStateSnapshot s = dynamic_cast<JointStateBroadcaster*>(m->controller("jsb_some"))->joint_states_port().read();
  EXPECT_EQ(s.names, (std::vector<std::string>{"arm1", "left_wheel", "caster"}));
  EXPECT_DOUBLE_EQ(s.velocity[1], 3.0);
  EXPECT_TRUE(std::isnan(s.effort[0]));  // effort not asked for
  EXPECT_EQ(s.position[2], 0.0);
  // A joint without an interface asked for: its claim would fail in ros2_control.
  const std::string yaml = std::string(kYaml).replace(std::string(kYaml).find("joints: [arm1, left_wheel]"),
                                                     std::string("joints: [arm1, left_wheel]").size(), "joints: [arm1, traction]");
  EXPECT_THAT(load_error(yaml, "jsb_some"), HasSubstr("joint 'traction' (/jsb_some/joints[1]) has no position state interface"));
}

TEST_F(Ros2Controllers, AControllersOwnUpdateRateRunsItSlowerThanTheManager) {
  auto m = manager();
  start(*m, {"jsb_slow"});
  auto* jsb = dynamic_cast<JointStateBroadcaster*>(m->controller("jsb_slow"));
  const std::uint64_t before = jsb->joint_states_port().sequence();
  run(*m, 100);  // 0.1 s at 1 kHz: 10 updates at 100 Hz
  EXPECT_EQ(jsb->joint_states_port().sequence() - before, 10u);
}

TEST_F(Ros2Controllers, ForwardCommandControllerWritesItsInterface) {
  auto m = manager();
  start(*m, {"forward"});
  const ControllerInfo info = *m->controller_info("forward");
  ASSERT_EQ(info.claims.size(), 1u);
  EXPECT_EQ(info.claims[0].interface, HardwareInterface::Position);
  EXPECT_EQ(info.claims[0].joints, (std::vector<std::string>{"arm1", "steer"}));
  auto* command = m->controller("forward")->port_as<ArrayCommandPort>("command");
  ASSERT_NE(command, nullptr);
  run(*m, 1);  // started: it holds where the joints are
  ASSERT_TRUE(command->write(std::vector<double>{0.04, -0.02}));
  std::string error;
  EXPECT_FALSE(command->write(std::vector<double>{0.4}, &error));  // ~/commands of the wrong size
  run(*m, 1);
  EXPECT_EQ(joint("arm1").command_mode, HardwareInterface::Position);
  EXPECT_DOUBLE_EQ(joint("arm1").commanded_position, 0.04);
  EXPECT_DOUBLE_EQ(joint("steer").commanded_position, -0.02);
}

TEST_F(Ros2Controllers, ForwardCommandControllerParameterErrorsNameThePath) {
  const auto with = [](const std::string& from, const std::string& by) {
    std::string y = kYaml;
    y.replace(y.find(from), from.size(), by);
    return y;
  };
  EXPECT_THAT(load_error(with("interface_name: position", "interface_name: torque"), "forward"),
              HasSubstr("parameter /forward/interface_name: interface 'torque' is none of position, velocity, effort"));
  EXPECT_THAT(load_error(with("interface_name: position", "interface_name: velocity"), "forward"),
              HasSubstr("steer"));  // steer offers no velocity command interface
  EXPECT_THAT(load_error(with("    interface_name: position\n", ""), "forward"), HasSubstr("/forward/interface_name not set"));
  EXPECT_THAT(load_error(with("joints: [arm1, steer]", "joints: [arm1, elbow]"), "forward"), HasSubstr("elbow"));
}

TEST_F(Ros2Controllers, HoldJointsKeepsUnclaimedActuatedJointsWhereTheyWere) {
  auto m = manager();
  start(*m, {"group_effort"});
  joint("arm1").command_mode = HardwareInterface::Effort;
  measure("arm1", 0.7, 0.0);
  run(*m, 1);
  EXPECT_EQ(joint("arm1").command_mode, HardwareInterface::Position);  // unclaimed: held
  EXPECT_EQ(joint("arm1").commanded_position, 0.7);
  measure("arm1", 0.65, 0.0);  // pushed: held where it was let go, not where it is
  run(*m, 1);
  EXPECT_EQ(joint("arm1").commanded_position, 0.7);
  EXPECT_EQ(joint("arm2").command_mode, HardwareInterface::Effort);  // claimed by group_effort
  EXPECT_EQ(joint("passive").command_mode, HardwareInterface::Effort);  // no command interface: free
  // Claimed, then let go again: held where it was then.
  ASSERT_TRUE(m->load_controller("forward"));
  ASSERT_TRUE(m->switch_controllers({"forward"}, {}, SwitchStrictness::Strict));
  run(*m, 1);
  measure("arm1", 0.6, 0.0);
  ASSERT_TRUE(m->switch_controllers({}, {"forward"}, SwitchStrictness::Strict));
  run(*m, 1);
  EXPECT_EQ(joint("arm1").commanded_position, 0.6);
}

TEST_F(Ros2Controllers, JointTrajectoryControllerReadsRos2Parameters) {
  auto m = manager();
  ASSERT_TRUE(m->load_controller("jtc_position"));
  EXPECT_EQ(m->controller_info("jtc_position")->claims[0].interface, HardwareInterface::Position);
  ASSERT_TRUE(m->load_controller("jtc_velocity"));
  EXPECT_EQ(m->controller_info("jtc_velocity")->claims[0].interface, HardwareInterface::Velocity);
  auto* jtc = dynamic_cast<JointTrajectoryController*>(m->controller("jtc_velocity"));
  auto* gains = jtc->port_as<PidGainsPort>("gains/arm1");
  ASSERT_NE(gains, nullptr);
  EXPECT_EQ(gains->latest().p, 4.0);
  EXPECT_EQ(gains->latest().i_max, 2.0);
  // Holding still at start, the velocity command is the PID's: zero error, zero command.
  ASSERT_TRUE(m->switch_controllers({"jtc_velocity"}, {}, SwitchStrictness::Strict));
  measure("arm1", 0.5, 0.0);
  run(*m, 2);
  EXPECT_EQ(joint("arm1").command_mode, HardwareInterface::Velocity);
  EXPECT_NEAR(joint("arm1").commanded_velocity, 0.0, 1e-12);

  const auto with = [](const std::string& from, const std::string& by) {
    std::string y = kYaml;
    y.replace(y.find(from), from.size(), by);
    return y;
  };
  EXPECT_THAT(load_error(with("    command_interfaces: [position, velocity]\n", ""), "jtc_position"),
              HasSubstr("parameter /jtc_position/command_interfaces not set"));
  EXPECT_THAT(load_error(with("command_interfaces: [position, velocity]", "command_interfaces: [effort, position]"), "jtc_position"),
              HasSubstr("'effort' cannot be combined"));
  EXPECT_THAT(load_error(with("joints: [arm1]\n    command_interfaces: [position, velocity]",
                              "joints: [steer]\n    command_interfaces: [position, velocity]"), "jtc_position"),
              HasSubstr("joint 'steer' (/jtc_position/joints[0]) has no velocity command interface"));
  EXPECT_THAT(load_error(with("joints: [arm1]\n    command_interfaces: [velocity]", "joints: [traction]\n    command_interfaces: [velocity]"),
                         "jtc_velocity"),
              HasSubstr("joint 'traction' (/jtc_velocity/joints[0]) has no position state interface"));
  EXPECT_THAT(load_error(with("joints: [arm1]\n    command_interfaces: [position, velocity]\n    state_interfaces: [position, velocity]",
                              "joints: [arm1]\n    command_interfaces: [position, velocity]\n    state_interfaces: [velocity]"),
                         "jtc_position"),
              HasSubstr("/jtc_position/state_interfaces must list 'position'"));
  EXPECT_THAT(load_error(with("command_interfaces: [velocity]\n    state_interfaces: [position, velocity]",
                              "command_interfaces: [velocity]\n    state_interfaces: [position]"),
                         "jtc_velocity"),
              HasSubstr("/jtc_velocity/state_interfaces must list 'velocity' with command interface velocity"));
}

TEST_F(Ros2Controllers, DiffDriveControllerWithRos2ParametersAndItsErrors) {
  auto m = manager();
  start(*m, {"base"});
  auto* dd = dynamic_cast<DiffDriveController*>(m->controller("base"));
  EXPECT_EQ(dd->config().left_wheels, (std::vector<std::string>{"left_wheel"}));
  EXPECT_TRUE(dd->config().linear.has_velocity_limits);
  EXPECT_EQ(dd->config().linear.min_velocity, -0.5);  // unset min: -max
  run(*m, 1);  // started: the command zeroed
  ASSERT_TRUE(dd->command_port().write(Twist{{1.0, 0.0, 0.0}, {0.0, 0.0, 0.5}}));
  run(*m, 1);
  // 0.5 m/s (the limit), 0.5 rad/s: left (0.5 - 0.5 * 0.2) / 0.1 = 4 rad/s, right 6 rad/s.
  EXPECT_NEAR(joint("left_wheel").commanded_velocity, 4.0, 1e-9);
  EXPECT_NEAR(joint("right_wheel").commanded_velocity, 6.0, 1e-9);

  const auto with = [](const std::string& from, const std::string& by) {
    std::string y = kYaml;
    y.replace(y.find(from), from.size(), by);
    return y;
  };
  EXPECT_THAT(load_error(with("right_wheel_names: [right_wheel]", "right_wheel_names: [right_wheel, passive]"), "base"),
              HasSubstr("list 1 and 2 wheels"));
  EXPECT_THAT(load_error(with("    wheel_separation: 0.4\n", ""), "base"), HasSubstr("parameter /base/wheel_separation not set"));
  EXPECT_THAT(load_error(with("    linear.x.max_velocity: 0.5\n", ""), "base"),
              HasSubstr("parameter /base/linear/x/has_velocity_limits is true but /base/linear/x/max_velocity is not set"));
  EXPECT_THAT(load_error(with("left_wheel_names: [left_wheel]", "left_wheel: [left_wheel]"), "base"),
              HasSubstr("parameter /base/left_wheel_names not set"));
}

TEST_F(Ros2Controllers, TricycleControllerTurnsATwistIntoSteeringAndTraction) {
  auto m = manager();
  start(*m, {"tricycle"});
  auto* t = dynamic_cast<TricycleController*>(m->controller("tricycle"));
  run(*m, 1);  // started: the command zeroed
  // 0.5 m/s at 0.5 rad/s: alpha = atan(0.5 * 0.5 / 0.5) = 0.4636 rad, Ws = 0.5 / (0.1 cos alpha).
  // (The steering joint's position commands move at most 0.1 rad a tick: its URDF velocity
  // limit, mechanism/safety_limits.hpp; 20 ticks get there.)
  ASSERT_TRUE(t->command_port().write(Twist{{0.5, 0.0, 0.0}, {0.0, 0.0, 0.5}}));
  measure("steer", std::atan(0.5), 0.0);
  run(*m, 20);
  EXPECT_NEAR(joint("steer").commanded_position, std::atan(0.5), 1e-9);
  EXPECT_NEAR(joint("traction").commanded_velocity, 0.5 / (0.1 * std::cos(std::atan(0.5))), 1e-9);
  // Turning in place: the wheel across (-pi/2 for a right turn), |w| wheelbase / r (the steering
  // already there: no scaling of the speed).
  ASSERT_TRUE(t->command_port().write(Twist{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}}));
  measure("steer", -M_PI_2, 0.0);
  run(*m, 30);
  EXPECT_NEAR(joint("steer").commanded_position, -M_PI_2, 1e-9);
  EXPECT_NEAR(joint("traction").commanded_velocity, 1.0 * 0.5 / 0.1, 1e-9);
  // Odometry from the traction wheel and the steering angle: 2 rad/s at 0 rad for 0.1 s.
  ASSERT_TRUE(m->switch_controllers({}, {"tricycle"}, SwitchStrictness::Strict));
  run(*m, 1);
  ASSERT_TRUE(m->switch_controllers({"tricycle"}, {}, SwitchStrictness::Strict));
  measure("steer", 0.0, 0.0);
  measure("traction", 0.0, 2.0);
  run(*m, 100);
  const OdometrySnapshot o = t->odometry_port().read();
  EXPECT_NEAR(o.x, 2.0 * 0.1 * 0.1, 1e-6);
  EXPECT_NEAR(o.linear.x, 0.2, 1e-9);
}

TEST_F(Ros2Controllers, ImuSensorBroadcasterPublishesTheSensorInItsFrame) {
  auto m = manager();
  start(*m, {"imu_broadcaster"});
  sensors_->imus()[0].angular_velocity = {0.1, 0.2, 0.3};
  run(*m, 1);
  const ImuSnapshot s = dynamic_cast<ImuSensorBroadcaster*>(m->controller("imu_broadcaster"))->imu_port().read();
  EXPECT_EQ(s.imu.frame_id, "imu_frame");
  EXPECT_EQ(s.imu.angular_velocity[2], 0.3);
  EXPECT_EQ(s.imu.orientation_covariance[4], 2.0);
  std::string yaml = kYaml;
  yaml.replace(yaml.find("sensor_name: imu"), std::string("sensor_name: imu").size(), "sensor_name: lidar");
  EXPECT_THAT(load_error(yaml, "imu_broadcaster"), HasSubstr("lidar"));
}

TEST_F(Ros2Controllers, CheckListsEveryDeclaredControllerWithItsClaims) {
  Ros2ParameterSet set;
  set.add_yaml(kYaml, "bot_controllers.yaml");
  const std::vector<ControllerCheck> checks =
      check_controllers(model_, ros2_control_setup(set, "/controller_manager").controllers,
                        ros2_controller_registry(ControllerPluginSet{}), sensors_.get());
  ASSERT_EQ(checks.size(), 10u);
  for (const ControllerCheck& c : checks) EXPECT_TRUE(c.ok()) << describe(c);
  EXPECT_EQ(describe(checks[3]), "/forward (forward_command_controller/ForwardCommandController): position [arm1, steer]");
}

}  // namespace
}  // namespace mechsim::control
