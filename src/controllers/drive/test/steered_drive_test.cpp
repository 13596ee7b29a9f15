// controllers/drive/steered_drive.hpp: the joints, PIDs, PID loop and snapshots shared by the rover drive
// and the PR2 base controllers, the twist command timeout and the odometry snapshot.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/angles.hpp"
#include "controllers/drive/steered_drive.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control {
namespace {

using testing::JointSpec;

std::unique_ptr<testing::TestRobot> two_by_two() {
  std::vector<JointSpec> joints;
  for (const char* name : {"s0", "s1", "w0", "w1"}) {
    joints.push_back({name, description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 10.0}});
  }
  return testing::make_robot(joints);
}

constexpr const char* kParams = R"(
drive:
  steer: [s0, s1]
  wheels: [w0, w1]
  steer_pid: {p: 10.0}
  wheel_pid: {p: 2.0}
  w1: {p: 5.0}
)";

// Two steering joints s0, s1 and two wheels w0, w1 on the test robot, claimed and given PIDs from kParams.
struct Rig {
  explicit Rig(SteeredDrive::Gains gains) {
    drive.claim(hardware, params, "steer", 1, "wheels", 1);
    drive.init_pids(params, "steer_pid", "wheel_pid", gains);
  }
  std::unique_ptr<testing::TestRobot> robot = two_by_two();
  RobotHardware hardware{robot->model, robot->state};
  Params params = Params::from_yaml_string(kParams).child("drive");
  SteeredDrive drive;
};

TEST(SteeredDrive, ClosesPositionPidsOnSteeringAndVelocityPidsOnWheels) {
  Rig rig(SteeredDrive::Gains::Shared);
  auto& robot = rig.robot;
  SteeredDrive& drive = rig.drive;
  ASSERT_EQ(drive.steering_count(), 2u);
  ASSERT_EQ(drive.wheel_count(), 2u);

  // s0 at 3.0 rad, set point -3.0: the shortest way is +0.283 rad across pi, not -6 rad.
  robot->joint("s0").position = 3.0;
  robot->joint("s1").position = 0.5;
  robot->joint("w0").velocity = 1.0;
  robot->joint("w1").velocity = -1.0;
  drive.steering_setpoints()[0] = -3.0;
  drive.steering_setpoints()[1] = 0.25;
  drive.wheel_setpoints()[0] = 2.0;
  drive.wheel_setpoints()[1] = 0.5;
  drive.update(0.001);

  const double across_pi = 2.0 * std::numbers::pi - 6.0;
  EXPECT_NEAR(robot->joint("s0").commanded_effort, 10.0 * across_pi, 1e-9);
  EXPECT_NEAR(robot->joint("s1").commanded_effort, 10.0 * -0.25, 1e-12);
  EXPECT_NEAR(robot->joint("w0").commanded_effort, 2.0 * 1.0, 1e-12);
  EXPECT_NEAR(robot->joint("w1").commanded_effort, 2.0 * 1.5, 1e-12);  // Shared: w1's own gains ignored
  ASSERT_EQ(drive.efforts().size(), 4u);
  EXPECT_EQ(drive.efforts()[3], robot->joint("w1").commanded_effort);

  drive.publish_state(2.5, 0.001);
  const JointGroupControllerState s = drive.state_port().read();
  EXPECT_THAT(s.joint_names, ::testing::ElementsAre("s0", "s1", "w0", "w1"));
  EXPECT_EQ(s.stamp, 2.5);
  EXPECT_EQ(s.joints[0].set_point, -3.0);
  EXPECT_EQ(s.joints[0].process_value, 3.0);
  EXPECT_NEAR(s.joints[0].error, across_pi, 1e-12);
  EXPECT_EQ(s.joints[0].gains.p, 10.0);
  EXPECT_EQ(s.joints[3].set_point, 0.5);
  EXPECT_EQ(s.joints[3].process_value, -1.0);
  EXPECT_EQ(s.joints[3].process_value_dot, 0.0);
  EXPECT_EQ(s.joints[3].error, 1.5);
  EXPECT_EQ(s.joints[3].command, drive.efforts()[3]);
  EXPECT_EQ(s.joints[3].time_step, 0.001);

  std::vector<Port*> ports;
  drive.append_gains_ports(ports);
  ASSERT_EQ(ports.size(), 4u);
  EXPECT_EQ(ports[1]->name(), "gains/s1");
  EXPECT_EQ(ports[3]->name(), "gains/w1");
}

TEST(SteeredDrive, JointGainsOverrideTheSharedOnesAndUnpoweredWheelsGetNoEffort) {
  Rig rig(SteeredDrive::Gains::JointOrShared);
  auto& robot = rig.robot;
  SteeredDrive& drive = rig.drive;
  robot->joint("w0").velocity = 0.0;
  robot->joint("w1").velocity = 0.0;
  drive.wheel_setpoints()[0] = 1.0;
  drive.wheel_setpoints()[1] = 1.0;
  drive.update(0.001);
  EXPECT_NEAR(robot->joint("w0").commanded_effort, 2.0, 1e-12);
  EXPECT_NEAR(robot->joint("w1").commanded_effort, 5.0, 1e-12);  // its own `w1` namespace

  const std::vector<std::uint8_t> unpowered{0, 1};
  drive.update(0.001, unpowered);
  EXPECT_NEAR(robot->joint("w0").commanded_effort, 2.0, 1e-12);
  EXPECT_EQ(robot->joint("w1").commanded_effort, 0.0);
  EXPECT_EQ(drive.efforts()[3], 0.0);
}

