// diff_drive_controller/DiffDriveController on the test robot (ideal velocity servos): wheel
// speeds from a twist with the separation and radius multipliers, two wheels a side, the command
// timeout, the speed limits, odometry (closed and open loop), cmd_vel_out, a husky-style parameter
// set, and configuration errors naming the parameter.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/drive/diff_drive_controller.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

constexpr const char* kBase = R"(bot:
  dd:
    type: diff_drive_controller/DiffDriveController
    left_wheel: left
    right_wheel: right
    wheel_separation: 0.4
    wheel_radius: 0.1
)";

struct Drive {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  DiffDriveController* c = nullptr;
  double time = 0.0;

  explicit Drive(const std::string& yaml, std::vector<std::string> joints = {"left", "right"}) {
    std::vector<testing::JointSpec> specs;
    for (const std::string& j : joints) specs.push_back({j, description::JointType::Continuous});
    robot = testing::make_robot(specs);
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml).child("bot"),
                                                  builtin_controller_registry());
    c = dynamic_cast<DiffDriveController*>(testing::load_and_start(*manager, "dd"));
    run(1);  // the switch: starting() zeroes the command
  }
  void run(int ticks) { time = testing::run(*manager, *robot, time, ticks); }
  void send(double v, double w) {
    Twist t;
    t.linear.x = v;
    t.angular.z = w;
    ASSERT_TRUE(c->command_port().write(t));
  }
  double wheel(const std::string& j) { return robot->joint(j).commanded_velocity; }
};

TEST(DiffDriveController, WheelSpeedsFromATwist) {
  Drive d(kBase);
  ASSERT_NE(d.c, nullptr);
  d.send(0.5, 1.0);
  d.run(2);
  EXPECT_NEAR(d.wheel("left"), (0.5 - 0.2) / 0.1, 1e-12);
  EXPECT_NEAR(d.wheel("right"), (0.5 + 0.2) / 0.1, 1e-12);
  EXPECT_EQ(d.robot->joint("left").command_mode, HardwareInterface::Velocity);
}

TEST(DiffDriveController, MultipliersScaleSeparationAndRadii) {
  Drive d(std::string(kBase) + "    wheel_separation_multiplier: 2.0\n    left_wheel_radius_multiplier: 0.5\n");
  d.send(0.5, 1.0);
  d.run(2);
  EXPECT_NEAR(d.wheel("left"), (0.5 - 0.4) / 0.05, 1e-12);  // separation 0.8, left radius 0.05
  EXPECT_NEAR(d.wheel("right"), (0.5 + 0.4) / 0.1, 1e-12);
  // wheel_radius_multiplier, when given, sets both sides.
  Drive both(std::string(kBase) + "    wheel_radius_multiplier: 2.0\n    left_wheel_radius_multiplier: 0.5\n");
  both.send(1.0, 0.0);
  both.run(2);
  EXPECT_NEAR(both.wheel("left"), 1.0 / 0.2, 1e-12);
  EXPECT_NEAR(both.wheel("right"), 1.0 / 0.2, 1e-12);
}

TEST(DiffDriveController, SkidSteerDrivesEveryWheelOfASide) {
  Drive d(R"(bot:
  dd:
    type: diff_drive_controller/DiffDriveController
    left_wheel: [fl, rl]
    right_wheel: [fr, rr]
    wheel_separation: 0.5
    wheel_radius: 0.1
)",
          {"fl", "fr", "rl", "rr"});
  ASSERT_NE(d.c, nullptr);
  d.send(0.0, 1.0);
  d.run(2);
  for (const char* j : {"fl", "rl"}) EXPECT_NEAR(d.wheel(j), -2.5, 1e-12) << j;
  for (const char* j : {"fr", "rr"}) EXPECT_NEAR(d.wheel(j), 2.5, 1e-12) << j;
  const auto claims = d.manager->controller_info("dd")->claims;
  ASSERT_EQ(claims.size(), 1u);
  EXPECT_EQ(claims[0].interface, HardwareInterface::Velocity);
  EXPECT_EQ(claims[0].joints.size(), 4u);
}

