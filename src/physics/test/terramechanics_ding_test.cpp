// The Ding et al. wheel-soil model (physics/terramechanics.hpp, SoilParameters::model) and
// grousers: it is Wong and Reece's without rear contact and slip sinkage; the rear contact sits
// where the rebound says and carries load behind the lowest point, so the wheel sinks less and
// meets less compaction resistance; slip sinkage sinks a slipping wheel further; grousers shear
// at their tips. A negative k_c (plate fits in sand) is accepted where k_c / b + k_phi > 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/soil.hpp"
#include "physics/terramechanics.hpp"

namespace mechsim::physics {
namespace {

// The plate fit of the CMU sand's large box (two_stage, ../shared/soil/cmu_plate_sinkage) with
// dry sand's shear values: the soil of the single-wheel rig.
SoilParameters sand(WheelSoilModel model) {
  SoilParameters s = *find_soil("dry_sand");
  s.n = 1.4765;
  s.k_c = -4.0648e5;
  s.k_phi = 1.973e7;
  s.model = model;
  return s;
}

TEST(TerramechanicsDing, WithoutRearContactOrSlipSinkageItIsWongReece) {
  SoilParameters ding = sand(WheelSoilModel::Ding);
  ding.rear_ratio = 0.0;
  const SoilParameters wr = sand(WheelSoilModel::WongReece);
  const WheelShape wheel{0.058, 0.05};
  for (const double z : {0.005, 0.015, 0.03})
    for (const double s : {-0.3, 0.0, 0.2, 0.6}) {
      const WheelSoilForces a = wheel_soil_forces(ding, wheel, z, s, 0.001, 1.0);
      const WheelSoilForces b = wheel_soil_forces(wr, wheel, z, s, 0.001, 1.0);
      EXPECT_NEAR(a.normal, b.normal, 1e-9 * b.normal) << "z " << z << " s " << s;
      EXPECT_NEAR(a.drawbar, b.drawbar, 1e-9 * b.normal);
      EXPECT_NEAR(a.torque, b.torque, 1e-9 * std::abs(b.torque) + 1e-12);
      EXPECT_NEAR(a.lateral, b.lateral, 1e-9 * b.normal);
    }
}

TEST(TerramechanicsDing, RearContactCarriesLoadBehindTheLowestPointAndCutsTheResistance) {
  const SoilParameters ding = sand(WheelSoilModel::Ding);
  const SoilParameters wr = sand(WheelSoilModel::WongReece);
  const WheelShape wheel{0.058, 0.05};
  const double z = 0.016;
  const WheelSoilForces f = wheel_soil_forces(ding, wheel, z, 0.2);
  EXPECT_NEAR(f.exit_angle, -std::acos(1.0 - ding.rear_ratio * z / wheel.radius), 1e-12);
  EXPECT_NEAR(f.entry_angle, std::acos(1.0 - z / wheel.radius), 1e-12);
  // A millimetre of rebound under a 58 mm wheel: a rear arc of about a fifth of the front's.
  EXPECT_GT(-f.exit_angle, 0.2 * f.entry_angle);
  const WheelSoilForces g = wheel_soil_forces(wr, wheel, z, 0.2);
  EXPECT_GT(f.normal, g.normal) << "the rear arc carries load too";
  for (const double slip : {0.0, 0.2, 0.5}) {
    const SteadyWheel a = steady_wheel(ding, wheel, 25.0, slip), b = steady_wheel(wr, wheel, 25.0, slip);
    ASSERT_TRUE(a.ok && b.ok);
    std::printf("[ figures  ] 25 N, slip %.1f: ding sinkage %.2f mm, DP/W %.3f, R/W %.3f; wong_reece %.2f mm, %.3f, %.3f\n", slip,
                1000 * a.sinkage, a.forces.drawbar / 25.0, a.forces.resistance / 25.0, 1000 * b.sinkage, b.forces.drawbar / 25.0,
                b.forces.resistance / 25.0);
    EXPECT_LT(a.sinkage, b.sinkage);
    EXPECT_LT(a.forces.resistance, 0.85 * b.forces.resistance);
    EXPECT_GT(a.forces.drawbar, b.forces.drawbar);
  }
}

TEST(TerramechanicsDing, SlipSinkageSinksASlippingWheelFurther) {
  SoilParameters with = sand(WheelSoilModel::Ding);
  with.n1 = 0.4;
  with.n2 = 0.3;
  const SoilParameters without = sand(WheelSoilModel::Ding);
  const WheelShape wheel{0.058, 0.05};
  const SteadyWheel a0 = steady_wheel(with, wheel, 25.0, 0.0), b0 = steady_wheel(without, wheel, 25.0, 0.0);
  EXPECT_NEAR(a0.sinkage, b0.sinkage, 1e-9) << "no slip, no slip sinkage";
  double last = a0.sinkage;
  for (const double slip : {0.2, 0.5, 0.75}) {
    const SteadyWheel a = steady_wheel(with, wheel, 25.0, slip), b = steady_wheel(without, wheel, 25.0, slip);
    EXPECT_GT(a.sinkage, 1.03 * b.sinkage) << "slip " << slip;
    EXPECT_GT(a.sinkage, last);
    last = a.sinkage;
  }
  EXPECT_GT(steady_wheel(with, wheel, 25.0, -0.5).sinkage, 1.03 * steady_wheel(without, wheel, 25.0, -0.5).sinkage) << "skid: n2";
  // The exponent's own units: the stress at the plate's own depth b is (k_c / b + k_phi) b^n for
  // any exponent (Reece's dimensionless form), so slip sinkage is the same in any unit of length.
  const double b = wheel.width;
  const double at_b = bekker_modulus(with, b) * std::pow(b, with.n);
  EXPECT_NEAR(at_b * std::pow(1.0, with.n + with.n1 * 0.5), at_b, 1e-9 * at_b);
}

TEST(TerramechanicsDing, GrousersShearTheSoilAtTheirTips) {
  const SoilParameters soil = sand(WheelSoilModel::Ding);
  const WheelShape smooth{0.058, 0.05};
  WheelShape lugged = smooth;
  lugged.grouser_height = 0.005;
  lugged.grouser_count = 16;
  const double z = 0.015;
  const WheelSoilForces a = wheel_soil_forces(soil, smooth, z, 0.1), b = wheel_soil_forces(soil, lugged, z, 0.1);
  EXPECT_DOUBLE_EQ(a.shear_radius, smooth.radius);
  // 16 grousers: one every 22.5 deg, fewer than the contact's ~55 deg: fully effective.
  EXPECT_NEAR(b.shear_radius, smooth.radius + 0.005, 1e-12);
  EXPECT_GT(b.drawbar, a.drawbar + 0.02 * a.normal) << "more shear displacement: more thrust";
  EXPECT_LT(b.torque, a.torque) << "and more torque to turn it";
  WheelShape sparse = lugged;
  sparse.grouser_count = 2;  // one every 180 deg: engaged a fraction of the time
  const WheelSoilForces c = wheel_soil_forces(soil, sparse, z, 0.1);
  EXPECT_GT(c.shear_radius, smooth.radius);
  EXPECT_LT(c.shear_radius, lugged.radius + 0.5 * lugged.grouser_height);
  // At rest (no rolling) grousers add nothing: only slip shears.
  EXPECT_NEAR(wheel_soil_forces(soil, lugged, z, 0.0, 0.0, 0.0).drawbar, wheel_soil_forces(soil, smooth, z, 0.0, 0.0, 0.0).drawbar, 1e-9);
}

TEST(TerramechanicsDing, ANegativeKcHoldsForWheelsWideEnough) {
  SoilParameters soil = sand(WheelSoilModel::Ding);
  EXPECT_EQ(check_soil(soil), "");
  EXPECT_EQ(check_soil_width(soil, 0.05), "");
  EXPECT_EQ(check_soil_width(soil, 0.03), "");
  const std::string narrow = check_soil_width(soil, 0.015);
  EXPECT_NE(narrow.find("0.0206"), std::string::npos) << narrow;  // -k_c / k_phi
  soil.k_phi = 0.0;
  EXPECT_NE(check_soil(soil).find("k_phi"), std::string::npos);
  soil = sand(WheelSoilModel::Ding);
  soil.rear_ratio = 1.5;
  EXPECT_NE(check_soil(soil).find("rear ratio"), std::string::npos);
  soil.rear_ratio = 0.05;
  soil.n1 = -1.6;
  EXPECT_NE(check_soil(soil).find("n1"), std::string::npos);
  EXPECT_EQ(find_model("ding"), WheelSoilModel::Ding);
  EXPECT_EQ(find_model("wong_reece"), WheelSoilModel::WongReece);
  EXPECT_FALSE(find_model("bekker"));
}

}  // namespace
}  // namespace mechsim::physics
