// Soil constants from plate-sinkage and shear tests (physics/soil_fit.hpp): exact on data made
// from known constants, by both methods; the residual of noisy data is the noise; the CMU sand's
// plate tests (../shared/soil/cmu_plate_sinkage) give the constants its README's independent
// processing gives; bad input named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "physics/soil_fit.hpp"
#include "physics/test/physics_test_util.hpp"

namespace mechsim::physics {
namespace {

std::vector<PlateTest> synthetic(double n, double k_c, double k_phi, double noise, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> e(0.0, noise);
  std::vector<PlateTest> tests;
  for (const double b : {0.03, 0.04, 0.05})
    for (int repeat = 0; repeat < 2; ++repeat) {
      PlateTest t;
      t.name = "b" + std::to_string(b) + "_" + std::to_string(repeat);
      t.b = b;
      for (int i = 1; i <= 100; ++i) {
        const double z = 0.0003 * i;
        t.z.push_back(z);
        t.p.push_back((k_c / b + k_phi) * std::pow(z, n) + (noise > 0.0 ? e(rng) : 0.0));
      }
      tests.push_back(std::move(t));
    }
  return tests;
}

TEST(SoilFit, PlateConstantsComeBackExactlyFromTheirOwnPressures) {
  for (const PlateFitMethod method : {PlateFitMethod::TwoStage, PlateFitMethod::Direct}) {
    for (const auto& [n, k_c, k_phi] : {std::tuple{1.1, 990.0, 1.52843e6}, std::tuple{1.4765, -4.0648e5, 1.973e7},
                                        std::tuple{0.7, 5270.0, 1.51504e6}}) {
      const PlateFit f = fit_plates(synthetic(n, k_c, k_phi, 0.0, 1), method);
      EXPECT_NEAR(f.n, n, 1e-6) << static_cast<int>(method);
      EXPECT_NEAR(f.k_c, k_c, 1e-5 * std::abs(k_phi) * 0.05);
      EXPECT_NEAR(f.k_phi, k_phi, 1e-5 * k_phi);
      EXPECT_LT(f.rms, 1e-6 * k_phi * std::pow(0.03, n));
      EXPECT_NEAR(f.r2, 1.0, 1e-9);
      ASSERT_EQ(f.sizes.size(), 3u);
      EXPECT_EQ(f.sizes[0].tests, 2);
      EXPECT_EQ(f.sizes[0].samples, 200);
      EXPECT_NEAR(f.sizes[1].K, k_c / 0.04 + k_phi, 1e-5 * k_phi);
    }
  }
}

TEST(SoilFit, TheResidualOfNoisyPlatesIsTheirNoise) {
  const PlateFit f = fit_plates(synthetic(1.3, 2e4, 8e6, 300.0, 7), PlateFitMethod::TwoStage);
  EXPECT_NEAR(f.rms, 300.0, 30.0);
  EXPECT_NEAR(f.n, 1.3, 0.03);
  EXPECT_EQ(f.test_rms.size(), 6u);
}

TEST(SoilFit, BadPlateTestsAreNamed) {
  std::vector<PlateTest> one_size = synthetic(1.0, 0.0, 1e6, 0.0, 1);
  one_size.resize(2);  // both b = 0.03
  try {
    fit_plates(one_size);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("two plate sizes"), std::string::npos) << e.what();
  }
  std::vector<PlateTest> bad = synthetic(1.0, 0.0, 1e6, 0.0, 1);
  bad[3].p.pop_back();
  try {
    fit_plates(bad);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(bad[3].name), std::string::npos) << e.what();
  }
  bad = synthetic(1.0, 0.0, 1e6, 0.0, 1);
  bad[0].b = 0.0;
  EXPECT_THROW(fit_plates(bad), std::invalid_argument);
  bad = synthetic(1.0, 0.0, 1e6, 0.0, 1);
  bad[1].z[5] = std::nan("");
  EXPECT_THROW(fit_plates(bad), std::invalid_argument);
}

