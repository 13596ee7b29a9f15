// The CC8's shipped gains (robots/cc8/config/controllers.yaml) meet the targets in the
// same experiments `mechsim tune` runs: a 0.5 rad steering step on the ground settles (2 %) within
// 0.3 s with under 5 % overshoot; a wheel velocity step reaches 95 % within 0.2 s.

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include "control/params.hpp"
#include "description/robot_loader.hpp"
#include "sim/tuning.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

TuneSetup cc8_setup(const std::string& joint) {
  const fs::path cc8 = fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8";
  description::LoadOptions load;
  load.packages["mechsim_cc8"] = cc8.string();
  TuneSetup setup;
  setup.robot = description::load_robot((cc8 / "urdf/cc8.urdf.xacro").string(), load).model;
  setup.controllers_file = (cc8 / "config/controllers.yaml").string();
  setup.controllers_namespace = "cc8";
  setup.joint = joint;
  return setup;
}

control::PidGains shipped_gains(const TuneSetup& setup, const std::string& controller) {
  const control::Params pid =
      control::Params::from_yaml_file(setup.controllers_file).child("cc8").child(controller).child("pid");
  control::PidGains g;
  g.p = pid.get<double>("p");
  g.i = pid.get<double>("i", 0.0);
  g.d = pid.get<double>("d", 0.0);
  return g;
}

TEST(Cc8Gains, SteeringStepSettlesWithin300msUnder5PercentOvershoot) {
  const TuneSetup setup = cc8_setup("steering_FL");
  const StepMetrics m = measure_step(setup, "steering_FL_position_controller", false,
                                     shipped_gains(setup, "steering_FL_position_controller"));
  std::cout << "[ figures  ] steering 0.5 rad step: settles at " << m.settling_time << " s, overshoot " << m.overshoot
            << " %, peak effort " << m.peak_effort << " N m\n";
  ASSERT_FALSE(m.diverged);
  EXPECT_GE(m.settling_time, 0.0) << "never settled";
  EXPECT_LE(m.settling_time, 0.3);
  EXPECT_LT(m.overshoot, 5.0);
}

TEST(Cc8Gains, WheelVelocityStepReaches95PercentWithin200ms) {
  const TuneSetup setup = cc8_setup("wheel_joint_FL");
  const StepMetrics m = measure_step(setup, "wheel_joint_FL_velocity_controller", true,
                                     shipped_gains(setup, "wheel_joint_FL_velocity_controller"));
  std::cout << "[ figures  ] wheel 2 rad/s step: 95 % at " << m.rise95 << " s, overshoot " << m.overshoot
            << " %, final error " << m.steady_state_error << " rad/s\n";
  ASSERT_FALSE(m.diverged);
  EXPECT_GE(m.rise95, 0.0) << "never reached 95 %";
  EXPECT_LE(m.rise95, 0.2);
  EXPECT_LT(std::abs(m.steady_state_error), 0.04);
}

}  // namespace
}  // namespace mechsim::sim
