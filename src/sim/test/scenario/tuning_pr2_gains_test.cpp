// The PR2's shipped arm, head, torso and laser tilt gains (robots/pr2/config/controllers.yaml,
// set with `mechsim tune`) meet their targets in the same experiments `mechsim tune` runs on
// mechsim's own description: a step from rest settles (2 %) within 0.3 s with under 5 %
// overshoot (0.3 rad; shoulders 0.6 s, their effort limit saturates; torso 0.02 m within 2 s,
// its velocity limit takes 1.54 s). And the trajectory controllers carry the same gains as the
// single-joint position controllers. The left arm mirrors the right and is left to the YAML
// consistency check (one arm's experiments already take seconds).

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <ostream>
#include <string>

#include "control/params.hpp"
#include "description/robot_loader.hpp"
#include "sim/tuning.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

const fs::path kPr2 = fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2";

control::Params pr2_controllers() {
  return control::Params::from_yaml_file((kPr2 / "config/controllers.yaml").string()).child("pr2");
}

struct StepCase {
  const char* joint;
  double step;    // rad or m; elbow and wrist flex rest at their upper soft limit: negative
  double settle;  // s
  double observe; // s after the step
};

void PrintTo(const StepCase& c, std::ostream* os) { *os << c.joint << " step " << c.step; }

class Pr2ShippedGains : public testing::TestWithParam<StepCase> {};

TEST_P(Pr2ShippedGains, StepMeetsTheTuningTargets) {
  const StepCase& c = GetParam();
  description::LoadOptions load;
  load.packages["mechsim_pr2"] = kPr2.string();
  TuneSetup setup;
  setup.robot = description::load_robot((kPr2 / "urdf/pr2.urdf.xacro").string(), load).model;
  setup.controllers_file = (kPr2 / "config/controllers.yaml").string();
  setup.controllers_namespace = "pr2";
  setup.joint = c.joint;
  setup.step = c.step;
  setup.observe = c.observe;
  std::string controller = c.joint;
  controller = controller.substr(0, controller.size() - std::string("_joint").size()) + "_position_controller";
  const control::Params pid = pr2_controllers().child(controller).child("pid");
  const control::PidGains gains{pid.get<double>("p"), pid.get<double>("i", 0.0), pid.get<double>("d", 0.0)};
  const StepMetrics m = measure_step(setup, controller, false, gains);
  std::cout << "[ figures  ] " << c.joint << " step " << c.step << ": settles at " << m.settling_time << " s, overshoot "
            << m.overshoot << " %, final error " << m.steady_state_error << "\n";
  ASSERT_FALSE(m.diverged);
  EXPECT_GE(m.settling_time, 0.0) << "never settled";
  EXPECT_LE(m.settling_time, c.settle);
  EXPECT_LT(m.overshoot, 5.0);
}

INSTANTIATE_TEST_SUITE_P(
    RightArmHeadTorsoLaser, Pr2ShippedGains,
    testing::Values(StepCase{"r_shoulder_pan_joint", 0.3, 0.6, 1.0}, StepCase{"r_shoulder_lift_joint", 0.3, 0.6, 1.0},
                    StepCase{"r_upper_arm_roll_joint", 0.3, 0.3, 1.0}, StepCase{"r_elbow_flex_joint", -0.3, 0.3, 1.0},
                    StepCase{"r_forearm_roll_joint", 0.3, 0.3, 1.0}, StepCase{"r_wrist_flex_joint", -0.3, 0.3, 1.0},
                    StepCase{"r_wrist_roll_joint", 0.3, 0.3, 1.0}, StepCase{"head_pan_joint", 0.3, 0.3, 1.0},
                    StepCase{"head_tilt_joint", 0.3, 0.3, 1.0}, StepCase{"laser_tilt_mount_joint", 0.3, 0.3, 1.0},
                    StepCase{"torso_lift_joint", 0.02, 2.0, 3.0}),
    [](const testing::TestParamInfo<StepCase>& param) { return std::string(param.param.joint); });

TEST(Pr2ShippedGainsYaml, TrajectoryControllersCarryThePositionControllersGains) {
  const control::Params ns = pr2_controllers();
  int compared = 0;
  for (const char* group : {"r_arm_controller", "l_arm_controller", "head_traj_controller", "torso_controller"}) {
    const control::Params gains = ns.child(group).child("gains");
    for (const std::string& joint : gains.keys()) {
      const std::string controller = joint.substr(0, joint.size() - std::string("_joint").size()) + "_position_controller";
      ASSERT_TRUE(ns.has(controller)) << controller;
      const control::Params a = gains.child(joint), b = ns.child(controller).child("pid");
      for (const char* key : {"p", "i", "d", "i_clamp"}) {
        EXPECT_EQ(a.get<double>(key, 0.0), b.get<double>(key, 0.0)) << group << " " << joint << " " << key;
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 17);  // 14 arm joints, head pan and tilt, torso
  EXPECT_EQ(ns.child("laser_tilt_controller").child("pid").get<double>("p"),
            ns.child("laser_tilt_mount_position_controller").child("pid").get<double>("p"));
  EXPECT_EQ(ns.child("laser_tilt_controller").child("pid").get<double>("d"),
            ns.child("laser_tilt_mount_position_controller").child("pid").get<double>("d"));
}

}  // namespace
}  // namespace mechsim::sim
