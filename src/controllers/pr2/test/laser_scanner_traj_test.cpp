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

LaserScanProfile periodic(PeriodicProfile kind, double period, double amplitude, double offset,
                          const ScanLimits& limits = {10.0, 30.0}) {
  LaserScanProfile p;
  std::string error;
  EXPECT_TRUE(LaserScanProfile::from_periodic({kind, period, amplitude, offset}, limits, p, &error)) << error;
  return p;
}

TEST(LaserProfile, LinearIsATriangleFromLowToHighAndBack) {
  const LaserScanProfile c = periodic(PeriodicProfile::Linear, 2.0, 0.5, 0.3);
  double p = 0.0, v = 0.0;
  c.sample(0.0, p, v);
  EXPECT_NEAR(p, -0.2, 1e-12);
  EXPECT_NEAR(v, 1.0, 1e-12);  // 4 A / T
  c.sample(0.5, p, v);
  EXPECT_NEAR(p, 0.3, 1e-12);
  c.sample(1.0, p, v);
  EXPECT_NEAR(p, 0.8, 1e-12);
  c.sample(1.5, p, v);
  EXPECT_NEAR(p, 0.3, 1e-12);
  EXPECT_NEAR(v, -1.0, 1e-12);
  c.sample(4.25, p, v);  // two periods later, a quarter in
  EXPECT_NEAR(p, 0.05, 1e-12);
  EXPECT_NEAR(c.duration(), 2.0, 1e-12);
}

TEST(LaserProfile, SineStartsAtTheOffsetGoingUp) {
  const LaserScanProfile c = periodic(PeriodicProfile::Sine, 4.0, 0.6, 0.1);
  double p = 0.0, v = 0.0;
  c.sample(0.0, p, v);
  EXPECT_NEAR(p, 0.1, 1e-12);
  EXPECT_NEAR(v, 0.6 * 2.0 * kPi / 4.0, 1e-12);
  c.sample(1.0, p, v);
  EXPECT_NEAR(p, 0.7, 1e-12);
  EXPECT_NEAR(v, 0.0, 1e-12);
  c.sample(3.0, p, v);
  EXPECT_NEAR(p, -0.5, 1e-12);
  c.sample(0.5, p, v);
  EXPECT_NEAR(p, 0.1 + 0.6 * std::sin(kPi / 4.0), 1e-12);
}

// Blended: the corners of the triangle become parabolas at max_acceleration; the path is
// continuous in position and velocity everywhere (the loop included), the acceleration never
// exceeds the limit, and the straight parts are the linear profile's.
TEST(LaserProfile, BlendedLinearRoundsTheCornersAtMaxAcceleration) {
  const double a_max = 30.0;
  const LaserScanProfile b = periodic(PeriodicProfile::BlendedLinear, 2.0, 0.5, 0.3, {10.0, a_max});
  const LaserScanProfile l = periodic(PeriodicProfile::Linear, 2.0, 0.5, 0.3);
  const double dt = 1e-4;
  double worst_jump = 0.0, worst_acc = 0.0;
  double p0 = 0.0, v0 = 0.0;
  b.sample(0.0, p0, v0);
  for (double t = dt; t < 6.0; t += dt) {
    double p = 0.0, v = 0.0;
    b.sample(t, p, v);
    worst_jump = std::max(worst_jump, std::abs(p - p0));
    worst_acc = std::max(worst_acc, std::abs(v - v0) / dt);
    p0 = p;
    v0 = v;
  }
  EXPECT_LT(worst_jump, 1.0 * dt * 1.01);       // |v| <= 1 rad/s: no jump in position
  EXPECT_LT(worst_acc, a_max * 1.001);          // velocity changes at no more than max_acceleration
  EXPECT_GT(worst_acc, a_max * 0.999);          // ... and reaches it in the blends
  double p = 0.0, v = 0.0, q = 0.0, w = 0.0;
  b.sample(0.5, p, v);  // mid-segment: the linear profile's
  l.sample(0.5, q, w);
  EXPECT_NEAR(p, q, 1e-12);
  EXPECT_NEAR(v, w, 1e-12);
  // At the high corner the blend (2 rad/s change over 30 rad/s^2: 0.0667 s) stays short of it by
  // (v_out - v_in) b / 8 = -2 * 0.0667 / 8.
  b.sample(1.0, p, v);
  EXPECT_NEAR(p, 0.8 - 2.0 * (2.0 / a_max) / 8.0, 1e-12);
  EXPECT_NEAR(v, 0.0, 1e-12);
}

