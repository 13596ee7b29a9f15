// Physics::set_armature: reflected rotor inertia added to one joint of one instance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

// Small-angle period (s) of joint 0, from its upward zero crossings over `duration` seconds.
double period_of(Physics& p, double duration) {
  double prev = p.position(0), prev_t = p.time(), first = -1.0, last = -1.0;
  int crossings = 0;
  while (p.time() < duration) {
    EXPECT_TRUE(p.step().ok());
    const double q = p.position(0);
    if (prev < 0.0 && q >= 0.0) {
      const double t = prev_t + (p.time() - prev_t) * (-prev) / (q - prev);
      if (first < 0.0) first = t;
      last = t;
      ++crossings;
    }
    prev = q;
    prev_t = p.time();
  }
  return crossings >= 2 ? (last - first) / (crossings - 1) : 0.0;
}

// T = 2 pi sqrt((I_pivot + A) / (m g L)) within 0.5 %; another instance of the same model keeps
// its own (zero) armature, and reset() keeps the armature.
TEST(PhysicsArmature, AddsToTheJointInertiaOfThisInstanceOnly) {
  const double L = 0.5, m = 1.0, Icm = 1e-3, A = 0.75;
  auto model = test::build(test::pendulum_urdf(L, m, Icm));
  Physics with(model), without(model);
  with.set_armature(0, A);
  EXPECT_DOUBLE_EQ(with.armature(0), A);
  EXPECT_DOUBLE_EQ(without.armature(0), 0.0);
  with.reset();
  EXPECT_DOUBLE_EQ(with.armature(0), A);
  with.set_joint_state(0, 0.01);
  without.set_joint_state(0, 0.01);
  const double g = 9.81;
  const double expected_with = 2.0 * M_PI * std::sqrt((Icm + m * L * L + A) / (m * g * L));
  const double expected_without = 2.0 * M_PI * std::sqrt((Icm + m * L * L) / (m * g * L));
  EXPECT_NEAR(period_of(with, 12.0), expected_with, 0.005 * expected_with);
  EXPECT_NEAR(period_of(without, 12.0), expected_without, 0.005 * expected_without);
}

TEST(PhysicsArmature, RejectsNegativeAndNonFiniteValuesNamingTheJoint) {
  auto model = test::build(test::pendulum_urdf(0.5, 1.0, 1e-3));
  Physics p(model);
  const std::string joint = model->joints()[0].name;
  for (const double bad : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    try {
      p.set_armature(0, bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(joint), std::string::npos) << e.what();
    }
  }
  EXPECT_DOUBLE_EQ(p.armature(0), 0.0);
}

// effective_inertia: the pendulum's I_pivot plus armature; a double pendulum's first joint sees
// less than its mass-matrix diagonal, because the second joint is free: 1 / (M^-1)_11.
TEST(PhysicsEffectiveInertia, IsThePivotInertiaPlusArmatureAndAccountsForFreeJoints) {
  const double L = 0.5, m = 2.0, Icm = 1e-3;
  Physics p(test::build(test::pendulum_urdf(L, m, Icm, R"(<dynamics damping="0.3"/>)")));
  EXPECT_NEAR(p.effective_inertia(0), Icm + m * L * L, 1e-9);
  EXPECT_DOUBLE_EQ(p.joint_damping(0), 0.3);
  p.set_armature(0, 0.25);
  EXPECT_NEAR(p.effective_inertia(0), Icm + m * L * L + 0.25, 1e-9);

  // Straight down, rods of 1 m and 1 kg: M = [[I1 + I2 + m l^2 + 2 m l c, I2 + m l c], [I2 + m l c, I2]]
  // with I = m l^2 / 3 about each pivot (plus the tiny iyy of the model) and c = 0.5 m.
  Physics d(test::build(test::double_pendulum_urdf()));
  const double i_rod = 1.0 / 12.0 + 0.25, m11 = 2.0 * i_rod + 1.0 + 1.0, m12 = i_rod + 0.5, m22 = i_rod;
  const double expected = m11 - m12 * m12 / m22;  // 1 / (M^-1)_11, the Schur complement
  EXPECT_NEAR(d.effective_inertia(0), expected, 1e-6);
  EXPECT_LT(d.effective_inertia(0), m11);
  // The query leaves the state alone: the pendulum still starts at rest where it was.
  EXPECT_DOUBLE_EQ(d.position(0), 0.0);
  EXPECT_TRUE(d.step().ok());
}

}  // namespace
}  // namespace mechsim::physics
