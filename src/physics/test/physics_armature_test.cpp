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

}  // namespace
}  // namespace mechsim::physics