// pr2_msgs/LaserTrajCmd: via points at their times, repeated; a segment too short for the
// velocity limit is stretched.
TEST(LaserProfile, TrajectoryLoopsThroughItsPointsAndStretchesWhatIsTooFast) {
  LaserTrajCommand cmd;
  cmd.profile = PeriodicProfile::Linear;
  cmd.positions = {-0.5, 0.5, 0.0};
  cmd.times_from_start = {0.0, 0.5, 1.5};
  cmd.max_velocity = 1.0;  // rad/s: the first segment needs 1 s, not 0.5
  LaserScanProfile p;
  std::string error;
  ASSERT_TRUE(LaserScanProfile::from_trajectory(cmd, {10.0, 30.0}, p, &error)) << error;
  EXPECT_NEAR(p.duration(), 2.0, 1e-12);
  double q = 0.0, v = 0.0;
  p.sample(0.5, q, v);
  EXPECT_NEAR(q, 0.0, 1e-12);
  EXPECT_NEAR(v, 1.0, 1e-12);
  p.sample(1.5, q, v);
  EXPECT_NEAR(q, 0.25, 1e-12);
  EXPECT_NEAR(v, -0.5, 1e-12);
  p.sample(2.25, q, v);  // looped: a quarter into the first segment again
  EXPECT_NEAR(q, -0.25, 1e-12);
  // Without a limit of its own the controller's applies (10 rad/s: the given times stand).
  cmd.max_velocity = 0.0;
  ASSERT_TRUE(LaserScanProfile::from_trajectory(cmd, {10.0, 30.0}, p, &error)) << error;
  EXPECT_NEAR(p.duration(), 1.5, 1e-12);
  // One point: hold it.
  cmd.positions = {0.4};
  cmd.times_from_start = {0.0};
  ASSERT_TRUE(LaserScanProfile::from_trajectory(cmd, {10.0, 30.0}, p, &error)) << error;
  p.sample(3.0, q, v);
  EXPECT_EQ(q, 0.4);
  EXPECT_EQ(v, 0.0);
}

TEST(LaserProfile, BadTrajectoriesSayWhy) {
  const auto why = [](LaserTrajCommand c) {
    LaserScanProfile p;
    std::string error;
    EXPECT_FALSE(LaserScanProfile::from_trajectory(c, {}, p, &error));
    return error;
  };
  LaserTrajCommand c;
  EXPECT_THAT(why(c), HasSubstr("no point"));
  c.positions = {0.0, 1.0};
  c.times_from_start = {0.0};
  EXPECT_THAT(why(c), HasSubstr("2 positions but 1 times"));
  c.times_from_start = {1.0, 0.5};
  EXPECT_THAT(why(c), HasSubstr("before"));
  c.times_from_start = {0.0, NAN};
  EXPECT_THAT(why(c), HasSubstr("not finite"));
  c.positions.assign(kMaxLaserScanPoints + 1, 0.0);
  c.times_from_start.assign(kMaxLaserScanPoints + 1, 0.0);
  EXPECT_THAT(why(c), HasSubstr("at most"));
  c = LaserTrajCommand{PeriodicProfile::Sine, {0.0}, {0.0}, 0.0, 0.0};
  EXPECT_THAT(why(c), HasSubstr("not a trajectory profile"));
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

TEST(LaserScannerTraj, TrajectoryCommandReplacesThePeriodicProfileAtTheNextTick) {
  Laser l;
  ASSERT_TRUE(l.c->command_port().write("linear", 2.0, 0.5, 0.3));
  l.run(300);
  LaserTrajCommand t;
  t.profile = PeriodicProfile::BlendedLinear;
  t.positions = {0.0, 1.0, 0.0};
  t.times_from_start = {0.0, 2.0, 4.0};
  ASSERT_TRUE(l.c->command_port().write(t));
  l.run(1);  // taken at this tick: its start
  EXPECT_NEAR(l.set_point(), 0.0 + 0.0, 0.02);  // the loop's blend starts just above 0
  EXPECT_EQ(l.c->active_profile().kind(), PeriodicProfile::BlendedLinear);
  l.run(1000);  // 1 s in: half way up the first segment
  EXPECT_NEAR(l.set_point(), 0.5, 1e-9);
  l.run(4000);  // 5 s: looped, 1 s in again
  EXPECT_NEAR(l.set_point(), 0.5, 1e-9);
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
  EXPECT_FALSE(l.c->command_port().write(LaserTrajCommand{PeriodicProfile::Linear, {0.0, 1.0}, {0.0}, 0.0, 0.0}, &error));
  EXPECT_THAT(error, HasSubstr("trajectory command"));
  EXPECT_EQ(l.c->command_port().count(), 5u);
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
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n    pid: {p: 1}\n    max_acceleration: 0\n"),
              HasSubstr("/pr2/l/max_acceleration"));
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n    pid: {p: 1}\n    profile: sine\n    amplitude: 1\n"),
              HasSubstr("/pr2/l/period"));
  EXPECT_THAT(load("    joint: laser_tilt_mount_joint\n    pid: {p: 1}\n    profile: sine\n    period: -1\n    amplitude: 1\n"),
              HasSubstr("/pr2/l/period"));
}

}  // namespace
}  // namespace mechsim::control
