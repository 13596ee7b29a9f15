// The Bekker-Wong wheel model (physics/terramechanics.hpp) against published closed forms and
// the properties Wong and Reece's analysis has: a towed rigid wheel's sinkage and compaction
// resistance as Bekker's formulas give them; drawbar pull, torque and sinkage rising with slip;
// a wheel at rest carrying only what its slip shears; lateral force against the slide; the named
// soils' values; bad values named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/soil.hpp"
#include "physics/terramechanics.hpp"

namespace mechsim::physics {
namespace {

// Bekker (Theory of Land Locomotion, 1956), as Wong gives it (Theory of Ground Vehicles, 4th ed.
// 2008, section 2.7, "Motion resistance of a rigid wheel"): a towed rigid wheel of diameter D and
// width b carrying W sinks z0 = [3 W / ((3 - n) b k sqrt(D))]^(2 / (2n + 1)), k = k_c / b + k_phi,
// and meets the compaction resistance R_c = b k z0^(n + 1) / (n + 1). The model with the stress
// peak at the bottom (c1 = c2 = 0), no slip and no rolling shear is the normal stress Bekker
// integrated; his closed form takes small angles (z / D small) and an approximate factor for n
// != 1, so the bounds are a few per cent and widen with z / D.
TEST(Terramechanics, ATowedWheelSinksAndResistsAsBekkersFormulasHaveIt) {
  for (const char* name : {"dry_sand", "lunar_regolith", "lete_sand", "sandy_loam"}) {
    SoilParameters soil = *find_soil(name);
    soil.c1 = soil.c2 = 0.0;
    for (const double load : {50.0, 100.0, 200.0}) {
      for (const double diameter : {0.18, 0.5}) {
        const WheelShape wheel{0.5 * diameter, 0.12};
        double lo = 0.0, hi = wheel.radius;
        for (int i = 0; i < 80; ++i) {
          const double mid = 0.5 * (lo + hi);
          (wheel_soil_forces(soil, wheel, mid, 0.0, 0.0, 0.0).normal < load ? lo : hi) = mid;
        }
        const double z = 0.5 * (lo + hi);
        const WheelSoilForces f = wheel_soil_forces(soil, wheel, z, 0.0, 0.0, 0.0);
        const double n = soil.n, k = soil.k_c / wheel.width + soil.k_phi;
        const double z0 = std::pow(3.0 * load / ((3.0 - n) * wheel.width * k * std::sqrt(diameter)), 2.0 / (2.0 * n + 1.0));
        const double rc = wheel.width * k * std::pow(z0, n + 1.0) / (n + 1.0);
        std::printf("[ figures  ] %s W %.0f N D %.2f m: sinkage %.2f mm (Bekker %.2f), resistance %.2f N (Bekker %.2f)\n", name,
                    load, diameter, 1000 * z, 1000 * z0, f.resistance, rc);
        // Bekker's (3 - n) factor is exact for n = 1 only: sandy loam (n 0.7) is 5-9 % off.
        EXPECT_NEAR(z / z0, 1.0, 0.07) << name << " W " << load << " D " << diameter;
        EXPECT_NEAR(f.resistance / rc, 1.0, z0 / diameter < 0.15 ? 0.10 : 0.12) << name << " W " << load << " D " << diameter;
        EXPECT_NEAR(f.drawbar, -f.resistance, 1e-9 * load) << "no shear without slip or rolling";
      }
    }
  }
}

// In a rut of depth z_r the rim meets soil below the rut's floor, where the stress is the virgin
// curve's at the depth below the old surface: for n = 1, the stress peak at the bottom and no
// rebound, sigma = k r (cos theta - cos theta_1 + z_r / r) over [0, theta_1], theta_1 now from the
// sinkage below the floor, z - z_r, and the integrals have closed forms: W = r b k r [theta_1 / 2 +
// sin(2 theta_1) / 4 - c sin theta_1] and R_c = r b k r [sin^2(theta_1) / 2 - c (1 - cos theta_1)]
// with c = cos theta_1 - z_r / r. No rut: Bekker's integral.
TEST(Terramechanics, InARutTheSoilCarriesTheWheelFromTheRutsFloorAtItsEarlierPressure) {
  SoilParameters soil = *find_soil("lunar_regolith");  // n = 1
  soil.c1 = soil.c2 = 0.0;
  ASSERT_EQ(soil.n, 1.0);
  const WheelShape wheel{0.09, 0.12};
  const double r = wheel.radius, b = wheel.width, k = soil.k_c / b + soil.k_phi;
  for (const double z : {0.004, 0.01, 0.03}) {
    for (const double rut_fraction : {0.0, 0.3, 0.8, 0.99}) {
      const double zr = rut_fraction * z;
      const WheelSoilForces f = wheel_soil_forces(soil, wheel, z, 0.0, 0.0, 0.0, zr);
      const double t1 = std::acos(1.0 - (z - zr) / r), c = std::cos(t1) - zr / r;
      const double load = r * b * k * r * (t1 / 2.0 + std::sin(2.0 * t1) / 4.0 - c * std::sin(t1));
      const double resistance = r * b * k * r * (std::sin(t1) * std::sin(t1) / 2.0 - c * (1.0 - std::cos(t1)));
      EXPECT_NEAR(f.normal, load, 1e-6 * load) << "z " << z << " rut " << zr;
      EXPECT_NEAR(f.resistance, resistance, 1e-6 * resistance) << "z " << z << " rut " << zr;
      EXPECT_NEAR(f.entry_angle, t1, 1e-12);
    }
    EXPECT_EQ(wheel_soil_forces(soil, wheel, z, 0.2, 0.0, 1.0, z).normal, 0.0) << "the rim just reaches the rut's floor";
    EXPECT_EQ(wheel_soil_forces(soil, wheel, z, 0.2, 0.0, 1.0, 2.0 * z).drawbar, 0.0);
  }
}

// Multi-pass, steady: a wheel (the CC8's, 60 N, slip 0.2) in the rut the same wheel left sinks
// further than the first (by at most 40 %), a third pass by less again, and meets a fraction of the
// compaction resistance. Its thrust falls too (its arc in the soil is short, so the soil's shear
// displacement stays small), so its drawbar pull need not rise: reported, not asserted. On every
// named soil that carries the wheel (snow lets it sink its radius).
TEST(Terramechanics, AWheelInAnotherWheelsRutSinksALittleFurtherAndMeetsLessResistance) {
  const WheelShape wheel{0.09, 0.12};
  int soils = 0;
  for (const SoilParameters& soil : named_soils()) {
    const SteadyWheel first = steady_wheel(soil, wheel, 60.0, 0.2);
    if (!first.ok) continue;
    ++soils;
    const SteadyWheel second = steady_wheel(soil, wheel, 60.0, 0.2, first.sinkage);
    const SteadyWheel third = steady_wheel(soil, wheel, 60.0, 0.2, second.sinkage);
    ASSERT_TRUE(second.ok && third.ok) << soil.name;
    std::printf("[ figures  ] %s, 60 N, slip 0.2: sinkage %.2f / %.2f / %.2f mm, resistance %.2f / %.2f N, drawbar %.2f / %.2f N\n",
                soil.name.c_str(), 1000 * first.sinkage, 1000 * second.sinkage, 1000 * third.sinkage,
                first.forces.resistance, second.forces.resistance, first.forces.drawbar, second.forces.drawbar);
    EXPECT_NEAR(second.forces.normal, 60.0, 1e-6);
    EXPECT_GT(second.sinkage, first.sinkage) << soil.name;
    EXPECT_LT(second.sinkage, 1.4 * first.sinkage) << soil.name;
    EXPECT_LT(third.sinkage - second.sinkage, second.sinkage - first.sinkage) << soil.name;
    EXPECT_LT(second.forces.resistance, 0.65 * first.forces.resistance) << soil.name;
    // No rut is the first pass.
    const WheelSoilForces none = wheel_soil_forces(soil, wheel, first.sinkage, 0.2, 0.0, 1.0, 0.0);
    EXPECT_EQ(none.normal, first.forces.normal);
    EXPECT_EQ(none.drawbar, first.forces.drawbar);
  }
  EXPECT_GE(soils, 5);
}

TEST(Terramechanics, DrawbarPullTorqueAndSinkageRiseWithSlip) {
  const SoilParameters soil = *find_soil("dry_sand");
  const WheelShape wheel{0.09, 0.12};
  SteadyWheel last = steady_wheel(soil, wheel, 100.0, 0.0);
  ASSERT_TRUE(last.ok);
  EXPECT_LT(last.forces.drawbar, 0.0) << "a wheel rolling without slip is resisted";
  for (double slip = 0.1; slip < 0.65; slip += 0.1) {
    const SteadyWheel w = steady_wheel(soil, wheel, 100.0, slip);
    ASSERT_TRUE(w.ok) << slip;
    EXPECT_NEAR(w.forces.normal, 100.0, 1e-6);
    // The shear's thrust rises with slip; the pull with it up to 0.4 (beyond, the deeper rut's
    // resistance takes over on this small, heavily loaded wheel).
    EXPECT_GT(w.forces.drawbar + w.forces.resistance, last.forces.drawbar + last.forces.resistance) << slip;
    if (slip < 0.45) {
      EXPECT_GT(w.forces.drawbar, last.forces.drawbar) << slip;
    }
    EXPECT_LT(w.forces.torque, last.forces.torque) << "more resisting torque at slip " << slip;
    EXPECT_GT(w.sinkage, last.sinkage) << "slip sinkage at " << slip;
    // Never more than Mohr-Coulomb's shear capacity of the contact.
    EXPECT_LT(w.forces.drawbar, soil.cohesion * wheel.width * wheel.radius * w.forces.entry_angle + 100.0 * std::tan(soil.friction_angle));
    last = w;
  }
}

TEST(Terramechanics, AtRestOnlyTheSlipShearsAndTheSideForceOpposesTheSlide) {
  const SoilParameters soil = *find_soil("lunar_regolith");
  const WheelShape wheel{0.09, 0.12};
  const double z = 0.02;
  const WheelSoilForces rest = wheel_soil_forces(soil, wheel, z, 0.0, 0.0, 0.0);
  EXPECT_NEAR(rest.drawbar + rest.resistance, 0.0, 1e-12 * rest.normal);
  EXPECT_DOUBLE_EQ(rest.torque, 0.0);
  const WheelSoilForces rolling = wheel_soil_forces(soil, wheel, z, 0.0, 0.0, 1.0);
  EXPECT_GT(rolling.drawbar + rolling.resistance, 0.0) << "the rolling rim shears the soil forward (arc longer than chord)";
  // Braking (negative slip) pulls back; a slide to +y is resisted towards -y, up to the capacity.
  EXPECT_LT(wheel_soil_forces(soil, wheel, z, -0.3, 0.0, 1.0).drawbar, rest.drawbar);
  const WheelSoilForces side = wheel_soil_forces(soil, wheel, z, 0.0, 0.05, 0.0);
  EXPECT_LT(side.lateral, 0.0);
  EXPECT_LT(std::abs(side.lateral), soil.cohesion * wheel.width * wheel.radius * side.entry_angle +
                                        side.normal * std::tan(soil.friction_angle));
  EXPECT_GT(std::abs(side.lateral), 0.3 * side.normal * std::tan(soil.friction_angle));
  EXPECT_EQ(wheel_soil_forces(soil, wheel, 0.0, 0.5).normal, 0.0) << "no sinkage, no force";
}

TEST(Terramechanics, NamedSoilsHoldTheirTablesValuesAndBadValuesAreNamed) {
  ASSERT_GE(named_soils().size(), 6u);
  for (const SoilParameters& s : named_soils()) {
    EXPECT_EQ(check_soil(s), "") << s.name;
    EXPECT_FALSE(s.source.empty()) << s.name;
  }
  // Wong's Table 2.3, dry sand (LLL): n 1.1, k_c 0.99 kN/m^(n+1), k_phi 1528.43 kN/m^(n+2), c 1.04 kPa, 28 deg.
  const SoilParameters sand = *find_soil("dry_sand");
  EXPECT_DOUBLE_EQ(sand.n, 1.1);
  EXPECT_DOUBLE_EQ(sand.k_c, 990.0);
  EXPECT_DOUBLE_EQ(sand.k_phi, 1528430.0);
  EXPECT_DOUBLE_EQ(sand.cohesion, 1040.0);
  EXPECT_NEAR(sand.friction_angle, 28.0 * M_PI / 180.0, 1e-12);
  EXPECT_FALSE(find_soil("quicksand"));
  SoilParameters bad = sand;
  bad.n = -1.0;
  EXPECT_NE(check_soil(bad).find("n must"), std::string::npos);
  bad = sand;
  bad.friction_angle = 1.5;
  EXPECT_NE(check_soil(bad).find("friction angle"), std::string::npos);
  bad = sand;
  bad.shear_modulus = 0.0;
  EXPECT_NE(check_soil(bad).find("shear modulus"), std::string::npos);
  bad = sand;
  bad.k_c = bad.k_phi = 0.0;
  EXPECT_NE(check_soil(bad).find("k_phi must be"), std::string::npos);
}

}  // namespace
}  // namespace mechsim::physics