TEST(DiffDriveController, StopsWhenTheCommandTimesOut) {
  Drive d(std::string(kBase) + "    cmd_vel_timeout: 0.2\n");
  d.send(0.5, 0.0);
  d.run(150);
  EXPECT_NEAR(d.wheel("left"), 5.0, 1e-12);
  d.run(100);  // 0.25 s since the command
  EXPECT_DOUBLE_EQ(d.wheel("left"), 0.0);
  d.send(0.3, 0.0);  // a fresh command drives again
  d.run(2);
  EXPECT_NEAR(d.wheel("left"), 3.0, 1e-12);
}

TEST(DiffDriveController, LimitsAccelerationAndVelocity) {
  Drive d(std::string(kBase) + R"(    cmd_vel_timeout: 100
    linear:
      x: {has_velocity_limits: true, max_velocity: 1.0, has_acceleration_limits: true, max_acceleration: 2.0}
    angular:
      z: {has_velocity_limits: true, max_velocity: 1.0}
    publish_cmd: true
)");
  ASSERT_EQ(d.c->ports().size(), 3u);  // cmd_vel, odom, cmd_vel_out
  d.send(5.0, 4.0);
  d.run(100);  // 0.1 s at 2 m/s^2: 0.2 m/s
  auto* out = dynamic_cast<StatePort<TwistSnapshot>*>(d.c->port("cmd_vel_out"));
  ASSERT_NE(out, nullptr);
  EXPECT_NEAR(out->read().twist.linear.x, 0.2, 1e-9);
  EXPECT_NEAR(out->read().twist.angular.z, 1.0, 1e-12);  // no angular acceleration limit
  d.run(900);
  EXPECT_NEAR(out->read().twist.linear.x, 1.0, 1e-12);
  EXPECT_EQ(out->read().frame_id, "base_link");
}

