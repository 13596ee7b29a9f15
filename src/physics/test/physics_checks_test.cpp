// The step's NaN/inf and runaway detector: it names the joint and leaves the state as it was.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using ::testing::HasSubstr;

TEST(PhysicsChecks, NanEffortIsRejectedNamingTheJoint) {
  Physics p(test::build(test::pendulum_urdf(1.0, 1.0, 1e-3)));
  p.set_joint_state(0, 0.2);
  ASSERT_TRUE(p.step().ok());
  const double q = p.position(0), t = p.time();
  p.set_effort(0, std::numeric_limits<double>::quiet_NaN());
  const StepStatus s = p.step();
  EXPECT_EQ(s.code, StepCode::NonFiniteCommand);
  EXPECT_EQ(s.element, "hinge");
  EXPECT_THAT(s.message(), HasSubstr("hinge"));
  EXPECT_EQ(p.position(0), q);
  EXPECT_EQ(p.time(), t);
  // A good command afterwards steps again.
  p.set_effort(0, 0.0);
  EXPECT_TRUE(p.step().ok());
}

TEST(PhysicsChecks, InfinitePositionCommandIsRejected) {
  Physics p(test::build(test::pendulum_urdf(1.0, 1.0, 1e-3)));
  p.set_mode(0, JointMode::Position);
  p.set_position_command(0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.step().code, StepCode::NonFiniteCommand);
}

TEST(PhysicsChecks, RunawayAccelerationIsDetectedAndTheStateRestored) {
  BuildOptions o;
  o.max_joint_acceleration = 1e5;
  Physics p(test::build(test::pendulum_urdf(1.0, 1.0, 1e-3), o));
  p.set_joint_state(0, 0.1, 0.5);
  const double q = p.position(0), v = p.velocity(0);
  p.set_effort(0, 1e7);  // 1e7 N m on ~1 kg m^2
  const StepStatus s = p.step();
  EXPECT_EQ(s.code, StepCode::RunawayAcceleration);
  EXPECT_EQ(s.element, "hinge");
  EXPECT_GT(s.value, 1e5);
  EXPECT_EQ(p.position(0), q);
  EXPECT_EQ(p.velocity(0), v);
  EXPECT_EQ(p.time(), 0.0);
}


TEST(PhysicsChecks, NonFiniteStateIsReportedNotSilentlyReset) {
  Physics p(test::build(test::pendulum_urdf(1.0, 1.0, 1e-3)));
  p.set_joint_state(0, 0.0, std::numeric_limits<double>::quiet_NaN());
  const StepStatus s = p.step();
  EXPECT_EQ(s.code, StepCode::NonFiniteState);
  EXPECT_EQ(s.element, "hinge");
  EXPECT_TRUE(std::isnan(p.velocity(0)));  // left as it was, for the caller to inspect
}

TEST(PhysicsChecks, NonFiniteBaseStateNamesTheFloatingBody) {
  Physics p(test::build(test::box_urdf()));
  description::Pose X;
  X.position.z = std::numeric_limits<double>::quiet_NaN();
  p.set_base_pose(X);
  const StepStatus s = p.step();
  EXPECT_EQ(s.code, StepCode::NonFiniteState);
  EXPECT_EQ(s.element, "box");
}

}  // namespace
}  // namespace mechsim::physics
