// The laser tilt controller: the profiles' values at known times, the controller's set points
// through its state port, tracking on a unit-inertia joint, command rejection, init errors.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/pr2/laser_scanner_traj_controller.hpp"
#include "controllers/test/test_robot.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;

TEST(LaserProfile, LinearIsATriangleFromLowToHighAndBack) {
  const PeriodicCommand c{PeriodicProfile::Linear, 2.0, 0.5, 0.3};
  double p = 0.0, v = 0.0;
  periodic_profile_sample(c, 0.0, p, v);
  EXPECT_NEAR(p, -0.2, 1e-12);
  EXPECT_NEAR(v, 1.0, 1e-12);  // 4 A / T
  periodic_profile_sample(c, 0.5, p, v);
  EXPECT_NEAR(p, 0.3, 1e-12);
  periodic_profile_sample(c, 1.0, p, v);
  EXPECT_NEAR(p, 0.8, 1e-12);
  periodic_profile_sample(c, 1.5, p, v);
  EXPECT_NEAR(p, 0.3, 1e-12);
  EXPECT_NEAR(v, -1.0, 1e-12);
  periodic_profile_sample(c, 4.25, p, v);  // two periods later, a quarter in
  EXPECT_NEAR(p, 0.05, 1e-12);
}

TEST(LaserProfile, SineStartsAtTheOffsetGoingUp) {
  const PeriodicCommand c{PeriodicProfile::Sine, 4.0, 0.6, 0.1};
  double p = 0.0, v = 0.0;
  periodic_profile_sample(c, 0.0, p, v);
  EXPECT_NEAR(p, 0.1, 1e-12);
  EXPECT_NEAR(v, 0.6 * 2.0 * kPi / 4.0, 1e-12);
  periodic_profile_sample(c, 1.0, p, v);
  EXPECT_NEAR(p, 0.7, 1e-12);
  EXPECT_NEAR(v, 0.0, 1e-12);
  periodic_profile_sample(c, 3.0, p, v);
  EXPECT_NEAR(p, -0.5, 1e-12);
  periodic_profile_sample(c, 0.5, p, v);
  EXPECT_NEAR(p, 0.1 + 0.6 * std::sin(kPi / 4.0), 1e-12);
}

struct Laser {
  std::unique_ptr<testing::TestRobot> robot;
  std::unique_ptr<ControllerManager> manager;
  LaserScannerTrajController* c = nullptr;
  double time = 0.0;

  explicit Laser(const std::string& extra = "") {
    robot = testing::make_robot({{"laser_tilt_mount_joint", description::JointType::Revolute,
                                  description::JointLimits{-0.7854, 1.48353, 0.65, 10.0}}});
    robot->mass = 0.01;  // kg m^2
    const std::string yaml = "pr2:\n  laser_tilt_controller:\n    type: pr2_mechanism_controllers/LaserScannerTrajController\n"
                             "    joint: laser_tilt_mount_joint\n    pid: {p: 8.0, d: 0.4}\n" + extra;
    manager = std::make_unique<ControllerManager>(robot->model, robot->state, Params::from_yaml_string(yaml).child("pr2"),
                                                  builtin_controller_registry());
    c = dynamic_cast<LaserScannerTrajController*>(testing::load_and_start(*manager, "laser_tilt_controller"));
  }
  void run(int ticks) { time = testing::run(*manager, *robot, time, ticks); }
  double set_point() const { return c->state_port().read().set_point; }
};

TEST(LaserScannerTraj, HoldsUntilAProfileArrivesThenFollowsIt) {
  Laser l;
  l.robot->joint("laser_tilt_mount_joint").position = 0.2;
  mechanism::propagate_joint_to_actuator_position(l.robot->model, l.robot->state);
  l.run(1);  // started at 0.2 (the switch happens in this tick)
  l.run(10);
  EXPECT_NEAR(l.set_point(), 0.2, 1e-12);
  ASSERT_TRUE(l.c->command_port().write("linear", 2.0, 0.5, 0.3));
  l.run(1);  // taken at this tick: phase 0
  EXPECT_NEAR(l.set_point(), -0.2, 1e-12);
  l.run(500);  // t = 0.5 s into the profile
  EXPECT_NEAR(l.set_point(), 0.3, 1e-9);
  l.run(500);
  EXPECT_NEAR(l.set_point(), 0.8, 1e-9);
  // Tracking on a 0.01 kg m^2 joint: within a few centiradians of the moving set point.
  l.run(3000);
  EXPECT_LT(std::abs(l.c->state_port().read().error), 0.05);
}

TEST(LaserScannerTraj, ProfileFromParametersClampedIntoTheJointLimits) {
  Laser l("    profile: sine\n    period: 1.0\n    amplitude: 1.0\n    offset: 0.0\n");
  l.run(1);
  EXPECT_NEAR(l.set_point(), 0.0, 1e-12);
  l.run(250);  // a quarter period: sin = 1, clamped to the upper limit 1.48353? no: 1.0 is within
  EXPECT_NEAR(l.set_point(), 1.0, 1e-9);
  l.run(500);  // three quarters: -1.0, below the lower limit -0.7854
  EXPECT_NEAR(l.set_point(), -0.7854, 1e-12);
}

TEST(LaserScannerTraj, RejectsBadCommands) {
  Laser l;
  std::string error;
  EXPECT_FALSE(l.c->command_port().write("square", 1.0, 0.1, 0.0, &error));
  EXPECT_THAT(error, HasSubstr("square"));
  EXPECT_FALSE(l.c->command_port().write("linear", 0.0, 0.1, 0.0, &error));
  EXPECT_THAT(error, HasSubstr("period"));
  EXPECT_FALSE(l.c->command_port().write("sine", 1.0, NAN, 0.0, &error));
  EXPECT_FALSE(l.c->command_port().write("sine", 1.0, -0.1, 0.0, &error));
  EXPECT_EQ(l.c->command_port().count(), 4u);
  EXPECT_EQ(l.c->command_port().accepted(), 0u);
}

TEST(LaserScannerTraj, InitErrorsNameTheParameterPath) {
  const auto load = [](const std::string& extra) {
    auto robot = testing::make_robot({{"laser_tilt_mount_joint"}});
    const std::string yaml = "pr2:\n  l:\n    type: pr2_mechanism_controllers/LaserScannerTrajController\n" + extra;
    ControllerManager m(robot->model, robot->state, Params::from_yaml_string(yaml).child("pr2"),
                        builtin_controller_registry());
    return m.load_controller("l").error;
  };
  EXPECT_THAT(load("    pid: {p: 1}\n"), HasSubstr("/pr2/l/joint"));
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n"), HasSubstr("/pr2/l/pid"));
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n    pid: {p: 1}\n    profile: square\n"), HasSubstr("/pr2/l/profile"));
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n    pid: {p: 1}\n    profile: sine\n    amplitude: 1\n"),
              HasSubstr("/pr2/l/period"));
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n    pid: {p: 1}\n    profile: sine\n    period: -1\n    amplitude: 1\n"),
              HasSubstr("/pr2/l/period"));
}

}  // namespace
}  // namespace mechsim::control
