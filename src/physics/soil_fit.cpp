#include "physics/soil_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mechsim::physics {
namespace {

// The minimum of f over [lo, hi]: a scan every `step`, then golden-section search around the
// best point of the scan (f is smooth; the scan keeps the search off a local minimum).
template <typename F>
double minimise(F&& f, double lo, double hi, double step) {
  double best = lo, best_f = f(lo);
  for (double x = lo + step; x <= hi + 1e-12; x += step) {
    const double v = f(x);
    if (v < best_f) best_f = v, best = x;
  }
  double a = std::max(lo, best - step), b = std::min(hi, best + step);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 60 && b - a > 1e-9 * std::max(1.0, std::abs(best)); ++i) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = f(d);
    }
  }
  const double x = 0.5 * (a + b);
  return f(x) <= best_f ? x : best;
}

double power(double z, double n) { return z > 0.0 ? std::pow(z, n) : 0.0; }

void check_plates(const std::vector<PlateTest>& tests) {
  if (tests.empty()) throw std::invalid_argument("no plate tests");
  for (const PlateTest& t : tests) {
    const std::string where = "plate test '" + t.name + "'";
    if (!(t.b > 0.0) || !std::isfinite(t.b)) throw std::invalid_argument(where + ": the plate's b (radius or width) must be > 0 m");
    if (t.z.empty()) throw std::invalid_argument(where + ": no samples");
    if (t.z.size() != t.p.size()) throw std::invalid_argument(where + ": as many pressures as sinkages are needed");
    for (std::size_t i = 0; i < t.z.size(); ++i)
      if (!std::isfinite(t.z[i]) || !std::isfinite(t.p[i]))
        throw std::invalid_argument(where + ": sample " + std::to_string(i + 1) + " is not a finite number");
  }
}

// The sizes (distinct b, to 1e-6 relative), increasing, and each test's size.
std::vector<double> plate_sizes(const std::vector<PlateTest>& tests, std::vector<std::size_t>& size_of) {
  std::vector<double> sizes;
  for (const PlateTest& t : tests) {
    bool known = false;
    for (double b : sizes) known = known || std::abs(b - t.b) <= 1e-6 * t.b;
    if (!known) sizes.push_back(t.b);
  }
  std::sort(sizes.begin(), sizes.end());
  size_of.clear();
  for (const PlateTest& t : tests)
    for (std::size_t s = 0; s < sizes.size(); ++s)
      if (std::abs(sizes[s] - t.b) <= 1e-6 * t.b) size_of.push_back(s);
  return sizes;
}

}  // namespace

double plate_pressure(const PlateFit& fit, double b, double z) { return (fit.k_c / b + fit.k_phi) * power(z, fit.n); }

