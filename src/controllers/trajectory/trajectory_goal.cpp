#include "controllers/trajectory/trajectory_goal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace mechsim::control {

const char* result_code_name(TrajectoryResultCode code) noexcept {
  switch (code) {
    case TrajectoryResultCode::Successful: return "SUCCESSFUL";
    case TrajectoryResultCode::InvalidGoal: return "INVALID_GOAL";
    case TrajectoryResultCode::InvalidJoints: return "INVALID_JOINTS";
    case TrajectoryResultCode::OldHeaderTimestamp: return "OLD_HEADER_TIMESTAMP";
    case TrajectoryResultCode::PathToleranceViolated: return "PATH_TOLERANCE_VIOLATED";
    case TrajectoryResultCode::GoalToleranceViolated: return "GOAL_TOLERANCE_VIOLATED";
  }
  return "?";
}

const char* goal_status_name(GoalStatus status) noexcept {
  switch (status) {
    case GoalStatus::Pending: return "pending";
    case GoalStatus::Active: return "active";
    case GoalStatus::Succeeded: return "succeeded";
    case GoalStatus::Aborted: return "aborted";
    case GoalStatus::Preempted: return "preempted";
    case GoalStatus::Rejected: return "rejected";
  }
  return "?";
}

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

TrajectoryChannel::TrajectoryChannel(TrajectoryChannelConfig config)
    : config_(std::move(config)), scratch_(config_.joints.size(), config_.max_points) {
  buffer_.init(scratch_);
}

TrajectoryResultCode TrajectoryChannel::validate(const JointTrajectory& t, const FollowJointTrajectoryGoal* goal,
                                                 std::string& error) {
  using Code = TrajectoryResultCode;
  const auto& joints = config_.joints;
  if (!running_.load(std::memory_order_acquire)) {
    error = "the controller is not running; it takes no trajectories";
    return Code::InvalidGoal;
  }
  if (!std::isfinite(t.start_time) || t.start_time < 0.0) {
    error = "header.stamp (start_time) " + num(t.start_time) + " is not a finite time >= 0";
    return Code::InvalidGoal;
  }
  // An empty trajectory is a stop request. On the command topic its joint names do not matter; an
  // action goal's are checked first, as joint_trajectory_controller's goal callback does.
  if (t.points.empty() && goal == nullptr) return Code::Successful;
  if (t.joint_names.empty()) {
    error = "the trajectory names no joints";
    return Code::InvalidJoints;
  }
  for (std::size_t i = 0; i < t.joint_names.size(); ++i) {
    const std::string& name = t.joint_names[i];
    if (std::find(joints.begin(), joints.end(), name) == joints.end()) {
      error = "joint_names[" + std::to_string(i) + "] '" + name + "' is not a joint of this controller";
      return Code::InvalidJoints;
    }
    if (std::count(t.joint_names.begin(), t.joint_names.end(), name) > 1) {
      error = "joint '" + name + "' is named twice in joint_names";
      return Code::InvalidJoints;
    }
  }
  if (!config_.allow_partial_joints_goal && t.joint_names.size() != joints.size()) {
    error = "the trajectory names " + std::to_string(t.joint_names.size()) + " of the controller's " +
            std::to_string(joints.size()) + " joints and partial goals are not allowed (allow_partial_joints_goal)";
    return Code::InvalidJoints;
  }
  if (t.points.empty()) return Code::Successful;  // an action goal's stop request
  if (t.points.size() > config_.max_points) {
    error = "the trajectory has " + std::to_string(t.points.size()) + " points; this controller holds at most " +
            std::to_string(config_.max_points) + " (parameter max_trajectory_points)";
    return Code::InvalidGoal;
  }
  const std::size_t n = t.joint_names.size();
  for (std::size_t k = 0; k < t.points.size(); ++k) {
    const TrajectoryPoint& p = t.points[k];
    const std::string where = "points[" + std::to_string(k) + "]";
    const auto size_ok = [&](const std::vector<double>& v, const char* field, bool optional) {
      if ((optional && v.empty()) || v.size() == n) return true;
      error = where + "." + field + " has " + std::to_string(v.size()) + " values for " + std::to_string(n) + " joints";
      return false;
    };
    if (!size_ok(p.positions, "positions", false) || !size_ok(p.velocities, "velocities", true) ||
        !size_ok(p.accelerations, "accelerations", true) || !size_ok(p.effort, "effort", true)) {
      return Code::InvalidGoal;
    }
    if (!p.accelerations.empty() && p.velocities.empty()) {
      error = where + " has accelerations without velocities";
      return Code::InvalidGoal;
    }
    if (!all_finite(p.positions) || !all_finite(p.velocities) || !all_finite(p.accelerations) ||
        !all_finite(p.effort)) {
      error = where + " holds a value that is not finite";
      return Code::InvalidGoal;
    }
    if (!std::isfinite(p.time_from_start) || p.time_from_start < 0.0) {
      error = where + ".time_from_start " + num(p.time_from_start) + " is not a finite time >= 0";
      return Code::InvalidGoal;
    }
    if (k > 0 && !(p.time_from_start > t.points[k - 1].time_from_start)) {
      error = where + ".time_from_start " + num(p.time_from_start) + " s is not after points[" +
              std::to_string(k - 1) + "]'s " + num(t.points[k - 1].time_from_start) +
              " s: times must increase strictly";
      return Code::InvalidGoal;
    }
  }
  if (goal != nullptr) {
    TrajectoryTolerances probe = config_.default_tolerances;
    if (!apply_goal_tolerances(*goal, joints, probe, error)) return Code::InvalidGoal;
  }
  // The tick checks again against its own clock; this catches what is already stale.
  const double now = time_.load(std::memory_order_relaxed);
  if (t.start_time > 0.0 && t.start_time + t.points.back().time_from_start <= now) {
    error = "the trajectory ends at " + num(t.start_time + t.points.back().time_from_start) +
            " s, at or before the current time " + num(now) + " s";
    return Code::OldHeaderTimestamp;
  }
  return Code::Successful;
}

