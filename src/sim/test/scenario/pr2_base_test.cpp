// The PR2's base under its default base_controller (Pr2BaseController2, geometry filled from the
// URDF) and base_odometry (Pr2Odometry), with the whole default set holding the arms, torso and
// head: 1 m forward at 0.3 m/s ends within 3 % of the distance, a 90 degree turn within 3
// degrees, and odometry agrees with the true motion within 3 %. The commands are open loop in
// time (cmd_vel re-sent every 50 ms, under the controller's 0.2 s timeout); the controller's
// acceleration limits ramp up and down symmetrically, so distance = speed * command time.
// Simulated time: 6.3 s + 5.6 s.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "controllers/drive/pr2_base_controller.hpp"
#include "controllers/drive/pr2_odometry.hpp"
#include "sim/pose_math.hpp"
#include "sim/test/scenario/pr2_util.hpp"

namespace mechsim::sim {
namespace {

const std::vector<std::string> kDefaultSet = {"r_arm_controller",     "l_arm_controller", "head_traj_controller",
                                              "torso_controller",     "base_controller",  "base_odometry",
                                              "r_gripper_controller", "l_gripper_controller", "laser_tilt_controller"};

double wrap(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

struct Motion {
  double dx = 0.0, dy = 0.0, dyaw = 0.0;       // true, world frame (m, rad)
  double odom_dx = 0.0, odom_dy = 0.0, odom_dyaw = 0.0;  // odometry
};

// Sends `twist` for `seconds`, then zero, then lets the base settle for `settle` seconds.
Motion drive(Simulation& sim, const control::Twist& twist, double seconds, double settle) {
  auto& base = pr2_controller<control::Pr2BaseController>(sim, "base_controller");
  auto& odom = pr2_controller<control::Pr2OdometryController>(sim, "base_odometry");
  const description::Pose p0 = sim.physics().base_pose();
  const control::OdometrySnapshot o0 = odom.odometry_port().read();
  // Whole ticks: 50 ms blocks, then the rest (run_for shorter than a tick would not advance).
  const auto ticks = static_cast<long>(std::lround(seconds / sim.period()));
  for (long done = 0; done < ticks;) {
    const long block = std::min(50L, ticks - done);
    EXPECT_TRUE(base.command_port().write(twist));
    for (long k = 0; k < block; ++k) EXPECT_TRUE(sim.step());
    done += block;
  }
  EXPECT_TRUE(base.command_port().write(control::Twist{}));
  EXPECT_TRUE(sim.run_for(settle));
  const description::Pose p1 = sim.physics().base_pose();
  const control::OdometrySnapshot o1 = odom.odometry_port().read();
  return {p1.position.x - p0.position.x, p1.position.y - p0.position.y, wrap(yaw_of(p1.orientation) - yaw_of(p0.orientation)),
          o1.x - o0.x, o1.y - o0.y, wrap(o1.yaw - o0.yaw)};
}

TEST(Pr2Base, OneMetreForwardAt30cmPerSecondWithin3Percent) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  auto sim = make_pr2_simulation(kDefaultSet);
  ASSERT_TRUE(sim->run_for(1.0));
  control::Twist forward;
  forward.linear.x = 0.3;
  const Motion m = drive(*sim, forward, 1.0 / 0.3, 2.0);
  const double distance = std::hypot(m.dx, m.dy), odom_distance = std::hypot(m.odom_dx, m.odom_dy);
  std::cout << "[ figures  ] base 1 m at 0.3 m/s: true " << m.dx << " m forward, " << m.dy << " m sideways, yaw "
            << m.dyaw * 180 / std::numbers::pi << " deg; odometry " << m.odom_dx << ", " << m.odom_dy
            << " m (error " << 100.0 * std::abs(odom_distance - distance) / distance << " % of the true distance)\n";
  EXPECT_NEAR(distance, 1.0, 0.03);
  EXPECT_NEAR(m.dy, 0.0, 0.03);
  EXPECT_NEAR(std::hypot(m.odom_dx - m.dx, m.odom_dy - m.dy), 0.0, 0.03 * distance);
}

TEST(Pr2Base, NinetyDegreeTurnWithin3Degrees) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  auto sim = make_pr2_simulation(kDefaultSet);
  ASSERT_TRUE(sim->run_for(1.0));
  control::Twist turn;
  turn.angular.z = 0.5;
  const Motion m = drive(*sim, turn, (std::numbers::pi / 2) / 0.5, 1.5);
  const double deg = 180.0 / std::numbers::pi;
  std::cout << "[ figures  ] base 90 deg turn at 0.5 rad/s: true " << m.dyaw * deg << " deg (drift " << m.dx << ", "
            << m.dy << " m); odometry " << m.odom_dyaw * deg << " deg\n";
  EXPECT_NEAR(m.dyaw * deg, 90.0, 3.0);
  EXPECT_NEAR(m.odom_dyaw, m.dyaw, 0.03 * std::abs(m.dyaw));
  EXPECT_LT(std::hypot(m.dx, m.dy), 0.1);  // turns roughly in place
}

}  // namespace
}  // namespace mechsim::sim