PlateFit fit_plates(const std::vector<PlateTest>& tests, PlateFitMethod method) {
  check_plates(tests);
  std::vector<std::size_t> size_of;
  const std::vector<double> sizes = plate_sizes(tests, size_of);
  if (sizes.size() < 2)
    throw std::invalid_argument("plate tests of at least two plate sizes are needed to separate k_c from k_phi (all have b = " +
                                std::to_string(sizes.front()) + " m)");
  PlateFit fit;
  fit.method = method;
  // Per size, for exponent n: K = sum z^n p / sum z^2n (least squares of p = K z^n).
  const auto size_moduli = [&](double n) {
    std::vector<double> num(sizes.size(), 0.0), den(sizes.size(), 0.0);
    for (std::size_t t = 0; t < tests.size(); ++t)
      for (std::size_t i = 0; i < tests[t].z.size(); ++i) {
        const double zn = power(tests[t].z[i], n);
        num[size_of[t]] += zn * tests[t].p[i];
        den[size_of[t]] += zn * zn;
      }
    for (std::size_t s = 0; s < sizes.size(); ++s) num[s] = den[s] > 0.0 ? num[s] / den[s] : 0.0;
    return num;
  };
  // Direct, for exponent n: (k_c, k_phi) by least squares of p = k_c z^n / b + k_phi z^n.
  const auto moduli = [&](double n, double& k_c, double& k_phi) {
    double s11 = 0, s12 = 0, s22 = 0, s1p = 0, s2p = 0;
    for (const PlateTest& t : tests)
      for (std::size_t i = 0; i < t.z.size(); ++i) {
        const double x2 = power(t.z[i], n), x1 = x2 / t.b;
        s11 += x1 * x1, s12 += x1 * x2, s22 += x2 * x2, s1p += x1 * t.p[i], s2p += x2 * t.p[i];
      }
    const double det = s11 * s22 - s12 * s12;
    k_c = det != 0.0 ? (s1p * s22 - s2p * s12) / det : 0.0;
    k_phi = det != 0.0 ? (s11 * s2p - s12 * s1p) / det : 0.0;
  };
  const auto sse = [&](const auto& pressure) {
    double out = 0.0;
    for (std::size_t t = 0; t < tests.size(); ++t)
      for (std::size_t i = 0; i < tests[t].z.size(); ++i) {
        const double e = tests[t].p[i] - pressure(t, tests[t].z[i]);
        out += e * e;
      }
    return out;
  };
  if (method == PlateFitMethod::TwoStage) {
    fit.n = minimise([&](double n) {
      const std::vector<double> K = size_moduli(n);
      return sse([&](std::size_t t, double z) { return K[size_of[t]] * power(z, n); });
    }, 0.05, 3.0, 0.01);
    const std::vector<double> K = size_moduli(fit.n);
    // The line K = k_c (1 / b) + k_phi through the sizes.
    double mx = 0.0, my = 0.0;
    for (std::size_t s = 0; s < sizes.size(); ++s) mx += 1.0 / sizes[s], my += K[s];
    mx /= static_cast<double>(sizes.size());
    my /= static_cast<double>(sizes.size());
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      sxy += (1.0 / sizes[s] - mx) * (K[s] - my);
      sxx += (1.0 / sizes[s] - mx) * (1.0 / sizes[s] - mx);
    }
    fit.k_c = sxy / sxx;
    fit.k_phi = my - fit.k_c * mx;
    double line = 0.0;
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      const double e = K[s] - (fit.k_c / sizes[s] + fit.k_phi);
      line += e * e;
    }
    fit.line_rms = std::sqrt(line / static_cast<double>(sizes.size()));
    for (std::size_t s = 0; s < sizes.size(); ++s) fit.sizes.push_back({sizes[s], K[s], 0, 0});
  } else {
    fit.n = minimise([&](double n) {
      double k_c = 0.0, k_phi = 0.0;
      moduli(n, k_c, k_phi);
      return sse([&](std::size_t t, double z) { return (k_c / tests[t].b + k_phi) * power(z, n); });
    }, 0.05, 3.0, 0.01);
    moduli(fit.n, fit.k_c, fit.k_phi);
    for (double b : sizes) fit.sizes.push_back({b, fit.k_c / b + fit.k_phi, 0, 0});
  }
  // Residuals of the constants, overall and per test; the first stage's.
  double total = 0.0, mean = 0.0, stage = 0.0;
  for (const PlateTest& t : tests)
    for (double p : t.p) mean += p, ++fit.samples;
  mean /= fit.samples;
  double sst = 0.0;
  for (std::size_t t = 0; t < tests.size(); ++t) {
    double own = 0.0;
    PlateFit::Size& size = fit.sizes[size_of[t]];
    ++size.tests;
    size.samples += static_cast<int>(tests[t].z.size());
    for (std::size_t i = 0; i < tests[t].z.size(); ++i) {
      const double e = tests[t].p[i] - plate_pressure(fit, tests[t].b, tests[t].z[i]);
      const double e1 = tests[t].p[i] - size.K * power(tests[t].z[i], fit.n);
      own += e * e;
      stage += e1 * e1;
      sst += (tests[t].p[i] - mean) * (tests[t].p[i] - mean);
    }
    total += own;
    fit.test_rms.push_back(std::sqrt(own / static_cast<double>(tests[t].z.size())));
  }
  fit.rms = std::sqrt(total / fit.samples);
  fit.stage_rms = method == PlateFitMethod::TwoStage ? std::sqrt(stage / fit.samples) : fit.rms;
  fit.r2 = sst > 0.0 ? 1.0 - total / sst : 0.0;
  return fit;
}

