#pragma once
// Soil constants from bevameter-style tests (`mechsim soil fit`): Bekker's pressure-sinkage
// constants n, k_c and k_phi from plate-sinkage tests with plates of several sizes, and the shear
// constants c, phi and K (Janosi-Hanamoto) from shear tests at several normal pressures. Pure
// functions on data in SI units; reading files and writing the soil are sim/soil_fit_report.hpp's.
//
// Plates (Bekker, Theory of Land Locomotion, 1956; Wong, Theory of Ground Vehicles, 4th ed. 2008,
// section 2.2): p = (k_c / b + k_phi) z^n, b the smaller side of the loaded area: a circular
// plate's radius, a rectangular one's width. Least squares on the pressures themselves (not their
// logarithms, which weigh the first millimetres' noise as much as the rest: Wong, "Data processing
// methodology in the characterization of the mechanical properties of terrain", J. Terramechanics
// 17(1), 1980), every sample of every test alike:
// - two_stage (the default): p = K_b z^n with one K per plate size and one common n, then the line
//   K_b = k_c / b + k_phi through the sizes' K by least squares;
// - direct: the three constants fitted to all samples at once.
// For a fixed n each stage is linear in the moduli, so n is found by a one-dimensional search
// (a scan, then golden-section refinement) and the moduli by linear least squares: the global
// optimum over n in [0.05, 3], whatever the starting point.
//
// Shear: tau = tau_max (1 - exp(-j / K)) with one K for all tests and one tau_max per test, then
// the Mohr-Coulomb line tau_max = c + sigma tan(phi) through the tests' normal pressures sigma.

#include <string>
#include <vector>

namespace mechsim::physics {

struct PlateTest {
  std::string name;        // for reports (the file)
  double b = 0.0;          // m: Bekker's b (a circular plate's radius, a rectangular plate's width)
  std::vector<double> z;   // m, sinkage (> 0 down)
  std::vector<double> p;   // Pa, pressure (same size as z)
};

enum class PlateFitMethod { TwoStage, Direct };

struct PlateFit {
  PlateFitMethod method = PlateFitMethod::TwoStage;
  double n = 0.0, k_c = 0.0, k_phi = 0.0;  // N/m^(n+1), N/m^(n+2)
  struct Size {
    double b = 0.0;      // m
    double K = 0.0;      // N/m^(n+2): two_stage, its own fit at the common n; direct, k_c / b + k_phi
    int tests = 0, samples = 0;
  };
  std::vector<Size> sizes;  // by increasing b
  double line_rms = 0.0;    // N/m^(n+2): two_stage, the sizes' K against the line; direct: 0
  double stage_rms = 0.0;   // Pa: two_stage, p = K_b z^n's residual (the first stage); direct: = rms
  double rms = 0.0;         // Pa: the constants' residual, p - (k_c / b + k_phi) z^n over all samples
  double r2 = 0.0;          // 1 - SSE / SST of the same
  std::vector<double> test_rms;  // Pa, per test (same order)
  int samples = 0;
};

// Throws std::invalid_argument naming the test: fewer than 2 sizes (k_c and k_phi need two),
// an empty test, a non-positive or non-finite b, z or p (non-finite), z and p of different sizes.
// Samples with z <= 0 are kept (they weigh in the residual) but carry no information on n.
PlateFit fit_plates(const std::vector<PlateTest>& tests, PlateFitMethod method = PlateFitMethod::TwoStage);

// (k_c / b + k_phi) z^n.
double plate_pressure(const PlateFit& fit, double b, double z);

struct ShearTest {
  std::string name;
  double normal_pressure = 0.0;  // Pa, sigma
  std::vector<double> j;         // m, shear displacement
  std::vector<double> tau;       // Pa, shear stress
};

struct ShearFit {
  double cohesion = 0.0;        // Pa
  double friction_angle = 0.0;  // rad
  double shear_modulus = 0.0;   // m, K
  std::vector<double> tau_max;  // Pa, per test
  double rms = 0.0;             // Pa, tau - (c + sigma tan phi)(1 - exp(-j / K)) over all samples
  double line_rms = 0.0;        // Pa, the tests' tau_max against the Mohr-Coulomb line
  int samples = 0;
};

// Throws std::invalid_argument: fewer than 2 distinct normal pressures, an empty test, bad values.
// A negative intercept is reported as it is fitted (cohesion < 0: the line says so; check_soil
// refuses it in a soil).
ShearFit fit_shear(const std::vector<ShearTest>& tests);

}  // namespace mechsim::physics
