// Physical checks of the joints and their dynamics, with the tolerances the issue states.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

constexpr double kG = 9.81;

// Times (s) of upward zero crossings of joint 0, linearly interpolated.
std::vector<double> upward_crossings(Physics& p, std::size_t joint, double duration) {
  std::vector<double> out;
  double prev = p.position(joint), prev_t = p.time();
  while (p.time() < duration) {
    EXPECT_TRUE(p.step().ok());
    const double q = p.position(joint);
    if (prev < 0.0 && q >= 0.0) out.push_back(prev_t + (p.time() - prev_t) * (-prev) / (q - prev));
    prev = q;
    prev_t = p.time();
  }
  return out;
}

// Small-angle period of a physical pendulum: T = 2 pi sqrt(I_pivot / (m g L)).
// Default options: implicit integrator, 1 ms step. Tolerance 0.5 %.
TEST(PhysicsDynamics, PendulumSmallAnglePeriodWithinHalfAPercent) {
  const double L = 1.0, m = 2.0, Icm = 1e-3;
  auto model = test::build(test::pendulum_urdf(L, m, Icm));
  Physics p(model);
  p.set_joint_state(0, 0.01);
  const auto t = upward_crossings(p, 0, 12.0);
  ASSERT_GE(t.size(), 4u);
  const double measured = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  const double analytic = 2.0 * M_PI * std::sqrt((Icm + m * L * L) / (m * kG * L));
  const double error = std::fabs(measured - analytic) / analytic;
  RecordProperty("period_error_percent", std::to_string(100.0 * error));
  std::printf("pendulum period: measured %.6f s, analytic %.6f s, error %.4f %%\n", measured, analytic, 100 * error);
  EXPECT_LT(error, 0.005);
}

// The inertial frame's rotation is applied to the inertia tensor: ixx = 0.5 turned 90 degrees
// about z becomes the inertia about the y hinge, so I_pivot = 0.5 + m L^2. Tolerance 0.5 %.
TEST(PhysicsDynamics, InertialOriginRotationIsHonoured) {
  const std::string urdf = R"(<robot name="rotated">
  <link name="world"/>
  <link name="bob">
    <inertial><origin xyz="0 0 -0.5" rpy="0 0 1.5707963267948966"/><mass value="1"/>
      <inertia ixx="0.5" iyy="0.3" izz="0.3" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="hinge" type="continuous"><parent link="world"/><child link="bob"/><origin xyz="0 0 2"/><axis xyz="0 1 0"/></joint>
</robot>)";
  Physics p(test::build(urdf));
  p.set_joint_state(0, 0.01);
  const auto t = upward_crossings(p, 0, 10.0);
  ASSERT_GE(t.size(), 3u);
  const double measured = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  const double analytic = 2.0 * M_PI * std::sqrt((0.5 + 0.25) / (1.0 * kG * 0.5));
  EXPECT_NEAR(measured, analytic, 0.005 * analytic);
}

// A massless link on the hinge with the mass on a fixed child: the mass is lumped into the
// hinge's body (as Gazebo lumps fixed joints), the joint is kept, the period is the same.
TEST(PhysicsDynamics, MassOnAFixedChildOfAMasslessLinkIsLumped) {
  const std::string urdf = R"(<robot name="lumped">
  <link name="world"/>
  <link name="mount"/>
  <link name="bob"><inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="continuous"><parent link="world"/><child link="mount"/><origin xyz="0 0 2"/><axis xyz="0 1 0"/></joint>
  <joint name="weld" type="fixed"><parent link="mount"/><child link="bob"/><origin xyz="0 0 -0.5" rpy="0 0.3 0"/></joint>
</robot>)";
  auto model = test::build(urdf);
  EXPECT_TRUE(model->warnings().empty()) << model->warnings().front();
  ASSERT_TRUE(model->joint_index("hinge").has_value());
  EXPECT_EQ(model->body_count(), 2);  // world + mount (bob lumped in)
  Physics p(model);
  p.set_joint_state(0, 0.01);
  const auto t = upward_crossings(p, 0, 10.0);
  ASSERT_GE(t.size(), 3u);
  const double measured = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  const double analytic = 2.0 * M_PI * std::sqrt((0.001 + 2.0 * 1.0) / (2.0 * kG * 1.0));
  EXPECT_NEAR(measured, analytic, 0.005 * analytic);
  // The bob's frame is still where the URDF puts it.
  EXPECT_NEAR(p.link_pose(*model->link_index("bob")).position.z, 1.5, 1e-3);
}

