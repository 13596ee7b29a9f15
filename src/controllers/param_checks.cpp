#include "controllers/param_checks.hpp"

#include <cmath>
#include <string>

#include "control/hardware.hpp"

namespace mechsim::control {

double positive_param(const Params& params, const char* key, double fallback) {
  if (!params.has(key)) return fallback;
  const double v = params.get<double>(key);
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), key) + " must be finite and > 0 (got " +
                                std::to_string(v) + ")");
  }
  return v;
}

double non_negative_param(const Params& params, const char* key, double fallback) {
  if (!params.has(key)) return fallback;
  const double v = params.get<double>(key);
  if (!(v >= 0.0) || !std::isfinite(v)) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), key) + " must be finite and >= 0 (got " +
                                std::to_string(v) + ")");
  }
  return v;
}

}  // namespace mechsim::control
