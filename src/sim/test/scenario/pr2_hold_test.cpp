// The real PR2 (reference expansion of pr2_description) spawns on the empty world and holds its
// posture with position PIDs on every arm, torso and head joint for 10 s.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "control/params.hpp"
#include "description/urdf_parser.hpp"
#include "sim/simulation.hpp"
#include "sim/test/scenario/pr2_util.hpp"
#include "sim/test/scenario/scenario_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

struct Gains {
  const char* joint;
  double p, i, d, i_clamp;
};

// Position gains of the PR2 simulation's joint controllers (robot_mechanism_controllers).
constexpr Gains kPr2Gains[] = {
    {"torso_lift_joint", 100000.0, 1000.0, 5000.0, 1000.0},
    {"head_pan_joint", 20.0, 0.0, 2.0, 0.0},
    {"head_tilt_joint", 60.0, 0.0, 4.0, 0.0},
    {"laser_tilt_mount_joint", 10.0, 0.0, 0.5, 0.0},
    {"shoulder_pan_joint", 2400.0, 800.0, 18.0, 4.0},
    {"shoulder_lift_joint", 1200.0, 700.0, 10.0, 4.0},
    {"upper_arm_roll_joint", 1000.0, 600.0, 6.0, 4.0},
    {"elbow_flex_joint", 700.0, 450.0, 4.0, 4.0},
    {"forearm_roll_joint", 300.0, 300.0, 6.0, 2.0},
    {"wrist_flex_joint", 300.0, 300.0, 4.0, 2.0},
    {"wrist_roll_joint", 300.0, 300.0, 4.0, 2.0},
};

std::string pr2_posture_yaml(std::vector<std::string>& names) {
  std::ostringstream yaml;
  auto add = [&](const std::string& joint, const Gains& g) {
    const std::string name = joint + "_position_controller";
    names.push_back(name);
    yaml << name << ":\n  type: robot_mechanism_controllers/JointPositionController\n  joint: " << joint
         << "\n  pid: {p: " << g.p << ", i: " << g.i << ", d: " << g.d << ", i_clamp: " << g.i_clamp << "}\n";
  };
  for (const Gains& g : kPr2Gains) {
    const std::string joint = g.joint;
    if (joint.find("shoulder") != std::string::npos || joint.find("arm") != std::string::npos ||
        joint.find("elbow") != std::string::npos || joint.find("wrist") != std::string::npos) {
      add("r_" + joint, g);
      add("l_" + joint, g);
    } else {
      add(joint, g);
    }
  }
  return yaml.str();
}

TEST(Pr2Scenario, HoldsItsPostureWithPositionControllers) {
  const fs::path shared = MECHSIM_SHARED_DIR;
  if (!fs::exists(shared / "robots/reference/pr2.urdf")) GTEST_SKIP() << "shared data absent: " << shared;
  description::UrdfOptions urdf_options;
  urdf_options.lenient = true;  // two sensor mounts break the triangle inequality
  urdf_options.packages["pr2_description"] = (shared / "robots/pr2_description").string();
  description::RobotModel pr2 =
      description::parse_urdf_file((shared / "robots/reference/pr2.urdf").string(), urdf_options);

  std::vector<std::string> names;
  const control::Params params = control::Params::from_yaml_string(pr2_posture_yaml(names), "pr2 posture");
  SimulationOptions options;
  options.spawn.z = 0.01;
  options.integrator = pr2_test_integrator();
  Simulation sim(std::move(pr2), make_world({}), params, options);
  sim.load_and_start(names);
  ASSERT_TRUE(sim.run_for(1.0));

  // Record every controlled joint's position after settling, then hold for 10 s.
  std::vector<std::size_t> joints;
  std::vector<double> start;
  for (const std::string& name : names) {
    const std::string joint = name.substr(0, name.size() - std::string("_position_controller").size());
    const auto j = sim.physics().model().joint_index(joint);
    ASSERT_TRUE(j) << joint;
    joints.push_back(*j);
    start.push_back(sim.physics().position(*j));
  }
  double worst = 0.0;
  std::string worst_joint;
  double max_tilt = 0.0;
  sim.add_observer([&](const Simulation& s) {
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const double drift = std::abs(s.physics().position(joints[k]) - start[k]);
      if (drift > worst) {
        worst = drift;
        worst_joint = names[k];
      }
    }
    max_tilt = std::max(max_tilt, tilt_of(s.physics().base_pose().orientation));
  });
  const TickResult r = sim.run_for(10.0);
  ASSERT_TRUE(r) << r.error;
  std::cout << "[ figures  ] PR2: worst joint drift over 10 s " << worst << " (" << worst_joint << "), max base tilt "
            << max_tilt << " rad, real-time factor " << sim.measured_real_time_factor() << "\n";
  EXPECT_LT(worst, 0.05) << worst_joint;
  EXPECT_LT(max_tilt, 0.02);
  for (const control::ControllerInfo& info : sim.controllers().list_controllers()) {
    EXPECT_EQ(info.state, control::ControllerLifecycle::Running) << info.name << ": " << info.failure;
  }
}

}  // namespace
}  // namespace mechsim::sim
