// The real PR2 (reference expansion of pr2_description) spawns on the empty world and holds its
// posture for 10 s with the shipped single-joint position controllers (robots/pr2/config/
// controllers.yaml, gains from `mechsim tune`) on every arm, torso and head joint.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "control/params.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"
#include "sim/test/scenario/pr2_util.hpp"
#include "sim/test/scenario/scenario_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

// The single-joint position controllers of the shipped controllers.yaml (robot_mechanism_
// controllers/JointPositionController, loaded but not started by default): every arm, torso and
// head joint and the laser tilt.
std::vector<std::string> shipped_position_controllers(const control::Params& pr2) {
  std::vector<std::string> names;
  for (const std::string& key : pr2.keys()) {
    const control::Params c = pr2.child(key);
    if (c.get<std::string>("type", "") == "robot_mechanism_controllers/JointPositionController") names.push_back(key);
  }
  return names;
}

TEST(Pr2Scenario, HoldsItsPostureWithPositionControllers) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  const control::Params root =
      control::Params::from_yaml_file((fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2/config/controllers.yaml").string());
  const std::vector<std::string> names = shipped_position_controllers(root.child("pr2"));
  ASSERT_EQ(names.size(), 18u);  // 14 arm joints, torso, head pan and tilt, laser tilt
  auto owned = make_pr2_simulation(names);
  Simulation& sim = *owned;
  ASSERT_TRUE(sim.run_for(1.0));

  // Record every controlled joint's position after settling, then hold for 10 s.
  std::vector<std::size_t> joints;
  std::vector<double> start;
  const control::Params pr2 = root.child("pr2");
  for (const std::string& name : names) {
    const std::string joint = pr2.child(name).get<std::string>("joint");
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