TrajectoryResultCode TrajectoryChannel::post(const JointTrajectory& t, const FollowJointTrajectoryGoal* goal,
                                             std::uint64_t goal_id, std::string& error, std::uint64_t& sequence) {
  const TrajectoryResultCode code = validate(t, goal, error);
  if (code != TrajectoryResultCode::Successful) return code;
  TrajectoryRequest& r = scratch_;
  const auto& joints = config_.joints;
  r.sequence = sequence = next_sequence_++;
  r.goal_id = goal_id;
  r.stop = t.points.empty();
  r.start_now = t.start_time == 0.0;
  r.start_time = t.start_time;
  r.point_count = t.points.size();
  std::fill(r.joint_in_request.begin(), r.joint_in_request.end(), std::uint8_t{0});
  for (std::size_t i = 0; i < t.joint_names.size() && !r.stop; ++i) {
    const auto j = static_cast<std::size_t>(std::find(joints.begin(), joints.end(), t.joint_names[i]) - joints.begin());
    r.joint_in_request[j] = 1;
    for (std::size_t k = 0; k < t.points.size(); ++k) {
      const TrajectoryPoint& p = t.points[k];
      r.positions[r.index(j, k)] = p.positions[i];
      r.velocities[r.index(j, k)] = p.velocities.empty() ? 0.0 : p.velocities[i];
      r.accelerations[r.index(j, k)] = p.accelerations.empty() ? 0.0 : p.accelerations[i];
    }
  }
  for (std::size_t k = 0; k < t.points.size(); ++k) {
    r.time_from_start[k] = t.points[k].time_from_start;
    r.point_order[k] = spline_order_for(!t.points[k].velocities.empty(), !t.points[k].accelerations.empty());
  }
  r.tolerances = config_.default_tolerances;
  if (goal != nullptr) (void)apply_goal_tolerances(*goal, joints, r.tolerances, error);
  buffer_.write(r);
  return TrajectoryResultCode::Successful;
}

GoalSubmission TrajectoryChannel::submit_goal(const FollowJointTrajectoryGoal& goal) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  GoalSubmission out;
  out.id = next_goal_id_++;
  Record record;
  std::string error;
  const TrajectoryResultCode code = post(goal.trajectory, &goal, out.id, error, record.sequence);
  if (code != TrajectoryResultCode::Successful) {
    record.status = GoalStatus::Rejected;
    record.result = {code, std::string(result_code_name(code)) + ": " + error};
    out.result = record.result;
  } else {
    out.accepted = true;
  }
  records_[out.id] = record;
  return out;
}

