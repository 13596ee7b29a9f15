#pragma once
// Seeded, reproducible sensor noise: description::NoiseSpec's error model applied to one
// measured quantity. The random generator is passed in (one per sensor, seeded by the sensor
// set): nothing global, and the same seed gives bit-identical readings on one platform.

#include <cstdint>
#include <random>

#include "description/sensor_spec.hpp"

namespace mechsim::sensors {

// A sensor's random generator. Draws go through the helpers below (not <random>'s
// distributions, whose algorithms differ between standard libraries).
using Rng = std::mt19937_64;

double uniform01(Rng& rng);         // [0, 1), 53 random bits
double standard_normal(Rng& rng);  // N(0, 1), Marsaglia's polar method

// The random state of one noisy quantity: its constant bias and its drift.
struct NoiseState {
  double bias = 0.0;   // drawn once: N(bias_mean, bias_stddev) with a random sign (as SDF)
  double drift = 0.0;  // the Gauss-Markov / random-walk drift now
};

NoiseState start_noise(const description::NoiseSpec& spec, Rng& rng);

// truth + offset + bias + drift + N(mean, stddev), quantised to spec.precision; `dt` (s) is the
// time since the previous reading (it advances the drift). Draws nothing when the spec is
// inactive, so a noiseless sensor leaves the generator as it was.
double apply_noise(const description::NoiseSpec& spec, NoiseState& state, double truth, double dt, Rng& rng);

}  // namespace mechsim::sensors
