#pragma once
// Reading a Gazebo model plugin's elements (the Params built by control/params_from_xml) with
// sdformat's conventions and errors that name the file, the line and the element:
//   "robot.urdf:42: <wheelDiameter> must be > 0 (got 0)".
// Absent elements give the plugin's default, as gazebo_plugins' getParameter does. Booleans
// take sdformat's spellings (true/false/1/0). Configuration time only: throws
// ControllerConfigError.

#include <string>
#include <vector>

#include "control/hardware.hpp"
#include "control/params.hpp"

namespace mechsim::control {

class PluginParams {
 public:
  explicit PluginParams(Params params) : params_(std::move(params)) {}

  const Params& params() const { return params_; }
  bool has(const char* key) const { return params_.has(key); }
  // "file:line" of the element, else of the <plugin> element.
  std::string location(const char* key) const;

  std::string text(const char* key, const std::string& fallback) const;
  double number(const char* key, double fallback) const;        // finite
  double positive(const char* key, double fallback) const;      // > 0, finite
  double non_negative(const char* key, double fallback) const;  // >= 0, finite
  // An update rate (Hz): >= 0, where 0 means every step, as Gazebo takes it.
  double rate(const char* key, double fallback) const;
  bool boolean(const char* key, bool fallback) const;
  // A joint name, non-empty.
  std::string joint(const char* key, const std::string& fallback) const;
  // A required element; throws naming it when absent.
  std::string required(const char* key) const;

  [[noreturn]] void fail(const char* key, const std::string& what) const;

 private:
  Params params_;
};

// The period (s) of an update rate: 1 / rate, 0 for a rate of 0 (every step).
inline double period_of(double rate) { return rate > 0.0 ? 1.0 / rate : 0.0; }

}  // namespace mechsim::control
