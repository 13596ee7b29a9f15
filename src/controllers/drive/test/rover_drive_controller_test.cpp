// The rover drive controller on the ten joints of the test rover (rover_drive_test_util.hpp)
// with a kinematic plant: after each update the steering joints go exactly to their set
// points and the wheels turn exactly at theirs, so what is checked is the controller's logic
// (limits, waiting, timeouts, signs, odometry), not PID tuning.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/drive/rover_drive_controller.hpp"
#include "controllers/drive/test/rover_drive_test_util.hpp"
#include "controllers/test/allocation_counter.hpp"

namespace mechsim::control {

namespace {

using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;
constexpr double kDt = 0.001;

struct KinematicRover {
  std::unique_ptr<testing::TestRobot> robot = testing::make_rover_robot();
  RoverDriveController controller;
  double time = 0.0;

  explicit KinematicRover(const std::string& extra = "", double offset = 0.0,
                          const std::array<double, 4>& steering_positions = {}) {
    for (std::size_t s = 0; s < 4; ++s) robot->state.joints[s].position = steering_positions[s];
    const Params params = Params::from_yaml_string(testing::test_rover_yaml(extra, offset)).child("rover");
    RobotHardware hardware(robot->model, robot->state);
    std::string error;
    EXPECT_TRUE(controller.init(hardware, params, error)) << error;
    controller.starting(time);
  }
  mechanism::JointState& joint(std::size_t i) { return robot->state.joints[i]; }
  JointGroupControllerState state() { return controller.state_port().read(); }
  RoverDriveStatus status() { return controller.status_port().read(); }
  OdometrySnapshot odom() { return controller.odometry_port().read(); }
  // Writes a command; tick() repeats it every 0.1 s, as a 10 Hz publisher would, unless
  // `republish` is off.
  void command(double vx, double vy, double wz) {
    last.linear.x = vx;
    last.linear.y = vy;
    last.angular.z = wz;
    ASSERT_TRUE(controller.command_port().write(last));
  }
  Twist last;
  bool republish = true;
  int count = 0;
  // One controller update, then the ideal plant.
  void tick() {
    if (republish && ++count % 100 == 0) {
      ASSERT_TRUE(controller.command_port().write(last));
    }
    ASSERT_TRUE(controller.update(time, kDt).ok);
    const JointGroupControllerState s = state();
    for (std::size_t j = 0; j < 10; ++j) {
      mechanism::JointState& js = joint(j);
      if (j < 4) {
        js.velocity = (s.joints[j].set_point - js.position) / kDt;
        js.position = s.joints[j].set_point;
      } else {
        js.velocity = s.joints[j].set_point;
        js.position += js.velocity * kDt;
      }
    }
    time += kDt;
  }
  void ticks(int n) {
    for (int i = 0; i < n; ++i) tick();
  }
  double wheel_setpoint(std::size_t wheel) { return state().joints[4 + wheel].set_point; }
  double steering_setpoint(std::size_t s) { return state().joints[s].set_point; }
};

TEST(RoverDriveController, StraightAheadTurnsEachWheelByItsAxisSign) {
  KinematicRover rover;
  rover.command(0.2, 0.0, 0.0);
  rover.ticks(5);
  // 0.2 m/s / 0.1 m = 2 rad/s, signed: FL +y, FR -y, ML -y, MR -y, RL +y, RR -y.
  const std::array<double, 6> expected{2.0, -2.0, -2.0, -2.0, 2.0, -2.0};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(rover.wheel_setpoint(i), expected[i], 1e-12) << i;
  for (std::size_t s = 0; s < 4; ++s) EXPECT_NEAR(rover.steering_setpoint(s), 0.0, 1e-12);
  const RoverDriveStatus st = rover.status();
  EXPECT_EQ(st.active_mode, DriveMode::Ackermann);
  EXPECT_DOUBLE_EQ(st.alignment_scale, 1.0);
}

TEST(RoverDriveController, SteeringJointsTurnOppositeToTheHeadingOnADownwardAxis) {
  KinematicRover rover;
  rover.command(0.5, 0.0, 0.25);  // left turn, R = 2 m
  rover.ticks(1000);
  // The FL wheel heads atan(0.5 / 1.6) to the left; the axis is -z, so the joint angle is minus that.
  EXPECT_NEAR(rover.steering_setpoint(0), -std::atan(0.5 / 1.6), 1e-9);
  EXPECT_NEAR(rover.steering_setpoint(3), std::atan(0.5 / 2.4), 1e-9);  // RR
}

TEST(RoverDriveController, SteeringRateLimitHoldsEveryTick) {
  KinematicRover rover("max_steering_rate: 1.0");
  rover.command(0.0, 0.0, 0.5);  // point turn: every corner turns by atan(0.5 / 0.4) = 0.896 rad
  std::array<double, 4> previous{};
  int ticks_to_reach = -1;
  for (int k = 0; k < 1500; ++k) {
    rover.tick();
    for (std::size_t s = 0; s < 4; ++s) {
      const double now = rover.steering_setpoint(s);
      EXPECT_LE(std::abs(now - previous[s]), 1.0 * kDt + 1e-12) << "tick " << k << " steering " << s;
      previous[s] = now;
    }
    if (ticks_to_reach < 0 && std::abs(previous[0] - std::atan(0.5 / 0.4)) < 1e-9) ticks_to_reach = k + 1;
  }
  EXPECT_NEAR(ticks_to_reach, std::atan(0.5 / 0.4) / (1.0 * kDt), 1.5);
}

TEST(RoverDriveController, WheelsWaitForTheSteering) {
  KinematicRover rover("max_steering_rate: 1.0\nsteering_tolerance: 0.05\nsteering_stop_error: 0.35");
  rover.command(0.0, 0.0, 0.5);
  const double target = std::atan(0.5 / 0.4);
  const double full = 0.5 * std::hypot(0.5, 0.4) / 0.1;  // rad/s of a corner wheel
  bool saw_partial = false;
  for (int k = 0; k < 1200; ++k) {
    rover.tick();
    const RoverDriveStatus st = rover.status();
    const double fl = std::abs(rover.wheel_setpoint(0));
    const double error = st.max_steering_error;
    if (error >= 0.35) {
      EXPECT_EQ(fl, 0.0) << "tick " << k;
    } else if (error <= 0.05) {
      EXPECT_NEAR(fl, full, 1e-9) << "tick " << k;
    } else {
      EXPECT_NEAR(fl, full * (0.35 - error) / 0.3, 1e-9) << "tick " << k;
      saw_partial = true;
    }
  }
  EXPECT_TRUE(saw_partial);
  EXPECT_NEAR(std::abs(rover.joint(0).position), target, 1e-9);
  EXPECT_NEAR(std::abs(rover.wheel_setpoint(0)), full, 1e-9);
}

TEST(RoverDriveController, ShorterWayRollsBackwardsInsteadOfTurningPast90Degrees) {
  // Heading 0 now; drive backwards and a little left: atan2(0.1, -0.5) = 169 deg is out of
  // range, so the wheels point at -11 deg and roll backwards.
  KinematicRover rover;
  rover.command(-0.5, 0.1, 0.0);
  rover.ticks(500);
  const double heading = std::atan2(0.1, -0.5) + kPi;  // -11 deg ... normalised below
  const double expected = std::remainder(heading, 2 * kPi);
  EXPECT_NEAR(rover.steering_setpoint(0), -expected, 1e-9);  // joint = -heading
  EXPECT_NEAR(rover.wheel_setpoint(0), -std::hypot(0.5, 0.1) / 0.1, 1e-9);  // FL axis +y, backwards
  EXPECT_EQ(rover.status().active_mode, DriveMode::Crab);
}

TEST(RoverDriveController, CommandTimeoutBrakes) {
  KinematicRover rover("cmd_vel_timeout: 0.2");
  rover.republish = false;
  rover.command(0.3, 0.0, 0.0);
  rover.ticks(150);
  EXPECT_NEAR(rover.wheel_setpoint(0), 3.0, 1e-12);
  EXPECT_FALSE(rover.status().timed_out);
  rover.ticks(100);  // 0.25 s after the command
  EXPECT_TRUE(rover.status().timed_out);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(rover.wheel_setpoint(i), 0.0);
  rover.command(0.3, 0.0, 0.0);  // the same command again counts as fresh
  rover.ticks(2);
  EXPECT_FALSE(rover.status().timed_out);
  EXPECT_NEAR(rover.wheel_setpoint(0), 3.0, 1e-12);
}

TEST(RoverDriveController, NonFiniteCommandsAreRejectedAndCounted) {
  KinematicRover rover;
  rover.command(0.3, 0.0, 0.0);
  rover.ticks(10);
  Twist bad;
  bad.linear.x = std::numeric_limits<double>::quiet_NaN();
  std::string error;
  EXPECT_FALSE(rover.controller.command_port().write(bad, &error));
  EXPECT_THAT(error, HasSubstr("non-finite"));
  bad.linear.x = 0.0;
  bad.angular.z = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(rover.controller.command_port().write(bad));
  EXPECT_EQ(rover.controller.command_port().count(), 2u);
  rover.ticks(10);
  EXPECT_NEAR(rover.wheel_setpoint(0), 3.0, 1e-12);  // the previous command stays
  for (std::size_t j = 0; j < 10; ++j) EXPECT_TRUE(std::isfinite(rover.state().joints[j].command));
}

TEST(RoverDriveController, NonFiniteMeasurementsStopTheWheelsAndSpareTheOdometry) {
  KinematicRover rover;
  rover.command(0.3, 0.0, 0.0);
  rover.ticks(100);
  const OdometrySnapshot before = rover.odom();
  rover.joint(1).position = std::numeric_limits<double>::quiet_NaN();  // steering_FR
  rover.joint(6).velocity = std::numeric_limits<double>::infinity();   // wheel_joint_ML
  ASSERT_TRUE(rover.controller.update(rover.time, kDt).ok);
  const JointGroupControllerState s = rover.state();
  for (std::size_t i = 4; i < 10; ++i) EXPECT_EQ(s.joints[i].set_point, 0.0) << s.joint_names[i];
  for (std::size_t j = 0; j < 10; ++j) EXPECT_TRUE(std::isfinite(s.joints[j].command)) << s.joint_names[j];
  const OdometrySnapshot after = rover.odom();
  EXPECT_TRUE(std::isfinite(after.x));
  EXPECT_NEAR(after.x, before.x, 1e-3);
  EXPECT_EQ(rover.status().alignment_scale, 0.0);
}

TEST(RoverDriveController, ModePortForcesAMode) {
  KinematicRover rover;
  ASSERT_TRUE(rover.controller.mode_port().write("crab"));
  rover.command(0.3, 0.0, 0.2);  // the crab cannot rotate: wz dropped
  rover.ticks(20);
  RoverDriveStatus st = rover.status();
  EXPECT_EQ(st.requested_mode, DriveMode::Crab);
  EXPECT_EQ(st.active_mode, DriveMode::Crab);
  EXPECT_TRUE(st.unsupported);
  EXPECT_EQ(st.unsupported_count, 20u);
  EXPECT_EQ(st.applied.wz, 0.0);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(std::abs(rover.wheel_setpoint(i)), 3.0, 1e-12);
  std::string error;
  EXPECT_FALSE(rover.controller.mode_port().write("skid", &error));
  EXPECT_THAT(error, HasSubstr("skid"));
  EXPECT_EQ(rover.controller.mode_port().count(), 1u);
  EXPECT_FALSE(rover.controller.mode_port().write(static_cast<DriveMode>(9)));
  EXPECT_EQ(rover.controller.mode_port().latest(), DriveMode::Crab);
  ASSERT_TRUE(rover.controller.mode_port().write(DriveMode::Auto));
  rover.ticks(1);
  EXPECT_EQ(rover.status().active_mode, DriveMode::Ackermann);
}

TEST(RoverDriveController, AccelerationAndVelocityLimits) {
  KinematicRover rover("max_linear_acceleration: 1.0\nmax_angular_acceleration: 2.0\nmax_linear_velocity: 0.4");
  rover.command(0.5, 0.0, 0.0);
  rover.ticks(100);
  EXPECT_NEAR(rover.status().applied.vx, 0.1, 1e-9);  // 1 m/s^2 for 0.1 s
  rover.ticks(500);
  EXPECT_NEAR(rover.status().applied.vx, 0.4, 1e-12);  // capped
  rover.command(0.0, 0.0, 0.0);
  rover.ticks(100);
  EXPECT_NEAR(rover.status().applied.vx, 0.3, 1e-9);  // braking is limited too
}

TEST(RoverDriveController, MaxWheelSpeedScalesAllWheelsTogether) {
  KinematicRover rover("max_wheel_speed: 2.0");
  rover.command(0.5, 0.0, 0.25);
  rover.ticks(1500);
  double fastest = 0.0;
  for (std::size_t i = 0; i < 6; ++i) fastest = std::fmax(fastest, std::abs(rover.wheel_setpoint(i)));
  EXPECT_NEAR(fastest, 2.0, 1e-9);
  // The ratio between wheels (the turn's geometry) is kept: ML / MR = (R - 0.45) / (R + 0.45).
  EXPECT_NEAR(rover.wheel_setpoint(2) / rover.wheel_setpoint(3), 1.55 / 2.45, 1e-9);
  EXPECT_LT(rover.status().wheel_speed_scale, 1.0);
}

TEST(RoverDriveController, OdometryFollowsAStraightLine) {
  KinematicRover rover;
  rover.command(0.2, 0.0, 0.0);
  rover.ticks(2000);
  const OdometrySnapshot o = rover.odom();
  EXPECT_TRUE(o.valid);
  // The plant turns the wheels after each update, so odometry lags one tick.
  EXPECT_NEAR(o.x, 0.2 * 1999 * kDt, 1e-9);
  EXPECT_NEAR(o.y, 0.0, 1e-12);
  EXPECT_NEAR(o.yaw, 0.0, 1e-12);
  EXPECT_NEAR(o.linear.x, 0.2, 1e-12);
  EXPECT_NEAR(o.residual, 0.0, 1e-12);
  EXPECT_EQ(o.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_link");
}

TEST(RoverDriveController, OdometryFollowsACircle) {
  // Steering offsets of 0.059 m (the CC8's) and the steering already at the turn's angles, so
  // that the rover is on its circle from the first tick: R = 2 m about (0, 2).
  const RoverKinematics k = testing::make_test_rover(0.059);
  std::array<double, 4> headings{};
  std::array<double, 6> speeds{};
  const std::array<double, 4> zero{};
  inverse_kinematics(k, {0.5, 0.0, 0.25}, zero, zero, headings, speeds);
  std::array<double, 4> joints{};
  for (std::size_t s = 0; s < 4; ++s) joints[s] = -headings[s];
  KinematicRover rover("pose_covariance_diagonal: [0.01, 0.01, 1.0e6, 1.0e6, 1.0e6, 0.03]", 0.059, joints);
  rover.command(0.5, 0.0, 0.25);
  const int quarter = static_cast<int>(std::lround(kPi / 2 / 0.25 / kDt));
  double worst_radius_error = 0.0;
  for (int i = 0; i <= quarter; ++i) {
    rover.tick();
    const OdometrySnapshot o = rover.odom();
    worst_radius_error = std::fmax(worst_radius_error, std::abs(std::hypot(o.x, o.y - 2.0) - 2.0));
  }
  EXPECT_LT(worst_radius_error, 1e-9);
  const OdometrySnapshot o = rover.odom();
  // `quarter` ticks of motion (the first tick saw the wheels still): close to a quarter turn.
  const double angle = 0.25 * quarter * kDt;
  EXPECT_NEAR(angle, kPi / 2, 1e-3);
  EXPECT_NEAR(o.x, 2.0 * std::sin(angle), 1e-9);
  EXPECT_NEAR(o.y, 2.0 * (1.0 - std::cos(angle)), 1e-9);
  EXPECT_NEAR(o.yaw, angle, 1e-9);
  EXPECT_NEAR(o.angular.z, 0.25, 1e-12);
  EXPECT_NEAR(o.linear.x, 0.5, 1e-12);
  EXPECT_NEAR(o.orientation().z, std::sin(angle / 2), 1e-9);
  EXPECT_DOUBLE_EQ(o.pose_covariance[0], 0.01);
  EXPECT_DOUBLE_EQ(o.pose_covariance[35], 0.03);
  EXPECT_DOUBLE_EQ(o.pose_covariance[1], 0.0);
  rover.controller.reset_odometry();
  rover.ticks(1);
  EXPECT_LT(std::hypot(rover.odom().x, rover.odom().y), 0.001);
}

TEST(RoverDriveController, StateReportsSetPointsAndErrors) {
  KinematicRover rover;
  rover.command(0.2, 0.0, 0.0);
  rover.ticks(3);
  const JointGroupControllerState s = rover.state();
  ASSERT_EQ(s.joint_names.size(), 10u);
  EXPECT_EQ(s.joint_names[0], "steering_FL");
  EXPECT_EQ(s.joint_names[4], "wheel_joint_FL");
  EXPECT_DOUBLE_EQ(s.joints[4].gains.p, 10.0);
  EXPECT_DOUBLE_EQ(s.joints[0].gains.p, 50.0);
  EXPECT_NEAR(s.joints[4].error, s.joints[4].set_point - s.joints[4].process_value, 1e-12);
  EXPECT_DOUBLE_EQ(s.stamp, 2 * kDt);
}

// ---------------------------------------------------------------- through the manager

struct ManagedRover {
  std::unique_ptr<testing::TestRobot> robot = testing::make_rover_robot();
  std::unique_ptr<ControllerManager> manager;
  explicit ManagedRover(const std::string& yaml) {
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml),
                                                  builtin_controller_registry());
  }
};

TEST(RoverDriveController, LoadsFromYamlAndClaimsItsTenJoints) {
  ManagedRover rig(testing::test_rover_yaml());
  const ControlResult r = rig.manager->load_controller("rover");
  ASSERT_TRUE(r.ok) << r.error;
  const auto info = rig.manager->controller_info("rover");
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->type, "mechsim/RoverDriveController");
  ASSERT_EQ(info->claims.size(), 1u);
  EXPECT_EQ(info->claims[0].interface, HardwareInterface::Effort);
  EXPECT_EQ(info->claims[0].joints.size(), 10u);
  auto* c = dynamic_cast<RoverDriveController*>(rig.manager->controller("rover"));
  ASSERT_NE(c, nullptr);
  EXPECT_NE(c->port_as<TwistCommandPort>("cmd_vel"), nullptr);
  EXPECT_NE(c->port_as<DriveModeCommandPort>("mode"), nullptr);
  EXPECT_NE(c->port_as<StatePort<OdometrySnapshot>>("odom"), nullptr);
  EXPECT_NE(c->port_as<StatePort<JointGroupControllerState>>("state"), nullptr);
  EXPECT_NE(c->port_as<StatePort<RoverDriveStatus>>("drive_status"), nullptr);
  EXPECT_NE(c->port_as<PidGainsPort>("gains/wheel_joint_MR"), nullptr);
  // The URDF velocity limits are the defaults of the rate limits.
  EXPECT_DOUBLE_EQ(c->config().max_steering_rate, 3.0);
  EXPECT_DOUBLE_EQ(c->config().max_wheel_speed, 20.0);
  // And it runs through the manager's tick.
  ASSERT_TRUE(rig.manager->switch_controllers({"rover"}, {}, SwitchStrictness::Strict).ok);
  double time = testing::run(*rig.manager, *rig.robot, 0.0, 1);  // starting() zeroes the command
  ASSERT_TRUE(c->command_port().write(Twist{{0.1, 0.0, 0.0}, {}}));
  testing::run(*rig.manager, *rig.robot, time, 200);
  EXPECT_EQ(rig.manager->controller_info("rover")->state, ControllerLifecycle::Running);
  EXPECT_NEAR(c->state_port().read().joints[4].set_point, 1.0, 1e-12);
}