TrajectoryResultCode TrajectoryChannel::post_command(const JointTrajectory& t, std::string& error) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  std::uint64_t sequence = 0;
  return post(t, nullptr, 0, error, sequence);
}

bool TrajectoryChannel::cancel(std::uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  auto it = records_.find(id);
  if (it == records_.end() || goal_finished(it->second.status)) return false;
  return cancels_.push(id);
}

std::optional<GoalStatus> TrajectoryChannel::status(std::uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  auto it = records_.find(id);
  if (it == records_.end()) return std::nullopt;
  return it->second.status;
}

std::optional<TrajectoryResult> TrajectoryChannel::result(std::uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  auto it = records_.find(id);
  if (it == records_.end() || !goal_finished(it->second.status)) return std::nullopt;
  return it->second.result;
}

std::string TrajectoryChannel::describe(const TrajectoryEvent& e) const {
  std::string s = e.reason;
  const ToleranceViolation& v = e.violation;
  if (v.joint >= 0 && static_cast<std::size_t>(v.joint) < config_.joints.size()) {
    s += ": joint '" + config_.joints[static_cast<std::size_t>(v.joint)] + "' " +
         tolerance_quantity_name(v.quantity) + " error " + num(v.error) + " exceeds the tolerance " +
         num(v.tolerance);
  }
  s += " (at t = " + num(e.time) + " s)";
  return s;
}

void TrajectoryChannel::drain() {
  TrajectoryEvent e;
  while (events_.pop(e)) {
    if (e.kind == TrajectoryEvent::Kind::Taken) {
      // Every goal posted before this request and never taken was overwritten unseen.
      for (auto& [id, record] : records_) {
        if (record.status == GoalStatus::Pending && record.sequence < e.sequence) {
          record.status = GoalStatus::Preempted;
          record.result = {TrajectoryResultCode::Successful, "replaced by a newer trajectory before it started"};
        }
      }
      if (e.goal_id != 0) {
        auto it = records_.find(e.goal_id);
        if (it != records_.end() && it->second.status == GoalStatus::Pending) it->second.status = GoalStatus::Active;
      }
      continue;
    }
    auto it = records_.find(e.goal_id);
    if (it == records_.end() || goal_finished(it->second.status)) continue;
    it->second.status = e.status;
    it->second.result.error_code = e.code;
    if (e.status == GoalStatus::Succeeded) {
      it->second.result.error_string.clear();
    } else if (e.code != TrajectoryResultCode::Successful) {
      it->second.result.error_string = std::string(result_code_name(e.code)) + ": " + describe(e);
    } else {
      it->second.result.error_string = describe(e);
    }
  }
  // Forget the oldest finished goals beyond a bound, so that a long run does not grow.
  for (auto it = records_.begin(); records_.size() > kMaxGoalRecords && it != records_.end();) {
    it = goal_finished(it->second.status) ? records_.erase(it) : std::next(it);
  }
}

const TrajectoryRequest* TrajectoryChannel::take_from_rt() noexcept {
  const TrajectoryRequest& r = buffer_.read_from_rt();
  if (r.sequence == taken_sequence_) return nullptr;
  taken_sequence_ = r.sequence;
  return &r;
}

void TrajectoryChannel::report_from_rt(const TrajectoryEvent& event) noexcept {
  if (!events_.push(event)) event_overflows_.fetch_add(1, std::memory_order_relaxed);
}

bool TrajectoryCommandPort::write(const JointTrajectory& trajectory, std::string* error) {
  std::string why;
  const TrajectoryResultCode code = channel_->post_command(trajectory, why);
  if (code != TrajectoryResultCode::Successful) {
    return reject("port '" + name() + "': " + result_code_name(code) + ": " + why + "; the trajectory was not taken",
                  error);
  }
  accepted_.fetch_add(1, std::memory_order_relaxed);
  return true;
}

}  // namespace mechsim::control
