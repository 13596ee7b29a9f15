#pragma once
// A multi-joint trajectory as the controller runs it: per joint, a time-ordered sequence of
// spline segments in storage of fixed capacity (sized at init, so that replacing and sampling
// in the tick never allocate). Also the validated request that carries a new trajectory from a
// port to the tick, and ros_control's trajectory replacement.
//
// Replacement at a time (ros_control's init_joint_trajectory), done in the tick at `now`:
//   t_start = the request's start time (header.stamp), or `now` when it is 0;
//   t0 = max(t_start, now): the current trajectory is kept unchanged before t0;
//   points at or before `now` are dropped (all of them: OLD_HEADER_TIMESTAMP);
//   a bridging segment runs from the current trajectory's state at t0 (position, velocity,
//   acceleration: the desired state stays continuous) to the first kept point, then one segment
//   per pair of points. Each segment's order is the lower of the orders its two ends support
//   (the bridge's start has every field);
//   continuous joints: the new points are shifted by a multiple of 2 pi so that the first one is
//   reached the short way round;
//   joints the request does not name keep their current trajectory.

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "controllers/trajectory/trajectory_msgs.hpp"
#include "controllers/trajectory/trajectory_segment.hpp"
#include "controllers/trajectory/trajectory_tolerances.hpp"

namespace mechsim::control {

// A trajectory validated against a controller and laid out in its joint order, with storage of
// fixed size (max points x joints) so that copying one into a slot of the same shape does not
// allocate. Built outside the tick (trajectory_goal.hpp), consumed in it.
struct TrajectoryRequest {
  std::uint64_t sequence = 0;  // increases with every request written; 0: none yet
  std::uint64_t goal_id = 0;   // 0: a plain command (no action semantics)
  bool stop = false;           // an empty trajectory: stop and hold the current position
  bool start_now = true;       // header.stamp was 0
  double start_time = 0.0;     // s, header.stamp
  std::size_t point_count = 0;
  std::size_t max_points = 0;
  std::vector<std::uint8_t> joint_in_request;  // per controller joint: 1 when named
  std::vector<double> time_from_start;         // [max_points], s
  std::vector<SplineOrder> point_order;        // [max_points], from the fields given
  std::vector<double> positions;               // [joint * max_points + point]
  std::vector<double> velocities;              // same layout; 0 where not given
  std::vector<double> accelerations;           // same layout; 0 where not given
  TrajectoryTolerances tolerances;             // resolved against the defaults

  TrajectoryRequest() = default;
  TrajectoryRequest(std::size_t joints, std::size_t max_points);
  std::size_t index(std::size_t joint, std::size_t point) const noexcept { return joint * max_points + point; }
};

class Trajectory {
 public:
  Trajectory() = default;
  // `capacity` segments per joint.
  Trajectory(std::size_t joints, std::size_t capacity);
  // Copies allocate (not for the tick); moves do not.
  Trajectory(const Trajectory& other);
  Trajectory& operator=(const Trajectory& other);
  Trajectory(Trajectory&&) noexcept = default;
  Trajectory& operator=(Trajectory&&) noexcept = default;

  std::size_t joint_count() const noexcept { return counts_.size(); }
  std::size_t capacity() const noexcept { return capacity_; }
  std::size_t segment_count(std::size_t joint) const noexcept { return counts_[joint]; }
  const SplineSegment& segment(std::size_t joint, std::size_t i) const noexcept { return segments_[joint * capacity_ + i]; }

  // Real-time: the desired state of `joint` at `time` (s): the last segment starting at or
  // before `time` (the first segment if none does). A joint without segments is at 0, at rest.
  SplineState sample(std::size_t joint, double time) const noexcept;
  // Real-time: the time the joint's last segment ends (s); -inf without segments.
  double end_time(std::size_t joint) const noexcept;

  // Real-time editing.
  void clear(std::size_t joint) noexcept { counts_[joint] = 0; }
  bool push(std::size_t joint, const SplineSegment& segment) noexcept;  // false when full
  void hold(std::size_t joint, double time, double position) noexcept;
  // Copies `other`'s segments of `joint` (same capacity) into this one.
  void copy_joint(const Trajectory& other, std::size_t joint) noexcept;

 private:
  std::size_t find(std::size_t joint, double time) const noexcept;
  struct Free {
    void operator()(SplineSegment* p) const noexcept { std::free(p); }
  };
  std::size_t capacity_ = 0;
  std::vector<std::size_t> counts_;
  // [joint * capacity_ + i], i < counts_[joint] constructed. Raw storage, not a vector: zeroing
  // every slot up front touched megabytes (the PR2's arm, head and torso controllers: 2.5 MB,
  // a tenth of its start-up in page faults) that a trajectory of a few points never uses.
  std::unique_ptr<SplineSegment[], Free> segments_;
};

struct ReplaceOutcome {
  TrajectoryResultCode code = TrajectoryResultCode::Successful;
  const char* reason = "";  // a string literal
  double start = 0.0;       // t0: when the new trajectory takes over (s)
  double end = 0.0;         // when its last point is reached (s)
};

// Real-time: writes into `out` (same shape as `current`) the result of replacing `current` by
// `request` at `now`, as described above. `continuous[j]` is nonzero for joints that wrap.
// On failure (every point in the past, storage full) `out` is unspecified.
ReplaceOutcome replace_trajectory(const Trajectory& current, const TrajectoryRequest& request,
                                  const std::vector<std::uint8_t>& continuous, double now, Trajectory& out) noexcept;

}  // namespace mechsim::control
