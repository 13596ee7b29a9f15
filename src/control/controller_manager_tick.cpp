// ControllerManager's real-time side: the tick (update), switches applied in it, controllers
// started, stopped and failed in it; no allocation, no lock but try-locks (DESIGN.md).
#include "control/controller_manager.hpp"
#include "control/controller_manager_entry.hpp"

#include "mechanism/propagation.hpp"

namespace mechsim::control {

using namespace manager_detail;

void ControllerManager::fail(Entry& entry, const char* prefix, const char* reason, double time) noexcept {
  rt_add(entry.failures, 1);
  if (entry.failure_mutex.try_lock()) {
    std::size_t used = append(entry.failure, sizeof entry.failure, 0, prefix);
    append(entry.failure, sizeof entry.failure, used, reason);
    entry.failure_mutex.unlock();
  }
  try {
    entry.controller->stopping(time);
  } catch (...) {
    // Already failing: stopping() gets one chance, the controller is stopped regardless.
  }
  entry.state.store(ControllerLifecycle::Stopped);
  // Leave its joints safe: no effort, hold position, zero velocity; the base to the physics.
  if (entry.claims_base) state_.base_command.active = false;
  for (JointHandle& h : entry.handles) {
    switch (h.interface()) {
      case HardwareInterface::Effort: h.set_command(0.0); break;
      case HardwareInterface::Position: h.set_command(h.position()); break;
      case HardwareInterface::Velocity: h.set_command(0.0); break;
    }
  }
}

void ControllerManager::apply_switch(double time) noexcept {
  transitions_.fetch_add(1, std::memory_order_acq_rel);
  for (Entry* e : pending_stop_) {
    if (e->state.load() == ControllerLifecycle::Running) stop(*e, time);
  }
  for (Entry* e : pending_start_) {
    if (e->state.load() != ControllerLifecycle::Running) start(*e, time);
  }
  transitions_.fetch_add(1, std::memory_order_acq_rel);
  switch_state_.store(kNoSwitch, std::memory_order_release);
}

void ControllerManager::try_apply_switch(double time) noexcept {
  int expected = kPending;
  if (switch_state_.compare_exchange_strong(expected, kApplying, std::memory_order_acq_rel)) apply_switch(time);
}

void ControllerManager::stop(Entry& e, double time) noexcept {
  try {
    e.controller->stopping(time);
  } catch (...) {
    // A controller being stopped is stopped even if stopping() throws.
  }
  e.state.store(ControllerLifecycle::Stopped);
}

void ControllerManager::start(Entry& e, double time) noexcept {
  const char* error = nullptr;
  try {
    e.controller->starting(time);
  } catch (const std::exception& ex) {
    error = ex.what();
  } catch (...) {
    error = "starting() threw an unknown exception";
  }
  if (error != nullptr) {
    rt_add(e.failures, 1);
    if (e.failure_mutex.try_lock()) {
      std::size_t used = append(e.failure, sizeof e.failure, 0, "starting() failed: ");
      append(e.failure, sizeof e.failure, used, error);
      e.failure_mutex.unlock();
    }
    e.state.store(ControllerLifecycle::Stopped);
    return;
  }
  e.updated_since_start = false;
  e.state.store(ControllerLifecycle::Running);
}

void ControllerManager::hold_unclaimed_joints(const std::vector<Entry*>& list) noexcept {
  std::fill(claimed_.begin(), claimed_.end(), std::uint8_t{0});
  for (const Entry* e : list) {
    if (e->state.load(std::memory_order_relaxed) != ControllerLifecycle::Running) continue;
    for (const int j : e->joint_indices) claimed_[static_cast<std::size_t>(j)] = 1;
  }
  for (const int j : hold_joints_) {
    const auto i = static_cast<std::size_t>(j);
    if (claimed_[i] != 0) {
      held_[i] = 0;
      continue;
    }
    mechanism::JointState& joint = state_.joints[i];
    if (held_[i] == 0) {
      held_[i] = 1;
      hold_position_[i] = joint.position;
    }
    joint.command_mode = HardwareInterface::Position;
    joint.commanded_position = hold_position_[i];
  }
}

void ControllerManager::run_controllers(const std::vector<Entry*>& list, double time, double period) noexcept {
  const double period_ns = period * 1e9;
  Clock::time_point before = Clock::now();
  for (Entry* e : list) {
    if (e->state.load(std::memory_order_relaxed) != ControllerLifecycle::Running) continue;
    double controller_period = period;
    if (e->update_period > 0.0) {
      // ros2_control: due when its own period has passed since its last update (a microsecond
      // of slack for the ticks' rounding), with that time as its period.
      if (e->updated_since_start) {
        const double elapsed = time - e->last_update;
        if (elapsed + 1e-6 < e->update_period) continue;
        controller_period = elapsed;
      }
      e->updated_since_start = true;
      e->last_update = time;
    }
    UpdateStatus status;
    bool failed = false;
    try {
      status = e->controller->update(time, controller_period);
    } catch (const std::exception& ex) {
      // The message is copied here, while the exception is alive.
      fail(*e, "update() threw: ", ex.what(), time);
      failed = true;
    } catch (...) {
      fail(*e, "update() threw an unknown exception", "", time);
      failed = true;
    }
    const Clock::time_point after = Clock::now();
    const std::uint64_t ns = elapsed_ns(before, after);
    before = after;
    rt_add(e->updates, 1);
    rt_add(e->time_sum_ns, ns);
    rt_max(e->time_max_ns, ns);
    if (period_ns > 0.0 && static_cast<double>(ns) > period_ns) rt_add(e->overruns, 1);
    if (!failed && !status.ok) fail(*e, "update() failed: ", status.reason, time);
  }
}

void ControllerManager::update(double time, double period, bool reset_controllers) noexcept {
  const Clock::time_point began = Clock::now();
  int index = 0;
  do {
    index = current_list_.load();
    list_in_use_.store(index);
  } while (current_list_.load() != index);
  const std::vector<Entry*>& list = lists_[index];

  mechanism::propagate_actuator_to_joint_position(model_, state_);
  if (switch_state_.load(std::memory_order_acquire) == kPending) try_apply_switch(time);
  const bool restart_all = restart_requested_.exchange(false, std::memory_order_acq_rel);
  if (reset_controllers || restart_all) {
    // ros_control's ControllerManager::update(time, period, true): every running controller is
    // stopped and started again (gazebo_ros_control asks for it when its e-stop is released).
    // Model plugins are not ros_control controllers: they run on, except through a reset's
    // request_restart() (Gazebo resets a model's plugins with the world).
    transitions_.fetch_add(1, std::memory_order_acq_rel);
    for (Entry* e : list) {
      if ((e->model_plugin && !restart_all) || e->state.load(std::memory_order_relaxed) != ControllerLifecycle::Running) {
        continue;
      }
      stop(*e, time);
      start(*e, time);
    }
    transitions_.fetch_add(1, std::memory_order_acq_rel);
  }
  for (mechanism::JointState& joint : state_.joints) {
    if (joint.command_mode == HardwareInterface::Effort) joint.commanded_effort = 0.0;
  }
  if (!hold_joints_.empty()) hold_unclaimed_joints(list);
  run_controllers(list, time, period);
  mechanism::enforce_safety_limits(model_, state_, period > 0.0 ? period : mechanism::kDefaultPeriod);
  mechanism::propagate_joint_to_actuator_effort(model_, state_);

  list_in_use_.store(-1);
  const std::uint64_t ns = elapsed_ns(began, Clock::now());
  rt_add(ticks_, 1);
  rt_add(tick_time_sum_ns_, ns);
  rt_max(tick_time_max_ns_, ns);
  if (period > 0.0 && static_cast<double>(ns) > period * 1e9) rt_add(tick_overruns_, 1);
}

}  // namespace mechsim::control