TEST(RoverDriveController, UpdateAllocatesNothing) {
  ManagedRover rig(testing::test_rover_yaml("max_linear_acceleration: 2.0\nmax_angular_acceleration: 2.0"));
  ASSERT_TRUE(rig.manager->load_controller("rover").ok);
  ASSERT_TRUE(rig.manager->switch_controllers({"rover"}, {}, SwitchStrictness::Strict).ok);
  auto* c = dynamic_cast<RoverDriveController*>(rig.manager->controller("rover"));
  ASSERT_NE(c, nullptr);
  double time = testing::run(*rig.manager, *rig.robot, 0.0, 1);
  long allocations = 0;
  for (const Twist& t : {Twist{{0.3, 0.0, 0.0}, {0.0, 0.0, 0.2}}, Twist{{0.2, 0.2, 0.0}, {}},
                         Twist{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}}, Twist{{0.1, 0.3, 0.0}, {0.0, 0.0, 0.4}}}) {
    ASSERT_TRUE(c->command_port().write(t));
    ASSERT_TRUE(c->mode_port().write(DriveMode::Auto));
    testing::start_counting_allocations();
    time = testing::run(*rig.manager, *rig.robot, time, 300);
    allocations += testing::stop_counting_allocations();
  }
  c->reset_odometry();
  testing::start_counting_allocations();
  time = testing::run(*rig.manager, *rig.robot, time, 700);  // through the command timeout
  allocations += testing::stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  EXPECT_TRUE(c->status_port().read().timed_out);
  EXPECT_EQ(rig.manager->controller_info("rover")->state, ControllerLifecycle::Running);
}