// A free body falls z(t) = z0 - g t^2 / 2. Default options. Tolerance 1 % of the drop.
TEST(PhysicsDynamics, FreeFallWithinOnePercent) {
  BuildOptions o;
  o.spawn.z = 10.0;
  auto model = test::build(test::box_urdf(), o);
  Physics p(model);
  while (p.time() < 1.0 - 1e-9) ASSERT_TRUE(p.step().ok());
  const double t = p.time();
  const double drop = 10.0 - p.base_pose().position.z;
  const double analytic = 0.5 * kG * t * t;
  const double error = std::fabs(drop - analytic) / analytic;
  std::printf("free fall: dropped %.6f m in %.3f s, analytic %.6f m, error %.4f %%\n", drop, t, analytic, 100 * error);
  EXPECT_LT(error, 0.01);
  EXPECT_NEAR(p.base_twist().linear.z, -kG * t, 0.01 * kG * t);
}

// Undamped double pendulum, RK4 at 1 ms (the choice for this check): the energy above the
// hanging rest state drifts less than 1 % over 10 s.
TEST(PhysicsDynamics, DoublePendulumEnergyDriftBelowOnePercentOver10s) {
  BuildOptions o;
  o.integrator = Integrator::Rk4;
  auto model = test::build(test::double_pendulum_urdf(), o);
  Physics p(model);
  const double e_rest = p.energy();
  p.set_joint_state(0, 1.0);
  p.set_joint_state(1, -0.5);
  const double e0 = p.energy() - e_rest;
  ASSERT_GT(e0, 1.0);
  double worst = 0.0;
  while (p.time() < 10.0) {
    ASSERT_TRUE(p.step().ok());
    worst = std::max(worst, std::fabs(p.energy() - e_rest - e0) / e0);
  }
  std::printf("double pendulum: E0 = %.4f J above rest, worst drift %.3e %% over 10 s\n", e0, 100 * worst);
  EXPECT_LT(worst, 0.01);
}

TEST(PhysicsDynamics, RevoluteLimitHoldsAgainstAPushingEffort) {
  auto model = test::build(test::pendulum_urdf(1.0, 1.0, 1e-3, R"(<limit lower="-0.5" upper="0.5" effort="100" velocity="5"/>)",
                                               "revolute"));
  Physics p(model);
  double highest = -1.0;
  while (p.time() < 2.0) {
    p.set_effort(0, 30.0);
    ASSERT_TRUE(p.step().ok());
    highest = std::max(highest, p.position(0));
  }
  EXPECT_LT(highest, 0.5 + 0.02);  // soft limit: a little penetration at impact
  EXPECT_NEAR(p.position(0), 0.5, 0.01);
  // At rest on the limit the constraint balances the effort and gravity.
  EXPECT_NEAR(p.constraint_effort(0), -(30.0 - 1.0 * kG * std::sin(0.5)), 0.5);
  EXPECT_NEAR(p.actuator_effort(0), 30.0, 1e-9);
}

TEST(PhysicsDynamics, PrismaticLimitHolds) {
  const std::string urdf = R"(<robot name="slider">
  <link name="world"/>
  <link name="cart"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="rail" type="prismatic"><parent link="world"/><child link="cart"/><origin xyz="0 0 1"/><axis xyz="1 0 0"/>
    <limit lower="-0.2" upper="0.3" effort="50" velocity="1"/></joint>
</robot>)";
  Physics p(test::build(urdf));
  while (p.time() < 2.0) {
    p.set_effort(0, -20.0);
    ASSERT_TRUE(p.step().ok());
    EXPECT_GT(p.position(0), -0.2 - 0.02);
  }
  EXPECT_NEAR(p.position(0), -0.2, 0.01);
}

