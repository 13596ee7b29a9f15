// The rover drive in crab: which wheels it leaves unpowered to sense the ground, the odometry
// that trusts them, and the heading hold. The plant slips: steering goes to its set points,
// powered wheels turn at their set points, but the ground moves the body at `ground_scale`
// times the twist those wheels command, turned by `yaw_disturbance` (rad/s) on top, and the
// unpowered wheels roll with the ground. That is what the CC8 does in crab (its middle wheels
// dragged sideways), reduced to the two numbers that matter.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "control/angles.hpp"
#include "controllers/drive/rover_drive_controller.hpp"
#include "controllers/drive/rover_drive_odometry.hpp"
#include "controllers/drive/test/rover_drive_test_util.hpp"
#include "controllers/test/allocation_counter.hpp"

namespace mechsim::control {

namespace {

using ::testing::HasSubstr;
constexpr double kDt = 0.001;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::uint32_t bit(int i) { return std::uint32_t{1} << i; }

struct SlipRover {
  std::unique_ptr<testing::TestRobot> robot = testing::make_rover_robot();
  RoverDriveController controller;
  double time = 0.0;
  double ground_scale = 1.0;
  double yaw_disturbance = 0.0;  // rad/s
  PlanarPose truth;              // the body's true pose, from the start
  double truth_distance = 0.0;   // m
  bool count_allocations = false;
  long allocations = 0;

  // An IMU on the body ("body_imu", 100 Hz: a new sample every 10 ticks) reading the true yaw.
  std::unique_ptr<SensorHardware> sensors;

  explicit SlipRover(const std::string& extra, bool with_imu = false) {
    if (with_imu) {
      ImuSensorData imu;
      imu.name = "body_imu";
      imu.frame_id = "imu_link";
      sensors = std::make_unique<SensorHardware>(std::vector<ImuSensorData>{imu}, std::vector<ForceTorqueSensorData>{});
    }
    const Params params = Params::from_yaml_string(testing::test_rover_yaml(extra)).child("rover");
    RobotHardware hardware(robot->model, robot->state);
    hardware.set_sensors(sensors.get());
    std::string error;
    EXPECT_TRUE(controller.init(hardware, params, error)) << error;
    controller.starting(time);
  }
  const RoverKinematics& k() const { return controller.config().kinematics; }
  void command(double vx, double vy, double wz) { ASSERT_TRUE(controller.command_port().write(Twist{{vx, vy, 0.0}, {0.0, 0.0, wz}})); }
  RoverDriveStatus status() { return controller.status_port().read(); }
  OdometrySnapshot odom() { return controller.odometry_port().read(); }
  JointGroupControllerState state() { return controller.state_port().read(); }

