// PID tables: the gains, error sequences and expected commands below are the published values
// of control_toolbox's unit tests (ros-controls/control_toolbox, test/pid_tests.cpp, ROS 1
// melodic/noetic branch; negativeIntegrationAntiwindupTest as updated in 1.17.0), restated
// as data. Pid(p, i, d, i_max, i_min, antiwindup) follows control_toolbox's argument order.

#include "control/pid.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace mechsim::control {
namespace {

struct Step {
  double error;
  double dt;
  double expected;
};

void run_table(Pid& pid, std::initializer_list<Step> steps) {
  int n = 0;
  for (const Step& s : steps) {
    EXPECT_DOUBLE_EQ(pid.compute_command(s.error, s.dt), s.expected) << "step " << n;
    ++n;
  }
}

TEST(PidTable, ITermBadIBoundsTest) {
  // i_max = -1 < i_min = 1: the output must stay finite.
  Pid pid(1.0, 1.0, 1.0, -1.0, 1.0);
  for (int k = 0; k < 2; ++k) {
    double cmd = pid.compute_command(-1.0, 1.0);
    EXPECT_FALSE(std::isinf(pid.current_errors().i));
    EXPECT_FALSE(std::isnan(cmd));
  }
}

TEST(PidTable, ZeroITermBadIBoundsTest) {
  Pid pid(1.0, 0.0, 0.0, -1.0, 0.0);
  for (int k = 0; k < 2; ++k) {
    double cmd = pid.compute_command(-1.0, 1.0);
    EXPECT_FALSE(std::isinf(pid.current_errors().i));
    EXPECT_FALSE(std::isnan(cmd));
  }
}

TEST(PidTable, IntegrationClampTest) {
  Pid pid(0.0, 1.0, 0.0, 1.0, -1.0);
  run_table(pid, {{-10.03, 1.0, -1.0}, {30.0, 1.0, 1.0}});
}

TEST(PidTable, IntegrationClampZeroGainTest) {
  Pid pid(0.0, 0.0, 0.0, 1.0, -1.0);
  run_table(pid, {{-1.0, 1.0, 0.0}, {-1.0, 1.0, 0.0}});
}

TEST(PidTable, IntegrationAntiwindupTest) {
  Pid pid(0.0, 2.0, 0.0, 1.0, -1.0, true);
  run_table(pid, {{-1.0, 1.0, -1.0}, {-1.0, 1.0, -1.0}, {0.5, 1.0, 0.0}, {-1.0, 1.0, -1.0}});
}

TEST(PidTable, NegativeIntegrationAntiwindupTest) {
  Pid pid(0.0, -2.5, 0.0, 0.5, -0.2, true);
  run_table(pid, {{0.1, 1.0, -0.2}, {0.1, 1.0, -0.2}, {-0.05, 1.0, -0.075}, {0.1, 1.0, -0.2}});
}

TEST(PidTable, NegativeIntegrationAntiwindupBeforeTest1_17) {
  // The pre-1.17 table (i = -2, bounds +-1) holds as well under the 1.17 clamping.
  Pid pid(0.0, -2.0, 0.0, 1.0, -1.0, true);
  run_table(pid, {{-1.0, 1.0, 1.0}, {-1.0, 1.0, 1.0}, {0.5, 1.0, 0.0}, {-1.0, 1.0, 1.0}});
}

TEST(PidTable, GainSettingCopyPIDTest) {
  Pid pid1(12.0, 34.0, 56.0, 78.0, -9.0, false);
  EXPECT_EQ(pid1.gains(), (PidGains{12.0, 34.0, 56.0, 78.0, -9.0, false}));
  pid1.set_gains(21.0, 43.0, 65.0, 87.0, -19.0, false);
  EXPECT_EQ(pid1.gains(), (PidGains{21.0, 43.0, 65.0, 87.0, -19.0, false}));

  pid1.set_current_command(10);
  (void)pid1.compute_command(20, 1.0);
  EXPECT_NE(pid1.current_errors().p, 0.0);

  Pid pid2(pid1);
  EXPECT_EQ(pid2.gains(), pid1.gains());
  EXPECT_EQ(pid2.current_errors().p, 0.0);
  EXPECT_EQ(pid2.current_errors().i, 0.0);
  EXPECT_EQ(pid2.current_errors().d, 0.0);

  Pid pid3;
  pid3 = pid1;
  EXPECT_EQ(pid3.gains(), pid1.gains());
  EXPECT_EQ(pid3.current_errors().i, 0.0);

  pid1.reset();
  EXPECT_EQ(pid1.current_errors().p, 0.0);
  EXPECT_EQ(pid1.current_errors().i, 0.0);
  EXPECT_EQ(pid1.current_errors().d, 0.0);
  EXPECT_EQ(pid1.current_command(), 0.0);
}

TEST(PidTable, ProportionalOnlyTest) {
  Pid pid(1.0, 0.0, 0.0, 0.0, 0.0);
  run_table(pid, {{-0.5, 1.0, -0.5}, {-0.5, 1.0, -0.5}, {-1.0, 1.0, -1.0}, {0.5, 1.0, 0.5}});
}

TEST(PidTable, IntegralOnlyTest) {
  Pid pid(0.0, 1.0, 0.0, 5.0, -5.0);
  run_table(pid, {{-0.5, 1.0, -0.5}, {-0.5, 1.0, -1.0}, {0.0, 1.0, -1.0}, {0.0, 1.0, -1.0}, {1.0, 1.0, 0.0}});
  // reset() clears the integral, reset(true) keeps it.
  run_table(pid, {{-0.5, 1.0, -0.5}});
  pid.reset();
  run_table(pid, {{0.0, 1.0, 0.0}, {-0.5, 1.0, -0.5}});
  pid.reset(true);
  run_table(pid, {{0.0, 1.0, -0.5}});
}

TEST(PidTable, DerivativeOnlyTest) {
  Pid pid(0.0, 0.0, 1.0, 0.0, 0.0);
  run_table(pid, {{-0.5, 1.0, -0.5}, {-0.5, 1.0, 0.0}, {-0.5, 0.1, 0.0}, {-1.0, 1.0, -0.5}, {-0.5, 1.0, 0.5}});
}

TEST(PidTable, CompletePIDTest) {
  Pid pid(1.0, 1.0, 1.0, 5.0, -5.0);
  run_table(pid, {{-0.5, 1.0, -1.5}, {-0.5, 1.0, -1.5}, {-1.0, 1.0, -3.5}});
}

TEST(PidTable, GivenErrorDotUpdatesTheIntegralWithDt) {
  // control_toolbox timeArgumentTest: with error_dot given as 0, p and i still act.
  Pid pid(1.0, 1.0, 1.0, 5.0, -5.0);
  EXPECT_DOUBLE_EQ(pid.compute_command(-0.5, 1.0), -1.5);
  EXPECT_DOUBLE_EQ(pid.compute_command(-0.5, 0.0, 1.0), -1.5);
  EXPECT_DOUBLE_EQ(pid.compute_command(-0.5, 0.0, 1.0), -2.0);
}

TEST(Pid, BadDtOrNonFiniteInputReturnsZeroWithoutCorruptingState) {
  Pid pid(1.0, 1.0, 1.0, 5.0, -5.0);
  EXPECT_DOUBLE_EQ(pid.compute_command(-0.5, 1.0), -1.5);
  const auto before = pid.current_errors();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(pid.compute_command(-0.5, 0.0), 0.0);
  EXPECT_EQ(pid.compute_command(-0.5, -1.0), 0.0);
  EXPECT_EQ(pid.compute_command(nan, 1.0), 0.0);
  EXPECT_EQ(pid.compute_command(inf, 1.0), 0.0);
  EXPECT_EQ(pid.compute_command(-0.5, nan, 1.0), 0.0);
  EXPECT_EQ(pid.compute_command(-0.5, 0.0, nan), 0.0);
  EXPECT_EQ(pid.current_errors().p, before.p);
  EXPECT_EQ(pid.current_errors().i, before.i);
  EXPECT_EQ(pid.current_errors().d, before.d);
  // The next good step continues as if the bad calls never happened.
  EXPECT_DOUBLE_EQ(pid.compute_command(-0.5, 1.0), -1.5);
}

TEST(Pid, InitFromParamsFollowsControlToolbox) {
  Params root = Params::from_yaml_string(R"(
a: {p: 1.0, i: 0.001, d: 0.01}
b: {p: 2, i: 3, i_clamp: -4, antiwindup: true}
c: {p: 2, i_clamp: 4, i_clamp_min: 1, i_clamp_max: -7}
d: {i: 3}
e: {p: fast}
)", "pid.yaml");
  EXPECT_EQ(Pid::gains_from_params(root.child("a")), (PidGains{1.0, 0.001, 0.01, 0.0, 0.0, false}));
  EXPECT_EQ(Pid::gains_from_params(root.child("b")), (PidGains{2.0, 3.0, 0.0, 4.0, -4.0, true}));
  EXPECT_EQ(Pid::gains_from_params(root.child("c")), (PidGains{2.0, 0.0, 0.0, 7.0, -1.0, false}));
  try {
    (void)Pid::gains_from_params(root.child("d"));
    FAIL();
  } catch (const ParamsError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("No p gain specified for pid. Namespace: /d"));
  }
  try {
    Pid pid;
    pid.init(root.child("e"));
    FAIL();
  } catch (const ParamsError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("/e/p: expected a number"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("pid.yaml:6"));
  }
}

TEST(Pid, GainsChangeSafelyWhileRunning) {
  Pid pid(1.0, 0.0, 0.0, 0.0, 0.0);
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (int k = 0; k < 20000; ++k) pid.set_gains(k % 2 == 0 ? 2.0 : 3.0, 0.0, 0.0, 0.0, 0.0);
    pid.set_gains(4.0, 0.0, 0.0, 0.0, 0.0);
    done = true;
  });
  // Every command must come from one consistent gain set: p in {1, 2, 3, 4}.
  while (!done) {
    const double cmd = pid.compute_command(1.0, 0.001);
    EXPECT_TRUE(cmd == 1.0 || cmd == 2.0 || cmd == 3.0 || cmd == 4.0) << cmd;
  }
  writer.join();
  EXPECT_DOUBLE_EQ(pid.compute_command(1.0, 0.001), 4.0);
}

}  // namespace
}  // namespace mechsim::control