TEST(DiffDriveController, OdometryFollowsTheWheels) {
  Drive d(std::string(kBase) +
          "    cmd_vel_timeout: 100\n    base_frame_id: base_footprint\n    pose_covariance_diagonal: [1, 2, 3, 4, 5, 6]\n");
  d.send(0.4, 0.0);
  d.run(1000);
  d.send(0.0, 0.5);
  d.run(1000);
  const OdometrySnapshot o = d.c->odometry_port().read();
  // The ideal servos take the set points one tick late: 0.999 s of each command.
  EXPECT_NEAR(o.x, 0.4 * 0.999, 1e-3);
  EXPECT_NEAR(o.y, 0.0, 1e-9);
  EXPECT_NEAR(o.yaw, 0.5 * 0.999, 1e-3);
  EXPECT_NEAR(o.angular.z, 0.5, 1e-9);
  EXPECT_EQ(o.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_footprint");
  EXPECT_DOUBLE_EQ(o.pose_covariance[35], 6.0);
  EXPECT_FALSE(o.in_world);
}

TEST(DiffDriveController, OpenLoopOdometryIntegratesTheCommand) {
  Drive d(std::string(kBase) + "    open_loop: true\n    cmd_vel_timeout: 100\n");
  d.robot->joint("left").position = 100.0;  // wheels that say nothing useful
  d.send(0.4, 0.0);
  d.run(1000);
  EXPECT_NEAR(d.c->odometry_port().read().x, 0.4 * 0.999, 1e-3);
}

// A popular four-wheel skid-steer base's control.yaml, its wheel names aside: two wheels a side,
// multipliers, limits, and keys diff_drive_controller ignores.
TEST(DiffDriveController, HuskyStyleParameterSetLoads) {
  Drive d(R"(bot:
  dd:
    type: "diff_drive_controller/DiffDriveController"
    left_wheel: ['front_left_wheel', 'rear_left_wheel']
    right_wheel: ['front_right_wheel', 'rear_right_wheel']
    publish_rate: 50
    pose_covariance_diagonal: [0.001, 0.001, 1000000.0, 1000000.0, 1000000.0, 0.03]
    twist_covariance_diagonal: [0.001, 0.001, 0.001, 1000000.0, 1000000.0, 0.03]
    cmd_vel_timeout: 0.25
    k_l: 0.1
    k_r: 0.1
    enable_odom_tf: false
    estimate_velocity_from_position: false
    wheel_separation_multiplier: 1.875
    wheel_radius_multiplier    : 1.0
    wheel_separation: 0.555
    wheel_radius: 0.165
    linear:
      x:
        has_velocity_limits    : true
        max_velocity           : 1.0
        has_acceleration_limits: true
        max_acceleration       : 3.0
    angular:
      z:
        has_velocity_limits    : true
        max_velocity           : 2.0
        has_acceleration_limits: true
        max_acceleration       : 6.0
)",
          {"front_left_wheel", "rear_left_wheel", "front_right_wheel", "rear_right_wheel"});
  ASSERT_NE(d.c, nullptr);
  const DiffDriveConfig& c = d.c->config();
  EXPECT_EQ(c.left_wheels.size(), 2u);
  EXPECT_DOUBLE_EQ(c.separation(), 0.555 * 1.875);
  EXPECT_DOUBLE_EQ(c.cmd_vel_timeout, 0.25);
  EXPECT_FALSE(c.enable_odom_tf);
  EXPECT_DOUBLE_EQ(c.angular.max_acceleration, 6.0);
  EXPECT_DOUBLE_EQ(c.angular.min_velocity, -2.0);
  d.send(0.0, 2.0);
  d.run(200);
  d.send(0.0, 2.0);  // within cmd_vel_timeout (0.25 s); the 6 rad/s^2 ramp takes 0.33 s
  d.run(200);
  EXPECT_NEAR(d.wheel("rear_right_wheel"), 2.0 * 0.555 * 1.875 / 2.0 / 0.165, 1e-9);
}

TEST(DiffDriveController, ConfigurationErrorsNameTheParameter) {
  const auto error_of = [](const std::string& yaml, std::vector<std::string> joints = {"left", "right"}) {
    std::vector<testing::JointSpec> specs;
    for (const std::string& j : joints) specs.push_back({j, description::JointType::Continuous});
    auto robot = testing::make_robot(specs);
    ControllerManager m(robot->model, robot->state, Params::from_yaml_string(yaml).child("bot"), builtin_controller_registry());
    const ControlResult r = m.load_controller("dd");
    EXPECT_FALSE(r.ok);
    return r.error;
  };
  EXPECT_THAT(error_of("bot:\n  dd: {type: diff_drive_controller/DiffDriveController, right_wheel: right}\n"),
              HasSubstr("/bot/dd/left_wheel not found"));
  EXPECT_THAT(error_of("bot:\n  dd: {type: diff_drive_controller/DiffDriveController, left_wheel: left, right_wheel: left, "
                       "wheel_separation: 1, wheel_radius: 1}\n"),
              HasSubstr("'left' is in both /bot/dd/left_wheel and /bot/dd/right_wheel"));
  EXPECT_THAT(error_of("bot:\n  dd: {type: diff_drive_controller/DiffDriveController, left_wheel: left, right_wheel: right}\n"),
              HasSubstr("/bot/dd/wheel_separation not found"));
  EXPECT_THAT(error_of(std::string(kBase) + "    pose_covariance_diagonal: [1, 2]\n"), HasSubstr("must list 6 values"));
  EXPECT_THAT(error_of(std::string(kBase) + "    wheel_radius_multiplier: 0\n"), HasSubstr("/bot/dd/wheel_radius_multiplier must be"));
  EXPECT_THAT(error_of(std::string(kBase), {"left", "other"}), HasSubstr("unknown joint 'right'"));
}

}  // namespace
}  // namespace mechsim::control
