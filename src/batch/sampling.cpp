#include "batch/sampling.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

namespace mechsim::batch {
namespace {

// SplitMix64's finaliser: decorrelates nearby seeds (seed 1 and 2, stream 0 and 1).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The values of one random axis for draws 0 .. samples-1.
std::vector<double> draw(const Axis& axis, std::size_t samples, std::uint64_t seed, std::size_t axis_number) {
  RandomStream rng(seed, axis_number);
  std::vector<double> out(samples);
  switch (axis.kind) {
    case Axis::Kind::Uniform:
      for (double& v : out) v = axis.a + (axis.b - axis.a) * rng.uniform();
      break;
    case Axis::Kind::Normal:
      for (double& v : out) v = axis.a + axis.b * rng.normal();
      break;
    case Axis::Kind::LogUniform: {
      const double la = std::log(axis.a), lb = std::log(axis.b);
      for (double& v : out) v = std::exp(la + (lb - la) * rng.uniform());
      break;
    }
    case Axis::Kind::Lhs: {
      // One value in each of `samples` equal strata, in a shuffled order (Fisher-Yates).
      std::vector<std::size_t> stratum(samples);
      for (std::size_t i = 0; i < samples; ++i) stratum[i] = i;
      for (std::size_t i = samples; i > 1; --i) {
        const auto j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(i));
        std::swap(stratum[i - 1], stratum[j < i ? j : i - 1]);
      }
      const double n = static_cast<double>(samples);
      for (std::size_t i = 0; i < samples; ++i) {
        out[i] = axis.a + (axis.b - axis.a) * (static_cast<double>(stratum[i]) + rng.uniform()) / n;
      }
      break;
    }
    case Axis::Kind::List:
    case Axis::Kind::Grid:
      break;
  }
  return out;
}

std::string grid_value(const Axis& axis, std::size_t i) {
  const double t = axis.steps == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(axis.steps - 1);
  // The ends exactly as written.
  const double v = i + 1 == static_cast<std::size_t>(axis.steps) ? axis.b : axis.a + (axis.b - axis.a) * t;
  return format_value(v, axis.integer);
}

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t stream) : engine_(mix(mix(seed) ^ mix(stream + 1))) {}

double RandomStream::uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

double RandomStream::normal() {
  const double u1 = 1.0 - uniform();  // (0, 1]: log(u1) is finite
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::string format_value(double v, bool integer) {
  char buf[40];
  if (integer) {
    std::snprintf(buf, sizeof buf, "%.0f", std::round(v));
    return std::string(buf) == "-0" ? "0" : buf;
  }
  // The shortest text that reads back as the same double.
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  std::string s(buf, end);
  // A whole number stays a float for the scenario reader ("2" would be an integer in YAML, which
  // reads as a number too, but "2.0" says what was drawn).
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::vector<Point> plan_points(const SweepSpec& spec, std::size_t limit) {
  const std::size_t total = point_count(spec);
  if (total > limit) throw SweepError(spec.file + ": " + std::to_string(total) + " points, more than " + std::to_string(limit));
  std::vector<std::vector<std::string>> random(spec.axes.size());
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    if (spec.axes[a].discrete()) continue;
    for (double v : draw(spec.axes[a], spec.samples, spec.seed, a)) random[a].push_back(format_value(v, spec.axes[a].integer));
  }
  std::vector<Point> points(total);
  for (std::size_t index = 0; index < total; ++index) {
    Point& p = points[index];
    p.index = index;
    p.values.resize(spec.axes.size());
    const std::size_t sample = index % spec.samples;
    std::size_t rest = index / spec.samples;
    // The last discrete axis varies fastest.
    for (std::size_t a = spec.axes.size(); a-- > 0;) {
      const Axis& axis = spec.axes[a];
      if (!axis.discrete()) {
        p.values[a] = random[a][sample];
        continue;
      }
      const std::size_t i = rest % axis.size();
      rest /= axis.size();
      p.values[a] = axis.kind == Axis::Kind::List ? axis.values[i] : grid_value(axis, i);
    }
  }
  return points;
}

}  // namespace mechsim::batch
