#pragma once
// The profiles the PR2's laser tilt controller runs, as pr2_mechanism_controllers'
// LaserScannerTrajController: a via-point trajectory of the tilt joint (positions at times from
// its start) that repeats for ever (the profile time is the time since the command, modulo the
// trajectory's duration), interpolated
//   "linear"          straight segments between the via points;
//   "blended_linear"  the same segments joined by parabolic blends at `max_acceleration`
//                     (the path passes near, not through, an interior via point).
// pr2_msgs/PeriodicCmd "linear"/"blended_linear" is the three-point trajectory
//   offset - amplitude at 0, offset + amplitude at period/2, offset - amplitude at period;
// pr2_msgs/LaserTrajCmd gives the points. A segment shorter than its move at `max_velocity`
// (and, blended, `max_acceleration`) allows is stretched to that duration, as the PR2's
// trajectory timing does, so the duration can exceed the last time given.
// mechsim adds "sine" (offset + amplitude sin(2 pi t / period)) and "hold" (one position).
//
// Storage is fixed (kMaxLaserScanPoints via points), so that a profile is copied, swapped and
// sampled without allocating: the controller takes it from a real-time buffer in its update().

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::control {

inline constexpr std::size_t kMaxLaserScanPoints = 128;

enum class PeriodicProfile : unsigned char { Hold, Linear, BlendedLinear, Sine };
const char* periodic_profile_name(PeriodicProfile p) noexcept;  // "hold", "linear", "blended_linear", "sine"
// "linear", "blended_linear", "sine" (the names a command may give).
bool parse_periodic_profile(std::string_view text, PeriodicProfile& out);

// pr2_msgs/PeriodicCmd. Hold keeps `offset` (rad).
struct PeriodicCommand {
  PeriodicProfile profile = PeriodicProfile::Hold;
  double period = 1.0;     // s, > 0
  double amplitude = 0.0;  // rad, >= 0
  double offset = 0.0;     // rad
};

// pr2_msgs/LaserTrajCmd.
struct LaserTrajCommand {
  PeriodicProfile profile = PeriodicProfile::Linear;  // Linear or BlendedLinear
  std::vector<double> positions;        // rad
  std::vector<double> times_from_start;  // s, one per position, not decreasing
  double max_velocity = 0.0;             // rad/s; <= 0: the controller's
  double max_acceleration = 0.0;         // rad/s^2; <= 0: the controller's
};

// Limits a profile is timed with (the controller's parameters, or a command's own).
struct ScanLimits {
  double max_velocity = 2.0;       // rad/s, > 0
  double max_acceleration = 20.0;  // rad/s^2, > 0
};

// A profile ready to sample: the via points with their (stretched) times, segment velocities and
// blend durations, or a sine / hold.
class LaserScanProfile {
 public:
  // Hold at `position` (rad).
  static LaserScanProfile hold(double position) noexcept;
  // From a periodic command / a trajectory command; false (and `error` says why) for bad input:
  // non-finite values, period <= 0, amplitude < 0, sizes that differ, no point, decreasing times,
  // more than kMaxLaserScanPoints points.
  static bool from_periodic(const PeriodicCommand& command, const ScanLimits& limits, LaserScanProfile& out,
                            std::string* error);
  static bool from_trajectory(const LaserTrajCommand& command, const ScanLimits& limits, LaserScanProfile& out,
                              std::string* error);

  // Position (rad) and rate (rad/s) at `t` seconds since the profile started (t >= 0; repeats).
  void sample(double t, double& position, double& velocity) const noexcept;

  PeriodicProfile kind() const noexcept { return kind_; }
  // One cycle (s): the trajectory's duration, or the sine's period; 0 for hold.
  double duration() const noexcept;
  std::size_t point_count() const noexcept { return count_; }

 private:
  void sample_points(double t, double& position, double& velocity) const noexcept;

  PeriodicProfile kind_ = PeriodicProfile::Hold;
  // Sine (and Hold, which uses offset_).
  double period_ = 1.0, amplitude_ = 0.0, offset_ = 0.0;
  // Via points: times from 0, positions, the velocity of the segment after each point, and the
  // blend duration at each point (0 for linear).
  std::size_t count_ = 0;
  bool closed_ = false;  // last point = first: the blend at the loop joins the last and first segments
  std::array<double, kMaxLaserScanPoints> t_{}, q_{}, v_{}, blend_{};
};

}  // namespace mechsim::control