TEST(SteeredDrive, ClaimErrorsNameTheParameterPath) {
  auto robot = two_by_two();
  RobotHardware hardware(robot->model, robot->state);
  const Params params = Params::from_yaml_string(R"(
drive:
  steer: [s0, nope]
  wheels: [w0]
)").child("drive");
  SteeredDrive drive;
  try {
    drive.claim(hardware, params, "steer", 1, "wheels", 1);
    FAIL() << "an unknown joint was claimed";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("drive/steer[1]"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("nope"));
  }
  SteeredDrive too_few;
  EXPECT_THROW(too_few.claim(hardware, params, "steer", 1, "wheels", 2), ControllerConfigError);
}

TEST(TwistCommandTimeout, ZeroesTheTargetOnceNoCommandArrivedForTheTimeout) {
  TwistCommandPort port("cmd_vel");
  TwistCommandTimeout timeout;
  timeout.start(port, 1.0);
  Twist t;
  t.linear.x = 0.3;
  t.linear.y = -0.1;
  t.linear.z = 9.0;  // ignored
  t.angular.z = 0.5;
  ASSERT_TRUE(port.write(t));
  PlanarTwist p = timeout.read(port, 1.1, 0.5);
  EXPECT_EQ(p.vx, 0.3);
  EXPECT_EQ(p.vy, -0.1);
  EXPECT_EQ(p.wz, 0.5);
  EXPECT_FALSE(timeout.timed_out());
  EXPECT_EQ(timeout.value().linear.z, 9.0);
  p = timeout.read(port, 1.6, 0.5);  // 0.5 s since the command: not yet
  EXPECT_EQ(p.vx, 0.3);
  p = timeout.read(port, 1.61, 0.5);
  EXPECT_TRUE(timeout.timed_out());
  EXPECT_EQ(p.vx, 0.0);
  EXPECT_EQ(p.wz, 0.0);
  ASSERT_TRUE(port.write(t));  // the same twist again counts as a new command
  p = timeout.read(port, 1.7, 0.5);
  EXPECT_FALSE(timeout.timed_out());
  EXPECT_EQ(p.vx, 0.3);
  p = timeout.read(port, 100.0, 0.0);  // <= 0: never times out
  EXPECT_FALSE(timeout.timed_out());

  timeout.start(port, 200.0);  // starting() zeroes the command
  p = timeout.read(port, 200.1, 0.5);
  EXPECT_EQ(p.vx, 0.0);
  EXPECT_FALSE(timeout.timed_out());
}

TEST(PlanarOdometry, IntegratesThePoseAndPublishesTheSnapshot) {
  StatePort<OdometrySnapshot> port("odom");
  const std::array<double, 6> pose_cov{1, 2, 3, 4, 5, 6}, twist_cov{7, 8, 9, 10, 11, 12};
  port.init(odometry_prototype("world", "base", pose_cov, twist_cov, PlanarPose{1.0, 2.0, 0.5}));
  OdometrySnapshot o = port.read();
  EXPECT_EQ(o.frame_id, "world");
  EXPECT_EQ(o.child_frame_id, "base");
  EXPECT_EQ(o.pose_covariance[0], 1.0);
  EXPECT_EQ(o.pose_covariance[35], 6.0);
  EXPECT_EQ(o.pose_covariance[1], 0.0);
  EXPECT_EQ(o.twist_covariance[7], 8.0);
  EXPECT_EQ(o.x, 1.0);
  EXPECT_EQ(o.yaw, 0.5);
  EXPECT_FALSE(o.valid);

  PlanarOdometry odom;
  odom.advance(PlanarTwist{1.0, 0.0, 0.0}, 2.0);
  odom.advance(PlanarTwist{0.0, 0.0, std::numbers::pi / 2}, 1.0);  // a quarter turn in place
  odom.residual = 0.25;
  odom.publish(port, 3.0);
  o = port.read();
  EXPECT_EQ(o.stamp, 3.0);
  EXPECT_NEAR(o.x, 2.0, 1e-12);
  EXPECT_NEAR(o.y, 0.0, 1e-12);
  EXPECT_NEAR(o.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(o.angular.z, std::numbers::pi / 2);
  EXPECT_EQ(o.linear.x, 0.0);
  EXPECT_EQ(o.residual, 0.25);
  EXPECT_TRUE(o.valid);
  EXPECT_EQ(o.frame_id, "world");  // the prototype's frames stay
}

}  // namespace
}  // namespace mechsim::control