TEST(RoverDriveController, RevoluteSteeringLimitsNarrowTheHeadingRange) {
  std::vector<testing::JointSpec> joints;
  for (const char* s : {"steering_FL", "steering_FR", "steering_RL", "steering_RR"}) {
    joints.push_back({s, description::JointType::Revolute, description::JointLimits{-0.6, 0.5, 100.0, 3.0}});
  }
  for (const char* w : {"wheel_joint_FL", "wheel_joint_FR", "wheel_joint_ML", "wheel_joint_MR", "wheel_joint_RL",
                        "wheel_joint_RR"}) {
    joints.push_back({w, description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 20.0}});
  }
  auto robot = testing::make_robot(joints);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(testing::test_rover_yaml()),
                            builtin_controller_registry());
  ASSERT_TRUE(manager.load_controller("rover").ok);
  auto* c = dynamic_cast<RoverDriveController*>(manager.controller("rover"));
  EXPECT_DOUBLE_EQ(c->config().kinematics.max_steering_angle, 0.5);
  ASSERT_TRUE(manager.switch_controllers({"rover"}, {}, SwitchStrictness::Strict).ok);
  double time = testing::run(manager, *robot, 0.0, 1);
  ASSERT_TRUE(c->command_port().write(Twist{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}}));  // wants 0.9 rad
  testing::run(manager, *robot, time, 300);
  for (std::size_t s = 0; s < 4; ++s) EXPECT_NEAR(std::abs(c->state_port().read().joints[s].set_point), 0.5, 1e-12);
}

