#include "controllers/trajectory/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>

#include "control/angles.hpp"

namespace mechsim::control {

TrajectoryRequest::TrajectoryRequest(std::size_t joints, std::size_t max_pts)
    : max_points(max_pts),
      joint_in_request(joints, 0),
      time_from_start(max_pts, 0.0),
      point_order(max_pts, SplineOrder::Linear),
      positions(joints * max_pts, 0.0),
      velocities(joints * max_pts, 0.0),
      accelerations(joints * max_pts, 0.0) {
  tolerances.path.assign(joints, StateTolerance{});
  tolerances.goal.assign(joints, StateTolerance{});
}

Trajectory::Trajectory(std::size_t joints, std::size_t capacity)
    : capacity_(capacity),
      counts_(joints, 0),
      segments_(static_cast<SplineSegment*>(std::malloc(std::max<std::size_t>(1, joints * capacity) * sizeof(SplineSegment)))) {
  static_assert(std::is_trivially_copyable_v<SplineSegment> && std::is_trivially_destructible_v<SplineSegment>);
  if (!segments_) throw std::bad_alloc();
}

Trajectory::Trajectory(const Trajectory& other) : Trajectory(other.counts_.size(), other.capacity_) {
  for (std::size_t j = 0; j < counts_.size(); ++j) copy_joint(other, j);
}

Trajectory& Trajectory::operator=(const Trajectory& other) {
  if (this != &other) *this = Trajectory(other);
  return *this;
}

std::size_t Trajectory::find(std::size_t joint, double time) const noexcept {
  const SplineSegment* first = segments_.get() + joint * capacity_;
  const SplineSegment* last = first + counts_[joint];
  const SplineSegment* it =
      std::upper_bound(first, last, time, [](double t, const SplineSegment& s) { return t < s.start_time(); });
  return it == first ? 0 : static_cast<std::size_t>(it - first) - 1;
}

SplineState Trajectory::sample(std::size_t joint, double time) const noexcept {
  if (counts_[joint] == 0) return {};
  return segment(joint, find(joint, time)).sample(time);
}

double Trajectory::end_time(std::size_t joint) const noexcept {
  if (counts_[joint] == 0) return -std::numeric_limits<double>::infinity();
  return segment(joint, counts_[joint] - 1).end_time();
}

bool Trajectory::push(std::size_t joint, const SplineSegment& s) noexcept {
  if (counts_[joint] >= capacity_) return false;
  std::construct_at(segments_.get() + joint * capacity_ + counts_[joint]++, s);
  return true;
}

void Trajectory::hold(std::size_t joint, double time, double position) noexcept {
  counts_[joint] = 0;
  (void)push(joint, SplineSegment::hold(time, position));
}

void Trajectory::copy_joint(const Trajectory& other, std::size_t joint) noexcept {
  const std::size_t n = std::min(other.counts_[joint], capacity_);
  std::uninitialized_copy_n(other.segments_.get() + joint * other.capacity_, n, segments_.get() + joint * capacity_);
  counts_[joint] = n;
}

ReplaceOutcome replace_trajectory(const Trajectory& current, const TrajectoryRequest& r,
                                  const std::vector<std::uint8_t>& continuous, double now, Trajectory& out) noexcept {
  ReplaceOutcome outcome;
  const double t_start = r.start_now ? now : r.start_time;
  const double t0 = std::max(t_start, now);
  std::size_t first = 0;
  while (first < r.point_count && t_start + r.time_from_start[first] <= now) ++first;
  if (first == r.point_count) {
    outcome.code = TrajectoryResultCode::OldHeaderTimestamp;
    outcome.reason = "every point of the trajectory lies at or before the current time";
    return outcome;
  }
  outcome.start = t0;
  outcome.end = t_start + r.time_from_start[r.point_count - 1];

  for (std::size_t j = 0; j < current.joint_count(); ++j) {
    if (r.joint_in_request[j] == 0) {
      out.copy_joint(current, j);
      continue;
    }
    out.clear(j);
    // Keep the current trajectory from the segment active now until t0.
    const std::size_t n = current.segment_count(j);
    std::size_t i = 0;
    while (i + 1 < n && current.segment(j, i + 1).start_time() <= now) ++i;
    for (; i < n && current.segment(j, i).start_time() < t0; ++i) {
      if (!out.push(j, current.segment(j, i))) {
        outcome.code = TrajectoryResultCode::InvalidGoal;
        outcome.reason = "the trajectory storage is full (too many queued segments)";
        return outcome;
      }
    }
    const SplineState start = current.sample(j, t0);
    double offset = 0.0;
    const double p_first = r.positions[r.index(j, first)];
    if (continuous[j] != 0) {
      offset = start.position + shortest_angular_distance(start.position, p_first) - p_first;
    }
    SplineState from = start;
    double from_time = t0;
    SplineOrder from_order = SplineOrder::Quintic;
    for (std::size_t k = first; k < r.point_count; ++k) {
      const std::size_t idx = r.index(j, k);
      const SplineState to{r.positions[idx] + offset, r.velocities[idx], r.accelerations[idx]};
      const double to_time = t_start + r.time_from_start[k];
      const SplineOrder order = std::min(from_order, r.point_order[k]);
      if (!out.push(j, SplineSegment(from_time, from, to_time, to, order))) {
        outcome.code = TrajectoryResultCode::InvalidGoal;
        outcome.reason = "the trajectory storage is full (too many queued segments)";
        return outcome;
      }
      from = to;
      from_time = to_time;
      from_order = r.point_order[k];
    }
  }
  return outcome;
}

}  // namespace mechsim::control