TEST(SoilFit, ShearConstantsComeBackFromTheirOwnCurves) {
  const double c = 1040.0, phi = 28.0 * M_PI / 180.0, K = 0.004;
  std::vector<ShearTest> tests;
  for (const double sigma : {5e3, 10e3, 20e3}) {
    ShearTest t;
    t.name = std::to_string(sigma);
    t.normal_pressure = sigma;
    for (int i = 0; i <= 60; ++i) {
      t.j.push_back(0.0005 * i);
      t.tau.push_back((c + sigma * std::tan(phi)) * (1.0 - std::exp(-t.j.back() / K)));
    }
    tests.push_back(t);
  }
  const ShearFit f = fit_shear(tests);
  EXPECT_NEAR(f.cohesion, c, 1e-3);
  EXPECT_NEAR(f.friction_angle, phi, 1e-8);
  EXPECT_NEAR(f.shear_modulus, K, 1e-8);
  EXPECT_LT(f.rms, 1e-3);
  tests.resize(1);
  EXPECT_THROW(fit_shear(tests), std::invalid_argument) << "one normal pressure cannot give c and phi";
}

// One run's samples file: z_m, force_N, pressure_Pa after '#' lines and a header.
PlateTest read_sample(const std::filesystem::path& file, double diameter) {
  std::ifstream in(file);
  PlateTest t;
  t.name = file.filename().string();
  t.b = diameter / 2.0;  // Bekker's b of a circular plate: its radius
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("z_m", 0) == 0) continue;
    std::istringstream row(line);
    double z = 0, f = 0, p = 0;
    row >> z >> f >> p;
    t.z.push_back(z);
    t.p.push_back(p);
  }
  return t;
}

// The README of ../shared/soil/cmu_plate_sinkage gives its own joint fits of the same samples
// (bekker_fit.tsv, variant primary, made by its process.py with SciPy): mechsim's fit must
// reproduce them.
TEST(SoilFit, TheCmuSandsPlateTestsGiveTheConstantsTheirIndependentProcessingGives) {
  const std::filesystem::path dir = std::filesystem::path(test::shared_dir()) / "soil" / "cmu_plate_sinkage" / "samples";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared data not found at " << dir << " (MECHSIM_SHARED_DIR): the CMU plate tests";
  struct Expected {
    const char* box;
    PlateFitMethod method;
    double n, k_c, k_phi, rms;
  };
  // bekker_fit.tsv, variant primary.
  const Expected expected[] = {{"large", PlateFitMethod::TwoStage, 1.4765, -4.0648e5, 1.973e7, 936},
                               {"large", PlateFitMethod::Direct, 1.4164, -2.7371e5, 1.4236e7, 1246},
                               {"small", PlateFitMethod::TwoStage, 1.4519, -3.4374e5, 1.6912e7, 1331},
                               {"small", PlateFitMethod::Direct, 1.4201, -2.7583e5, 1.4149e7, 1518}};
  for (const Expected& e : expected) {
    std::vector<PlateTest> tests;
    for (int i = 1; i <= 9; ++i)  // 1-3: 60 mm, 4-6: 100 mm, 7-9: 80 mm (the README's table)
      tests.push_back(read_sample(dir / (std::string(e.box) + "_" + std::to_string(i) + ".tsv"), i <= 3 ? 0.06 : i <= 6 ? 0.1 : 0.08));
    const PlateFit f = fit_plates(tests, e.method);
    std::printf("[ figures  ] %s box, %s: n %.4f, k_c %.4e, k_phi %.4e, rms %.0f Pa (stage %.0f), R^2 %.4f\n", e.box,
                e.method == PlateFitMethod::TwoStage ? "two_stage" : "direct", f.n, f.k_c, f.k_phi, f.rms, f.stage_rms, f.r2);
    EXPECT_EQ(f.samples, 1800);
    EXPECT_NEAR(f.n, e.n, 0.0006) << e.box;
    EXPECT_NEAR(f.k_c, e.k_c, 0.005 * std::abs(e.k_c)) << e.box;
    EXPECT_NEAR(f.k_phi, e.k_phi, 0.005 * e.k_phi) << e.box;
    // The README's rms is the two-stage fit's first stage (one K per size).
    EXPECT_NEAR(e.method == PlateFitMethod::TwoStage ? f.stage_rms : f.rms, e.rms, 2.0) << e.box;
  }
}

}  // namespace
}  // namespace mechsim::physics