TEST(RoverDriveController, UnknownJointNamesTheParameter) {
  std::string yaml = testing::test_rover_yaml();
  yaml.replace(yaml.find("wheel_joint_ML, "), 16, "wheel_joint_XL, ");
  ManagedRover rig(yaml);
  const ControlResult r = rig.manager->load_controller("rover");
  ASSERT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("wheel_joint_XL"));
  EXPECT_THAT(r.error, HasSubstr("/rover/wheel_joints[2]"));
}

TEST(RoverDriveController, MissingGeometryNamesTheParameter) {
  std::string yaml = testing::test_rover_yaml();
  const auto from = yaml.find("    wheel_axis_signs:");
  const auto to = yaml.find("    wheel_steering:");
  yaml.erase(from, to - from);
  ManagedRover rig(yaml);
  const ControlResult r = rig.manager->load_controller("rover");
  ASSERT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("/rover/wheel_axis_signs"));
}

TEST(RoverDriveController, BadGeometryValuesNameTheParameter) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"wheel_radius: -0.1", "/rover/wheel_radius"},
      {"steering_stop_error: 0.01", "/rover/steering_stop_error"},
      {"pose_covariance_diagonal: [1, 2]", "/rover/pose_covariance_diagonal"},
  };
  for (const auto& [extra, path] : cases) {
    std::string yaml = testing::test_rover_yaml(extra);
    if (extra.rfind("wheel_radius", 0) == 0) yaml.erase(yaml.find("    wheel_radius: 0.1\n"), 22);
    ManagedRover rig(yaml);
    const ControlResult r = rig.manager->load_controller("rover");
    ASSERT_FALSE(r.ok) << extra;
    EXPECT_THAT(r.error, HasSubstr(path)) << extra;
  }
  std::string yaml = testing::test_rover_yaml();
  yaml.replace(yaml.find("wheel_joint_MR: -1"), 18, "wheel_joint_MR: 2.");
  ManagedRover rig(yaml);
  const ControlResult r = rig.manager->load_controller("rover");
  ASSERT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("/rover/wheel_axis_signs/wheel_joint_MR"));
}

}  // namespace
}  // namespace mechsim::control
