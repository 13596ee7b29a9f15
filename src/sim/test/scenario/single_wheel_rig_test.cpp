// The single-wheel test rig (robots/single_wheel_rig) in the sand of Pavlov and Johnson's tests:
// the shipped soil is what `mechsim soil fit` makes of the shared CMU plate tests; run at a test
// rig's 10 mm/s over slip 0-0.75, the rig's drawbar pull and sinkage have the published shape
// (DP < 0 at slip 0, rising with slip, crossing zero at low slip; sinkage rising with slip), and a
// narrow wheel (b <= r) and a wide one on the same soil each settle on the steady model for their
// own width: they differ by what their width explains.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "physics/terramechanics.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/soil_config.hpp"
#include "sim/soil_fit_report.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

const fs::path kRig = fs::path(MECHSIM_SOURCE_DIR) / "robots/single_wheel_rig";

TEST(SingleWheelRig, TheShippedSoilIsWhatSoilFitMakesOfTheSharedPlateTests) {
  const fs::path samples = fs::path(MECHSIM_SHARED_DIR) / "soil/cmu_plate_sinkage/samples";
  if (!fs::exists(samples)) GTEST_SKIP() << "shared data not found at " << samples << " (MECHSIM_SHARED_DIR): the CMU plate tests";
  const SoilFitSpec spec = read_soil_fit_spec((kRig / "soil/cmu_sand_plates.yaml").string());
  ASSERT_EQ(spec.plates.size(), 9u);
  const SoilFitOutcome fit = run_soil_fit(spec, "", false);
  const physics::SoilParameters shipped = soil_by_name((kRig / "soil/cmu_sand.soil.yaml").string());
  EXPECT_NEAR(shipped.n, fit.soil.n, 1e-5);
  EXPECT_NEAR(shipped.k_c, fit.soil.k_c, 1e-5 * std::abs(fit.soil.k_c));
  EXPECT_NEAR(shipped.k_phi, fit.soil.k_phi, 1e-5 * fit.soil.k_phi);
  EXPECT_EQ(shipped.model, physics::WheelSoilModel::Ding);
  // What the plates do not give comes from dry sand (Wong's table), nothing from wheel tests.
  const physics::SoilParameters dry = *physics::find_soil("dry_sand");
  EXPECT_EQ(shipped.cohesion, dry.cohesion);
  EXPECT_EQ(shipped.friction_angle, dry.friction_angle);
  EXPECT_EQ(shipped.shear_modulus, dry.shear_modulus);
  EXPECT_EQ(shipped.rear_ratio, physics::SoilParameters{}.rear_ratio);
}

ScenarioResult run_rig(const char* name) {
  const Scenario s = load_scenario((kRig / "scenarios" / name).string());
  const ScenarioResult r = run_scenario(s, RunOptions{});
  EXPECT_TRUE(r.completed) << name << ": " << r.error;
  EXPECT_TRUE(r.passed) << name << ": the slips are the set ones";
  return r;
}

TEST(SingleWheelRig, DrawbarPullAndSinkageAgainstSlipHaveThePublishedShapeForNarrowAndWideWheels) {
  const physics::SoilParameters soil = soil_by_name((kRig / "soil/cmu_sand.soil.yaml").string());
  std::vector<double> narrow_sinkage;
  for (const auto& [name, width] : {std::pair{"slip_sweep.yaml", 0.05}, std::pair{"slip_sweep_wide.yaml", 0.10}}) {
    const ScenarioResult r = run_rig(name);
    ASSERT_EQ(r.wheels.size(), 1u) << name << ": the wheel is a soil wheel, narrow or not";
    EXPECT_EQ(r.wheels[0].narrow, width <= 0.058);
    EXPECT_TRUE(r.not_wheels.empty());
    ASSERT_EQ(r.steady_states.size(), 8u);
    double crossing = -1.0;
    for (std::size_t k = 0; k < r.steady_states.size(); ++k) {
      const SteadyStateRow& row = r.steady_states[k];
      const double dpw = row.drawbar / row.load;
      const physics::SteadyWheel model = physics::steady_wheel(soil, {0.058, width}, row.load, row.slip);
      std::printf("[ figures  ] b %.2f m, slip %.3f: DP/W %.4f (steady model %.4f), torque %.4f N m (%.4f), sinkage %.2f mm (%.2f)\n",
                  width, row.slip, dpw, model.forces.drawbar / row.load, row.torque, model.forces.torque, 1000 * row.sinkage,
                  1000 * model.sinkage);
      EXPECT_NEAR(row.load, 25.0, 0.25);
      // Each wheel on the steady model of its own width: what differs is what the width explains.
      EXPECT_NEAR(row.sinkage, model.sinkage, 0.05 * model.sinkage) << name << " slip " << row.slip;
      EXPECT_NEAR(row.drawbar, model.forces.drawbar, 0.1 * std::abs(model.forces.drawbar) + 0.01 * row.load) << name << " slip " << row.slip;
      if (k == 0) {
        EXPECT_LT(dpw, -0.05) << name << ": at slip 0 the wheel is pushed back (compaction resistance)";
        continue;
      }
      const SteadyStateRow& before = r.steady_states[k - 1];
      EXPECT_GT(row.sinkage, before.sinkage) << name << ": sinkage rises with slip";
      if (row.slip <= 0.45 + 1e-3) {
        EXPECT_GT(dpw, before.drawbar / before.load) << name << ": DP/W rises with slip";
      }
      if (crossing < 0.0 && dpw > 0.0 && before.drawbar < 0.0)
        crossing = before.slip + (row.slip - before.slip) * (-before.drawbar / before.load) / (dpw - before.drawbar / before.load);
      if (width <= 0.058) narrow_sinkage.push_back(row.sinkage);
    }
    std::printf("[ figures  ] b %.2f m: DP crosses zero at slip %.3f\n", width, crossing);
    EXPECT_GT(crossing, 0.05) << name;
    EXPECT_LT(crossing, 0.3) << name << ": a low slip";
    if (width > 0.058) {
      // The wide wheel sinks less: 25 N over twice the width.
      for (std::size_t k = 1; k < r.steady_states.size(); ++k) EXPECT_LT(r.steady_states[k].sinkage, narrow_sinkage[k - 1]);
    }
  }
}

}  // namespace
}  // namespace mechsim::sim