  void tick() {
    if (sensors && std::lround(time / kDt) % 10 == 0) {
      ImuSensorData& imu = sensors->imus()[0];
      imu.orientation = {0.0, 0.0, std::sin(truth.yaw / 2), std::cos(truth.yaw / 2)};
      imu.stamp = time;
      ++imu.count;
    }
    if (count_allocations) testing::start_counting_allocations();
    const bool ok = controller.update(time, kDt).ok;
    if (count_allocations) allocations += testing::stop_counting_allocations();
    ASSERT_TRUE(ok);
    const JointGroupControllerState s = state();
    const RoverDriveStatus st = status();
    std::array<double, 4> headings{};
    for (std::size_t j = 0; j < 4; ++j) {
      mechanism::JointState& js = robot->state.joints[j];
      js.velocity = (s.joints[j].set_point - js.position) / kDt;
      js.position = s.joints[j].set_point;
      headings[j] = normalize_angle(k().steering_axis_signs[j] * js.position);
    }
    // The twist the powered wheels ask for, then what the ground makes of it.
    std::array<double, 6> speeds{}, rolling{}, lateral{};
    for (std::size_t i = 0; i < 6; ++i) {
      speeds[i] = k().wheels[i].axis_sign * s.joints[4 + i].set_point * k().wheel_radius;
      rolling[i] = (st.sensing_wheels & bit(static_cast<int>(i))) != 0 ? 0.0 : 1.0;
      lateral[i] = k().wheels[i].steering >= 0 ? 1.0 : 0.0;
    }
    PlanarTwist asked;
    if (!estimate_twist_weighted(k(), headings, speeds, rolling, lateral, asked)) asked = {};
    const bool moving = std::hypot(asked.vx, asked.vy) > 1e-9 || std::abs(asked.wz) > 1e-9;
    const PlanarTwist ground{ground_scale * asked.vx, ground_scale * asked.vy, asked.wz + (moving ? yaw_disturbance : 0.0)};
    truth = integrate_pose(truth, ground, kDt);
    truth_distance += std::hypot(ground.vx, ground.vy) * kDt;
    for (std::size_t i = 0; i < 6; ++i) {
      mechanism::JointState& js = robot->state.joints[4 + i];
      if ((st.sensing_wheels & bit(static_cast<int>(i))) != 0) {
        const int steering = k().wheels[i].steering;
        const double heading = steering >= 0 ? headings[static_cast<std::size_t>(steering)] : 0.0;
        js.velocity = k().wheels[i].axis_sign * rolling_speed(k(), i, heading, ground) / k().wheel_radius;
      } else {
        js.velocity = s.joints[4 + i].set_point;
      }
      js.position += js.velocity * kDt;
    }
    time += kDt;
  }
  // Runs `seconds`, re-sending the command at 10 Hz as a publisher would.
  void run(double seconds, double vx, double vy, double wz) {
    const int n = static_cast<int>(std::lround(seconds / kDt));
    for (int i = 0; i < n; ++i) {
      if (i % 100 == 0) command(vx, vy, wz);
      tick();
    }
  }
  double odometry_error() {
    const OdometrySnapshot o = odom();
    return std::hypot(o.x - truth.x, o.y - truth.y);
  }
};

TEST(RoverDriveCrab, TrailingSideCornersSenseWhileCrabbingOnly) {
  SlipRover rover("crab_sensing_wheels: trailing_side");
  rover.ground_scale = 0.8;
  rover.run(1.0, 0.2, 0.2, 0.0);  // crab to the front left: the right side trails
  RoverDriveStatus st = rover.status();
  EXPECT_EQ(st.active_mode, DriveMode::Crab);
  EXPECT_TRUE(st.crab_sensing);
  EXPECT_EQ(st.sensing_wheels, bit(1) | bit(5));  // wheel_joint_FR, wheel_joint_RR
  // Unpowered although the ground turns them slower than their set points.
  const JointGroupControllerState s = rover.state();
  for (std::size_t i : {std::size_t{1}, std::size_t{5}}) {
    EXPECT_EQ(s.joints[4 + i].command, 0.0) << s.joint_names[4 + i];
    EXPECT_GT(std::abs(s.joints[4 + i].error), 0.1) << s.joint_names[4 + i];
  }
  rover.run(1.0, 0.2, -0.2, 0.0);  // to the front right: the left side trails
  EXPECT_EQ(rover.status().sensing_wheels, bit(0) | bit(4));
  rover.run(1.0, 0.3, 0.0, 0.1);  // Ackermann: every wheel drives
  st = rover.status();
  EXPECT_EQ(st.active_mode, DriveMode::Ackermann);
  EXPECT_FALSE(st.crab_sensing);
  EXPECT_EQ(st.sensing_wheels, 0u);
  rover.run(1.0, 0.0, 0.0, 0.0);  // stopped in crab steering: every wheel brakes
  EXPECT_EQ(rover.status().sensing_wheels, 0u);
}

TEST(RoverDriveCrab, ListedWheelsSenseAndNoneByDefault) {
  SlipRover listed("crab_sensing_wheels: [wheel_joint_FL, wheel_joint_RR]");
  listed.run(1.0, 0.2, 0.2, 0.0);
  EXPECT_EQ(listed.status().sensing_wheels, bit(0) | bit(5));
  SlipRover plain("");
  plain.run(1.0, 0.2, 0.2, 0.0);
  EXPECT_EQ(plain.status().active_mode, DriveMode::Crab);
  EXPECT_EQ(plain.status().sensing_wheels, 0u);
}

TEST(RoverDriveCrab, OdometryFollowsTheGroundWhenThePoweredWheelsSlip) {
  for (const bool sensing : {false, true}) {
    SlipRover rover(sensing ? "crab_sensing_wheels: trailing_side" : "");
    rover.ground_scale = 0.8;  // the powered wheels slip 20 %
    rover.run(6.0, 0.3, 0.3, 0.0);
    const double fraction = rover.odometry_error() / rover.truth_distance;
    std::cout << "[ figures  ] crab with the powered wheels slipping 20 %, sensing " << (sensing ? "on" : "off")
              << ": odometry error " << 100 * fraction << " % of " << rover.truth_distance << " m\n";
    ASSERT_GT(rover.truth_distance, 1.5);
    if (sensing) {
      EXPECT_LT(fraction, 0.01);
    } else {
      EXPECT_GT(fraction, 0.2);  // the wheels held at their set points report the command
    }
  }
}

TEST(RoverDriveCrab, HeadingHoldCancelsAYawTheSensingWheelsSee) {
  // The no-side-slip rows, which this plant's yaw disturbance breaks, nearly out of the way.
  const std::string sensing = "crab_sensing_wheels: trailing_side\ncrab_lateral_weight: 0.01\n";
  const std::string hold = "crab_heading_p: 1.0\ncrab_heading_i: 0.5\ncrab_heading_max_rate: 0.1\n";
  for (const bool holding : {false, true}) {
    SlipRover rover(sensing + (holding ? hold : ""));
    rover.yaw_disturbance = 0.03;  // rad/s: the ground turns the rover left
    rover.run(10.0, 0.3, 0.3, 0.0);
    const RoverDriveStatus st = rover.status();
    std::cout << "[ figures  ] crab with a 0.03 rad/s yaw disturbance, heading hold " << (holding ? "on" : "off")
              << ": true yaw " << rover.truth.yaw / kDeg << " deg, odometry yaw " << rover.odom().yaw / kDeg
              << " deg, correction " << st.yaw_correction << " rad/s\n";
    if (holding) {
      EXPECT_TRUE(st.heading_hold);
      EXPECT_NEAR(st.held_yaw, 0.0, 1e-9);
      EXPECT_NEAR(st.yaw_correction, -0.03, 0.005);  // the PI's integral settles on the disturbance
      EXPECT_LT(std::abs(rover.truth.yaw), 1.5 * kDeg);
    } else {
      EXPECT_FALSE(st.heading_hold);
      EXPECT_EQ(st.yaw_correction, 0.0);
      EXPECT_GT(rover.truth.yaw, 12.0 * kDeg);
    }
    // Either way the odometry sees the yaw through the sensing wheels.
    EXPECT_NEAR(rover.odom().yaw, rover.truth.yaw, 1.5 * kDeg);
  }
}

// With no sensing wheels the odometry cannot see the yaw that slip causes, and the heading hold
// on it holds nothing; on the IMU's yaw (crab_heading_source: imu) it holds the true heading.
TEST(RoverDriveCrab, HeadingHoldOnTheImuCancelsAYawTheWheelsCannotSee) {
  const std::string hold = "crab_sensing_wheels: none\ncrab_heading_p: 1.0\ncrab_heading_i: 0.5\ncrab_heading_max_rate: 0.1\n";
  for (const bool imu : {false, true}) {
    SlipRover rover(hold + (imu ? "crab_heading_source: imu\ncrab_heading_imu: body_imu\n" : ""), true);
    rover.yaw_disturbance = 0.03;
    rover.run(10.0, 0.3, 0.3, 0.0);
    const RoverDriveStatus st = rover.status();
    std::cout << "[ figures  ] crab, no sensing wheels, 0.03 rad/s yaw disturbance, heading from "
              << (imu ? "the IMU" : "the wheels") << ": true yaw " << rover.truth.yaw / kDeg << " deg, correction "
              << st.yaw_correction << " rad/s\n";
    EXPECT_TRUE(st.heading_hold);
    if (imu) {
      EXPECT_NEAR(st.yaw_correction, -0.03, 0.005);
      EXPECT_LT(std::abs(rover.truth.yaw), 1.5 * kDeg);
    } else {
      EXPECT_GT(rover.truth.yaw, 12.0 * kDeg);
    }
  }
  // The IMU source without an IMU, with an unknown one, or a source that does not exist.
  const std::vector<std::pair<std::string, std::string>> cases{
      {"crab_heading_source: compass", "/rover/crab_heading_source must be 'wheels' or 'imu' (got 'compass')"},
      {"crab_heading_source: imu", "/rover/crab_heading_imu (the robot's IMUs: none)"},
  };
  for (const auto& [yaml, message] : cases) {
    auto robot = testing::make_rover_robot();
    RoverDriveController c;
    RobotHardware hardware(robot->model, robot->state);
    std::string error;
    try {
      c.init(hardware, Params::from_yaml_string(testing::test_rover_yaml(yaml)).child("rover"), error);
      ADD_FAILURE() << yaml << ": no error";
    } catch (const ControllerConfigError& e) {
      EXPECT_THAT(e.what(), HasSubstr(message)) << yaml;
    }
  }
  auto robot = testing::make_rover_robot();
  ImuSensorData body;
  body.name = "body_imu";
  SensorHardware one({body}, {});
  RoverDriveController c;
  RobotHardware hardware(robot->model, robot->state);
  hardware.set_sensors(&one);
  std::string error;
  try {
    c.init(hardware, Params::from_yaml_string(testing::test_rover_yaml("crab_heading_source: imu\ncrab_heading_imu: zed2")).child("rover"),
           error);
    ADD_FAILURE() << "no error";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown IMU 'zed2' (parameter /rover/crab_heading_imu); the robot's IMUs: body_imu"));
  }
}

TEST(RoverDriveCrab, HeadingHoldOnlyInCrabWithoutACommandedRotation) {
  SlipRover rover("crab_sensing_wheels: trailing_side\ncrab_heading_p: 1.0\ncrab_heading_i: 0.5");
  rover.run(2.0, 0.3, 0.0, 0.3);  // Ackermann: the heading is the command's business
  RoverDriveStatus st = rover.status();
  EXPECT_EQ(st.active_mode, DriveMode::Ackermann);
  EXPECT_FALSE(st.heading_hold);
  const double yaw = rover.odom().yaw;
  EXPECT_GT(yaw, 0.3);
  rover.run(1.0, 0.1, 0.4, 0.05);  // vy and wz: crab wins, wz dropped, but a rotation was asked for
  st = rover.status();
  EXPECT_EQ(st.active_mode, DriveMode::Crab);
  EXPECT_FALSE(st.heading_hold);
  EXPECT_EQ(st.yaw_correction, 0.0);
  rover.run(1.0, 0.1, 0.4, 0.0);  // a plain crab holds the heading it starts with
  st = rover.status();
  EXPECT_TRUE(st.heading_hold);
  EXPECT_NEAR(st.held_yaw, yaw, 0.05);
  EXPECT_NEAR(rover.odom().yaw, st.held_yaw, 0.01);
  rover.run(1.0, 0.0, 0.0, 0.0);  // stopped: nothing to hold with
  EXPECT_FALSE(rover.status().heading_hold);
}

TEST(RoverDriveCrab, CrabUpdateAllocatesNothing) {
  SlipRover rover("crab_sensing_wheels: trailing_side\ncrab_heading_p: 1.0\ncrab_heading_i: 0.5");
  rover.yaw_disturbance = 0.02;
  rover.ground_scale = 0.9;
  rover.run(0.01, 0.0, 0.0, 0.0);
  rover.count_allocations = true;
  rover.run(1.0, 0.3, 0.3, 0.0);
  rover.run(1.0, 0.3, -0.3, 0.0);
  rover.run(0.5, 0.0, 0.0, 0.0);
  EXPECT_EQ(rover.allocations, 0);
  EXPECT_TRUE(rover.status().crab_sensing || rover.status().sensing_wheels == 0u);
}

TEST(RoverDriveCrab, BadCrabParametersNameTheParameter) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"crab_sensing_wheels: [wheel_joint_FL, wheel_joint_XX]", "/rover/crab_sensing_wheels[1]"},
      {"crab_sensing_wheels: leading_side", "/rover/crab_sensing_wheels"},
      {"crab_sensing_wheels: [wheel_joint_FL, wheel_joint_FR, wheel_joint_ML, wheel_joint_MR, wheel_joint_RL, "
       "wheel_joint_RR]",
       "/rover/crab_sensing_wheels"},
      {"crab_heading_p: -1", "/rover/crab_heading_p"},
      {"crab_heading_max_rate: 0", "/rover/crab_heading_max_rate"},
      {"crab_lateral_weight: -0.5", "/rover/crab_lateral_weight"},
      {"odometry_robust_iterations: 50", "/rover/odometry_robust_iterations"},
      {"odometry_robust_scale: -0.1", "/rover/odometry_robust_scale"},
  };
  for (const auto& [extra, path] : cases) {
    auto robot = testing::make_rover_robot();
    const Params params = Params::from_yaml_string(testing::test_rover_yaml(extra)).child("rover");
    RobotHardware hardware(robot->model, robot->state);
    RoverDriveController controller;
    std::string error;
    try {
      controller.init(hardware, params, error);
      ADD_FAILURE() << extra << ": accepted";
    } catch (const std::exception& e) {
      EXPECT_THAT(e.what(), HasSubstr(path)) << extra;
    }
  }
}

}  // namespace
}  // namespace mechsim::control