// Viscous damping b: the small-angle amplitude decays as exp(-b t / (2 I_pivot)). Tolerance 5 %.
TEST(PhysicsDynamics, DampingSlowsAtTheExpectedRate) {
  const double L = 1.0, m = 1.0, Icm = 1e-3, b = 0.2;
  const double I = Icm + m * L * L;
  auto damped = test::build(test::pendulum_urdf(L, m, Icm, R"(<dynamics damping="0.2"/>)"));
  auto free = test::build(test::pendulum_urdf(L, m, Icm));
  Physics pd(damped), pf(free);
  EXPECT_DOUBLE_EQ(damped->joints()[0].damping, b);
  pd.set_joint_state(0, 0.05);
  pf.set_joint_state(0, 0.05);
  double peak_damped = 0.0, peak_free = 0.0;
  while (pd.time() < 6.0) {
    ASSERT_TRUE(pd.step().ok());
    ASSERT_TRUE(pf.step().ok());
    if (pd.time() > 5.0) {
      peak_damped = std::max(peak_damped, std::fabs(pd.position(0)));
      peak_free = std::max(peak_free, std::fabs(pf.position(0)));
    }
  }
  EXPECT_NEAR(peak_free, 0.05, 0.0005);
  // Peaks in [5, 6] s: the envelope at about the time of the largest peak.
  const double expected_upper = 0.05 * std::exp(-b * 5.0 / (2 * I));
  const double expected_lower = 0.05 * std::exp(-b * 6.0 / (2 * I));
  EXPECT_LT(peak_damped, expected_upper * 1.05);
  EXPECT_GT(peak_damped, expected_lower * 0.95);
}

TEST(PhysicsDynamics, FrictionLossHoldsAJointBelowItsBreakaway) {
  auto model = test::build(test::pendulum_urdf(1.0, 1.0, 1e-3, R"(<dynamics friction="5"/>)"));
  Physics p(model);
  while (p.time() < 1.0) {
    p.set_effort(0, 3.0);  // below the 5 N m friction loss
    ASSERT_TRUE(p.step().ok());
  }
  EXPECT_LT(std::fabs(p.position(0)), 0.01);
}

TEST(PhysicsDynamics, IdenticalInputsGiveBitIdenticalTrajectories) {
  BuildOptions o;
  o.spawn = {0.0, 0.0, 0.4, 0.3, 0.2, 0.1};
  auto model = test::build(test::box_urdf(), o);
  Physics a(model), b(model);
  for (int i = 0; i < 1500; ++i) {
    ASSERT_TRUE(a.step().ok());
    ASSERT_TRUE(b.step().ok());
  }
  std::vector<Contact> contacts;
  EXPECT_GT(a.contacts(contacts), 0u);  // it landed: the run exercised the contact solver
  const auto xa = a.base_pose(), xb = b.base_pose();
  EXPECT_EQ(std::memcmp(&xa, &xb, sizeof(xa)), 0);
  // And after a reset, the same trajectory again.
  const auto first = a.base_pose();
  a.reset();
  for (int i = 0; i < 1500; ++i) ASSERT_TRUE(a.step().ok());
  const auto again = a.base_pose();
  EXPECT_EQ(std::memcmp(&first, &again, sizeof(first)), 0);
}

TEST(PhysicsDynamics, ResetReturnsToTheSpawnState) {
  BuildOptions o;
  o.spawn.z = 2.0;
  Physics p(test::build(test::box_urdf(), o));
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(p.step().ok());
  EXPECT_LT(p.base_pose().position.z, 1.9);
  p.reset();
  EXPECT_EQ(p.time(), 0.0);
  EXPECT_DOUBLE_EQ(p.base_pose().position.z, 2.0);
  EXPECT_DOUBLE_EQ(p.base_twist().linear.z, 0.0);
}

TEST(PhysicsDynamics, LinkTwistIncludesTheOffsetFromTheBodyOrigin) {
  Physics p(test::build(test::pendulum_urdf(1.0, 1.0, 1e-3)));
  p.set_joint_state(0, 0.0, 2.0);  // 2 rad/s about +y
  const auto v = p.link_twist(*p.model().link_index("bob"));
  EXPECT_NEAR(v.angular.y, 2.0, 1e-12);
  // The bob link frame is at the joint; its origin does not move.
  EXPECT_NEAR(v.linear.x, 0.0, 1e-12);
}

}  // namespace
}  // namespace mechsim::physics
