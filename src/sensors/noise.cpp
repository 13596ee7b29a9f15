#include "sensors/noise.hpp"

#include <cmath>

namespace mechsim::sensors {

double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double standard_normal(Rng& rng) {
  for (;;) {
    const double u = 2.0 * uniform01(rng) - 1.0, v = 2.0 * uniform01(rng) - 1.0;
    const double s = u * u + v * v;
    if (s > 0.0 && s < 1.0) return u * std::sqrt(-2.0 * std::log(s) / s);
  }
}

NoiseState start_noise(const description::NoiseSpec& spec, Rng& rng) {
  NoiseState state;
  if (spec.bias_mean != 0.0 || spec.bias_stddev > 0.0) {
    state.bias = spec.bias_mean + spec.bias_stddev * standard_normal(rng);
    if (uniform01(rng) < 0.5) state.bias = -state.bias;
  }
  return state;
}

double apply_noise(const description::NoiseSpec& spec, NoiseState& state, double truth, double dt, Rng& rng) {
  if (!spec.active()) return truth;
  if (spec.drift_stddev > 0.0 && dt > 0.0) {
    if (spec.drift_time > 0.0) {
      // Exact discretisation of a first-order Gauss-Markov process with stationary deviation
      // drift_stddev and correlation time drift_time.
      const double phi = std::exp(-dt / spec.drift_time);
      state.drift = phi * state.drift + spec.drift_stddev * std::sqrt(1.0 - phi * phi) * standard_normal(rng);
    } else {
      state.drift += spec.drift_stddev * std::sqrt(dt) * standard_normal(rng);
    }
  }
  double value = truth + spec.offset + state.bias + state.drift + spec.mean;
  if (spec.stddev > 0.0) value += spec.stddev * standard_normal(rng);
  if (spec.precision > 0.0) value = std::round(value / spec.precision) * spec.precision;
  return value;
}

}  // namespace mechsim::sensors
