#pragma once
// Drives a mobile base along a list of waypoints by producing body twists: pure pursuit towards
// a look-ahead point on the current segment, with a turn on the spot when the next point lies
// far off the heading. Used by scenario timelines ("route:") for the rover demo.

#include <array>
#include <cstddef>
#include <vector>

#include "control/ports.hpp"

namespace mechsim::sim {

struct RouteParams {
  double speed = 0.4;          // m/s
  double tolerance = 0.3;      // m: waypoint reached inside this radius
  double lookahead = 1.0;      // m
  double max_yaw_rate = 0.6;   // rad/s
  double turn_in_place_angle = 1.2;  // rad: beyond this heading error, turn on the spot
};

class RouteFollower {
 public:
  RouteFollower(std::vector<std::array<double, 2>> waypoints, RouteParams params);

  // The twist (base frame) for a base at (x, y) with heading yaw (world frame, m and rad).
  control::Twist update(double x, double y, double yaw);
  bool done() const { return next_ >= waypoints_.size(); }
  std::size_t next_waypoint() const { return next_; }  // index of the waypoint being driven to
  const std::vector<std::array<double, 2>>& waypoints() const { return waypoints_; }

 private:
  std::vector<std::array<double, 2>> waypoints_;
  RouteParams params_;
  std::size_t next_ = 0;
  std::array<double, 2> segment_start_{0.0, 0.0};
  bool started_ = false;
};

// Wraps an angle into (-pi, pi].
double wrap_angle(double angle);

}  // namespace mechsim::sim
