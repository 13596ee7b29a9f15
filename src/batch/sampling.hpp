#pragma once
// The points of a sweep: the values each axis takes at each point, drawn deterministically from
// the sweep's seed (the same file gives the same points on every machine: the generator is
// std::mt19937_64, whose output the standard fixes, and the conversions to uniform and normal
// values are written here rather than left to the library's distributions).

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "batch/sweep_spec.hpp"

namespace mechsim::batch {

struct Point {
  std::size_t index = 0;
  std::vector<std::string> values;  // one per axis, as YAML scalar text
};

// Uniform and normal draws from one seeded stream.
class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream);
  double uniform();  // [0, 1), 53 random bits
  double normal();   // mean 0, standard deviation 1 (Box-Muller)

 private:
  std::mt19937_64 engine_;
};

// A number as the value of an override: integers without a decimal point, others with enough
// digits to read back the same double.
std::string format_value(double v, bool integer);

// Every point of `spec`, in index order: the product of the discrete axes (first slowest), each
// with `samples` draws of the random axes. Throws SweepError past `limit` points.
std::vector<Point> plan_points(const SweepSpec& spec, std::size_t limit = static_cast<std::size_t>(-1));

}  // namespace mechsim::batch