ShearFit fit_shear(const std::vector<ShearTest>& tests) {
  std::vector<double> pressures;
  for (const ShearTest& t : tests) {
    const std::string where = "shear test '" + t.name + "'";
    if (!std::isfinite(t.normal_pressure) || t.normal_pressure < 0.0) throw std::invalid_argument(where + ": normal pressure must be >= 0 Pa");
    if (t.j.empty()) throw std::invalid_argument(where + ": no samples");
    if (t.j.size() != t.tau.size()) throw std::invalid_argument(where + ": as many shear stresses as displacements are needed");
    for (std::size_t i = 0; i < t.j.size(); ++i)
      if (!std::isfinite(t.j[i]) || !std::isfinite(t.tau[i]))
        throw std::invalid_argument(where + ": sample " + std::to_string(i + 1) + " is not a finite number");
    bool known = false;
    for (double p : pressures) known = known || std::abs(p - t.normal_pressure) <= 1e-6 * std::max(1.0, p);
    if (!known) pressures.push_back(t.normal_pressure);
  }
  if (pressures.size() < 2) throw std::invalid_argument("shear tests at two or more normal pressures are needed for c and phi");
  const auto tau_max = [&](double K) {
    std::vector<double> out;
    for (const ShearTest& t : tests) {
      double num = 0.0, den = 0.0;
      for (std::size_t i = 0; i < t.j.size(); ++i) {
        const double f = 1.0 - std::exp(-std::max(0.0, t.j[i]) / K);
        num += f * t.tau[i], den += f * f;
      }
      out.push_back(den > 0.0 ? num / den : 0.0);
    }
    return out;
  };
  const auto sse = [&](double K) {
    const std::vector<double> tm = tau_max(K);
    double out = 0.0;
    for (std::size_t k = 0; k < tests.size(); ++k)
      for (std::size_t i = 0; i < tests[k].j.size(); ++i) {
        const double e = tests[k].tau[i] - tm[k] * (1.0 - std::exp(-std::max(0.0, tests[k].j[i]) / K));
        out += e * e;
      }
    return out;
  };
  ShearFit fit;
  fit.shear_modulus = std::pow(10.0, minimise([&](double lg) { return sse(std::pow(10.0, lg)); }, -5.0, 0.0, 0.01));
  fit.tau_max = tau_max(fit.shear_modulus);
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < tests.size(); ++k) mx += tests[k].normal_pressure, my += fit.tau_max[k];
  mx /= static_cast<double>(tests.size());
  my /= static_cast<double>(tests.size());
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < tests.size(); ++k) {
    sxy += (tests[k].normal_pressure - mx) * (fit.tau_max[k] - my);
    sxx += (tests[k].normal_pressure - mx) * (tests[k].normal_pressure - mx);
  }
  const double slope = sxy / sxx;
  fit.cohesion = my - slope * mx;
  fit.friction_angle = std::atan(slope);
  double line = 0.0, total = 0.0;
  for (std::size_t k = 0; k < tests.size(); ++k) {
    const double e = fit.tau_max[k] - (fit.cohesion + slope * tests[k].normal_pressure);
    line += e * e;
    const double tmax = fit.cohesion + slope * tests[k].normal_pressure;
    for (std::size_t i = 0; i < tests[k].j.size(); ++i) {
      const double r = tests[k].tau[i] - tmax * (1.0 - std::exp(-std::max(0.0, tests[k].j[i]) / fit.shear_modulus));
      total += r * r;
      ++fit.samples;
    }
  }
  fit.line_rms = std::sqrt(line / static_cast<double>(tests.size()));
  fit.rms = std::sqrt(total / fit.samples);
  return fit;
}

}  // namespace mechsim::physics
