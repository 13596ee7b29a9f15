#include "controllers/gripper/pr2_gripper_ports.hpp"

#include <cmath>

namespace mechsim::control {

bool GripperCommandPort::write(const GripperCommand& command, std::string* error) {
  if (!std::isfinite(command.position) || !std::isfinite(command.max_effort)) {
    return reject("port '" + name() + "': rejected gripper command (position " + std::to_string(command.position) +
                      " m, max_effort " + std::to_string(command.max_effort) +
                      " N): not finite; the previous command stays",
                  error);
  }
  buffer_.write(command);
  accepted_.fetch_add(1, std::memory_order_acq_rel);
  return true;
}

GripperSubmission GripperGoalPort::submit(const GripperCommand& goal) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  GripperSubmission s;
  s.id = next_id_++;
  if (!running_.load(std::memory_order_acquire)) {
    s.error = "the controller is not running; it takes no goals";
  } else if (!std::isfinite(goal.position) || !std::isfinite(goal.max_effort)) {
    s.error = "the goal's position or max_effort is not finite";
  }
  if (!s.error.empty()) {
    records_[s.id] = {GoalStatus::Rejected, {}};
    return s;
  }
  records_[s.id] = {GoalStatus::Pending, {}};
  goals_.write({s.id, goal});
  s.accepted = true;
  return s;
}

bool GripperGoalPort::cancel(std::uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  auto it = records_.find(id);
  if (it == records_.end() || goal_finished(it->second.status)) return false;
  cancel_.store(id, std::memory_order_release);
  return true;
}

std::optional<GoalStatus> GripperGoalPort::status(std::uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  auto it = records_.find(id);
  if (it == records_.end()) return std::nullopt;
  return it->second.status;
}

std::optional<GripperResult> GripperGoalPort::result(std::uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex_);
  drain();
  auto it = records_.find(id);
  if (it == records_.end() || !goal_finished(it->second.status)) return std::nullopt;
  return it->second.result;
}

void GripperGoalPort::drain() {
  GripperGoalEvent e;
  while (events_.pop(e)) {
    if (e.status == GoalStatus::Active) {
      // A goal submitted after this one may have replaced it before the tick looked: the ones
      // still pending below the taken id never ran.
      for (auto& [id, record] : records_) {
        if (id < e.id && record.status == GoalStatus::Pending) record.status = GoalStatus::Preempted;
      }
    }
    auto it = records_.find(e.id);
    if (it == records_.end() || goal_finished(it->second.status)) continue;
    it->second.status = e.status;
    it->second.result = e.result;
  }
}

bool GripperGoalPort::take_from_rt(GripperGoalRequest& out) noexcept {
  const GripperGoalRequest& r = goals_.read_from_rt();
  if (r.id == 0 || r.id == taken_id_) return false;
  taken_id_ = r.id;
  out = r;
  return true;
}

void GripperGoalPort::report_from_rt(const GripperGoalEvent& event) noexcept {
  // A full ring (nobody has queried for 64 events) drops the event; the feedback still tells.
  (void)events_.push(event);
}

}  // namespace mechsim::control
