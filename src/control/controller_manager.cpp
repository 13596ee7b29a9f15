#include "control/controller_manager.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <thread>

#include "mechanism/propagation.hpp"

namespace mechsim::control {

const char* lifecycle_name(ControllerLifecycle state) {
  switch (state) {
    case ControllerLifecycle::Initialized: return "initialized";
    case ControllerLifecycle::Running: return "running";
    case ControllerLifecycle::Stopped: return "stopped";
  }
  return "?";
}

struct ControllerManager::Entry {
  std::string name;
  std::string type;
  std::unique_ptr<Controller> controller;
  std::vector<ResourceClaim> claims;
  std::vector<SensorUse> sensors;
  std::vector<JointHandle> handles;  // every claimed joint, made safe after a failure
  std::vector<int> joint_indices;    // for conflict checks
  bool model_plugin = false;         // add_model_plugin
  std::string origin;                // model plugins: "file:line" of the <plugin> element
  bool claims_base = false;

  std::atomic<ControllerLifecycle> state{ControllerLifecycle::Initialized};
  std::atomic<std::uint64_t> updates{0};
  std::atomic<std::uint64_t> time_sum_ns{0};
  std::atomic<std::uint64_t> time_max_ns{0};
  std::atomic<std::uint64_t> overruns{0};
  std::atomic<std::uint64_t> failures{0};

  // The failure text is written by the tick (try-lock, fixed buffer) and read outside.
  mutable std::mutex failure_mutex;
  char failure[256] = {};
};

namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t elapsed_ns(Clock::time_point from, Clock::time_point to) noexcept {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(to - from).count());
}

// Statistics have one writer, the tick: plain load + store (no locked read-modify-write),
// atomic only so that readers on other threads see whole values.
void rt_add(std::atomic<std::uint64_t>& target, std::uint64_t value) noexcept {
  target.store(target.load(std::memory_order_relaxed) + value, std::memory_order_relaxed);
}

void rt_max(std::atomic<std::uint64_t>& target, std::uint64_t value) noexcept {
  if (value > target.load(std::memory_order_relaxed)) target.store(value, std::memory_order_relaxed);
}

// Appends `text` to the fixed buffer without allocating.
std::size_t append(char* buffer, std::size_t capacity, std::size_t used, const char* text) noexcept {
  if (text == nullptr) return used;
  const std::size_t room = capacity - 1 - used;
  const std::size_t n = std::min(room, std::strlen(text));
  std::memcpy(buffer + used, text, n);
  buffer[used + n] = '\0';
  return used + n;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

ControllerManager::ControllerManager(const mechanism::MechanismModel& model, mechanism::MechanismState& state,
                                     Params params, ControllerRegistry registry)
    : model_(model), state_(state), params_(std::move(params)), registry_(std::move(registry)) {}

ControllerManager::~ControllerManager() = default;

ControllerManager::Entry* ControllerManager::find(const std::string& name) const {
  for (const auto& e : entries_) {
    if (e->name == name) return e.get();
  }
  return nullptr;
}

void ControllerManager::publish_list(std::vector<Entry*> list) {
  const int current = current_list_.load();
  const int spare = 1 - current;
  lists_[spare] = std::move(list);
  current_list_.store(spare);
  // The tick marks which list it iterates; wait until it has let go of the old one (at most
  // one tick; at once when no tick is running).
  while (list_in_use_.load() == current) std::this_thread::sleep_for(std::chrono::microseconds(50));
}

namespace {

// "controller 'x'" or "Gazebo model plugin 'p' (libgazebo_ros_diff_drive.so, robot.urdf:12)".
template <class E>
std::string describe_entry(const E& e) {
  if (!e.model_plugin) return "controller '" + e.name + "'";
  return "Gazebo model plugin '" + e.name + "' (" + e.type + (e.origin.empty() ? "" : ", " + e.origin) + ")";
}

}  // namespace

std::string ControllerManager::claim_conflict(const Entry& entry) const {
  for (const auto& other : entries_) {
    if (other.get() == &entry || (!other->model_plugin && !entry.model_plugin)) continue;  // ros_control's rule: at switch
    for (int j : entry.joint_indices) {
      if (std::find(other->joint_indices.begin(), other->joint_indices.end(), j) == other->joint_indices.end()) continue;
      return "joint '" + model_.joints[static_cast<std::size_t>(j)].name + "' is claimed by both " + describe_entry(*other) +
             " and " + describe_entry(entry) + "; a model plugin's joints are its own for the whole run";
    }
    if (entry.claims_base && other->claims_base) {
      return "the floating base is claimed by both " + describe_entry(*other) + " and " + describe_entry(entry);
    }
  }
  return {};
}

ControlResult ControllerManager::add_model_plugin(const std::string& name, const std::string& type,
                                                  std::unique_ptr<Controller> controller, const Params& params,
                                                  const std::string& origin, double time) {
  std::lock_guard<std::mutex> lock(config_mutex_);
  auto entry = std::make_unique<Entry>();
  entry->name = name;
  entry->type = type;
  entry->model_plugin = true;
  entry->origin = origin;
  const std::string what = describe_entry(*entry);
  if (name.empty()) return ControlResult::failure(what + ": a plugin needs a name");
  if (find(name) != nullptr) {
    return ControlResult::failure("could not load " + what + ": " + describe_entry(*find(name)) + " has the same name");
  }
  entry->controller = std::move(controller);
  RobotHardware hardware(model_, state_, HardwareAccess::ModelPlugin);
  hardware.set_sensors(sensors_);
  std::string error;
  bool ok = false;
  try {
    ok = entry->controller->init(hardware, params, error);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!ok) return ControlResult::failure("could not load " + what + ": " + (error.empty() ? "init() returned false" : error));
  entry->claims = hardware.claims();
  entry->sensors = hardware.sensor_uses();
  entry->claims_base = hardware.claims_base();
  for (const ResourceClaim& claim : entry->claims) {
    for (const std::string& joint : claim.joints) {
      const int index = hardware.find_joint(joint);
      entry->joint_indices.push_back(index);
      entry->handles.emplace_back(&model_.joints[static_cast<std::size_t>(index)],
                                  &state_.joints[static_cast<std::size_t>(index)], claim.interface);
    }
  }
  if (std::string conflict = claim_conflict(*entry); !conflict.empty()) {
    return ControlResult::failure("could not load " + what + ": " + conflict);
  }
  try {
    entry->controller->starting(time);
  } catch (const std::exception& e) {
    return ControlResult::failure("could not start " + what + ": " + e.what());
  }
  entry->state.store(ControllerLifecycle::Running);
  std::vector<Entry*> list = lists_[current_list_.load()];
  list.push_back(entry.get());
  entries_.push_back(std::move(entry));
  publish_list(std::move(list));
  return {};
}

ControlResult ControllerManager::load_controller(const std::string& name) {
  std::lock_guard<std::mutex> lock(config_mutex_);
  const std::string path = join_param_path(params_.path(), name);
  if (name.empty()) return ControlResult::failure("cannot load a controller with an empty name");
  if (find(name) != nullptr) {
    return ControlResult::failure("controller '" + name + "' is already loaded");
  }
  auto params = params_.find(name);
  if (!params || !params->is_map()) {
    return ControlResult::failure("could not load controller '" + name + "': no parameters at " + path +
                                  " (expected a map with a 'type')");
  }
  auto entry = std::make_unique<Entry>();
  entry->name = name;
  try {
    if (!params->has("type")) {
      return ControlResult::failure("could not load controller '" + name + "': parameter " +
                                    join_param_path(path, "type") + " not found (the controller's type)");
    }
    entry->type = params->get<std::string>("type");
  } catch (const ParamsError& e) {
    return ControlResult::failure("could not load controller '" + name + "': " + e.what());
  }
  try {
    entry->controller = registry_.create(entry->type);
  } catch (const std::exception& e) {
    return ControlResult::failure("could not load controller '" + name + "': " + e.what());
  }
  if (!entry->controller) {
    std::string notes;
    for (const std::string& note : registry_.notes()) notes += "; " + note;
    return ControlResult::failure("could not load controller '" + name + "': unknown type '" + entry->type +
                                  "' (parameter " + join_param_path(path, "type") + "); known types: " +
                                  join(registry_.types()) + notes);
  }
  RobotHardware hardware(model_, state_);
  hardware.set_sensors(sensors_);
  hardware.set_direct_joint_owner([this](int joint) {  // under config_mutex_, as load_controller
    std::string owners;
    for (const auto& e : entries_) {
      if (!e->model_plugin) continue;
      if (std::find(e->joint_indices.begin(), e->joint_indices.end(), joint) == e->joint_indices.end()) continue;
      owners += (owners.empty() ? "" : ", ") + describe_entry(*e);
    }
    return owners;
  });
  std::string error;
  bool ok = false;
  try {
    ok = entry->controller->init(hardware, *params, error);
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown exception";
  }
  if (!ok) {
    return ControlResult::failure("could not initialize controller '" + name + "' of type '" + entry->type +
                                  "': " + (error.empty() ? "init() returned false" : error));
  }
  entry->claims = hardware.claims();
  entry->sensors = hardware.sensor_uses();
  for (const ResourceClaim& claim : entry->claims) {
    for (const std::string& joint : claim.joints) {
      const int index = hardware.find_joint(joint);
      entry->joint_indices.push_back(index);
      entry->handles.emplace_back(&model_.joints[static_cast<std::size_t>(index)],
                                  &state_.joints[static_cast<std::size_t>(index)], claim.interface);
    }
  }
  if (std::string conflict = claim_conflict(*entry); !conflict.empty()) {
    return ControlResult::failure("could not load controller '" + name + "': " + conflict);
  }
  std::vector<Entry*> list = lists_[current_list_.load()];
  list.push_back(entry.get());
  entries_.push_back(std::move(entry));
  publish_list(std::move(list));
  return {};
}

ControlResult ControllerManager::unload_controller(const std::string& name) {
  std::lock_guard<std::mutex> lock(config_mutex_);
  Entry* entry = find(name);
  if (entry == nullptr) {
    return ControlResult::failure("could not unload controller '" + name + "': no controller with this name is loaded");
  }
  if (entry->model_plugin) {
    return ControlResult::failure("could not unload " + describe_entry(*entry) +
                                  ": a model plugin runs for the life of the simulation");
  }
  if (switch_pending()) {
    auto in = [&](const std::vector<Entry*>& v) { return std::find(v.begin(), v.end(), entry) != v.end(); };
    if (in(pending_start_) || in(pending_stop_)) {
      return ControlResult::failure("could not unload controller '" + name + "': it is part of a pending switch");
    }
  }
  if (entry->state.load() == ControllerLifecycle::Running) {
    return ControlResult::failure("could not unload controller '" + name + "': it is running; stop it first");
  }
  std::vector<Entry*> list = lists_[current_list_.load()];
  list.erase(std::remove(list.begin(), list.end(), entry), list.end());
  publish_list(std::move(list));
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.get() == entry; }),
                 entries_.end());
  return {};
}

SwitchResult ControllerManager::switch_controllers(const std::vector<std::string>& start,
                                                   const std::vector<std::string>& stop,
                                                   SwitchStrictness strictness) {
  std::lock_guard<std::mutex> lock(config_mutex_);
  SwitchResult result;
  const bool strict = strictness == SwitchStrictness::Strict;
  auto refuse = [&](std::string why) {
    result.ok = false;
    result.error = std::move(why);
    result.starting.clear();
    result.stopping.clear();
    return result;
  };
  if (switch_pending()) {
    return refuse("a previous switch has not been applied yet (the tick applies it; is the simulation running?)");
  }

  std::vector<Entry*> to_stop;
  for (const std::string& name : stop) {
    Entry* e = find(name);
    std::string problem;
    if (e == nullptr) {
      problem = "could not stop controller '" + name + "': no controller with this name is loaded";
    } else if (e->state.load() != ControllerLifecycle::Running) {
      problem = "could not stop controller '" + name + "': it is not running";
    } else if (e->model_plugin && std::find(start.begin(), start.end(), name) == start.end()) {
      problem = "could not stop " + describe_entry(*e) + ": a model plugin runs for the life of the simulation";
    }
    if (!problem.empty()) {
      if (strict) return refuse(problem);
      result.skipped.push_back(problem);
      continue;
    }
    if (std::find(to_stop.begin(), to_stop.end(), e) == to_stop.end()) to_stop.push_back(e);
  }

  std::vector<Entry*> to_start;
  for (const std::string& name : start) {
    Entry* e = find(name);
    std::string problem;
    const bool stopping = e != nullptr && std::find(to_stop.begin(), to_stop.end(), e) != to_stop.end();
    if (e == nullptr) {
      problem = "could not start controller '" + name + "': no controller with this name is loaded";
    } else if (e->state.load() == ControllerLifecycle::Running && !stopping) {
      problem = "could not start controller '" + name + "': it is already running";
    }
    if (!problem.empty()) {
      if (strict) return refuse(problem);
      result.skipped.push_back(problem);
      continue;
    }
    if (std::find(to_start.begin(), to_start.end(), e) == to_start.end()) to_start.push_back(e);
  }

  // Resource conflicts among the controllers that would run after the switch: one joint may be
  // claimed by one running controller only (ros_control's default conflict rule).
  std::vector<const Entry*> owner(model_.joints.size(), nullptr);
  for (const auto& e : entries_) {
    if (e->state.load() != ControllerLifecycle::Running) continue;
    if (std::find(to_stop.begin(), to_stop.end(), e.get()) != to_stop.end()) continue;
    if (std::find(to_start.begin(), to_start.end(), e.get()) != to_start.end()) continue;  // restart
    for (int j : e->joint_indices) owner[static_cast<std::size_t>(j)] = e.get();
  }
  std::vector<Entry*> accepted;
  for (Entry* e : to_start) {
    std::string conflict;
    for (int j : e->joint_indices) {
      const Entry* other = owner[static_cast<std::size_t>(j)];
      if (other != nullptr && other != e) {
        conflict = "resource conflict: joint '" + model_.joints[static_cast<std::size_t>(j)].name +
                   "' would be claimed by both '" + other->name + "' and '" + e->name + "'";
        break;
      }
    }
    if (!conflict.empty()) {
      if (strictness != SwitchStrictness::SkipConflicts) return refuse("could not switch controllers: " + conflict);
      result.skipped.push_back("could not start controller '" + e->name + "': " + conflict);
      continue;
    }
    for (int j : e->joint_indices) owner[static_cast<std::size_t>(j)] = e;
    accepted.push_back(e);
  }

  for (Entry* e : to_stop) result.stopping.push_back(e->name);
  for (Entry* e : accepted) result.starting.push_back(e->name);
  if (to_stop.empty() && accepted.empty()) return result;
  pending_stop_ = std::move(to_stop);
  pending_start_ = std::move(accepted);
  switch_state_.store(kPending, std::memory_order_release);
  return result;
}

bool ControllerManager::cancel_pending_switch() {
  std::lock_guard<std::mutex> lock(config_mutex_);
  int expected = kPending;
  if (!switch_state_.compare_exchange_strong(expected, kNoSwitch, std::memory_order_acq_rel)) return false;
  pending_start_.clear();
  pending_stop_.clear();
  return true;
}

bool ControllerManager::wait_for_switch(double timeout) const {
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout);
  while (switch_pending()) {
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  return true;
}

namespace {

ControllerStatistics read_statistics(std::uint64_t updates, std::uint64_t sum_ns, std::uint64_t max_ns,
                                     std::uint64_t overruns, std::uint64_t failures) {
  ControllerStatistics s;
  s.updates = updates;
  s.mean_update_time = updates > 0 ? static_cast<double>(sum_ns) * 1e-9 / static_cast<double>(updates) : 0.0;
  s.max_update_time = static_cast<double>(max_ns) * 1e-9;
  s.overruns = overruns;
  s.failures = failures;
  return s;
}

}  // namespace

std::vector<ControllerInfo> ControllerManager::list_controllers() const {
  std::lock_guard<std::mutex> lock(config_mutex_);
  std::vector<ControllerInfo> out;
  for (const auto& e : entries_) {
    ControllerInfo info;
    info.name = e->name;
    info.type = e->type;
    info.state = e->state.load();
    info.claims = e->claims;
    info.sensors = e->sensors;
    info.model_plugin = e->model_plugin;
    info.origin = e->origin;
    info.claims_base = e->claims_base;
    info.statistics = read_statistics(e->updates.load(), e->time_sum_ns.load(), e->time_max_ns.load(),
                                      e->overruns.load(), e->failures.load());
    {
      std::lock_guard<std::mutex> failure_lock(e->failure_mutex);
      info.failure = e->failure;
    }
    // The tick reads the pending lists but never changes them; switch_controllers() writes them
    // under config_mutex_ only while no switch is pending.
    if (switch_pending()) {
      auto in = [&](const std::vector<Entry*>& v) { return std::find(v.begin(), v.end(), e.get()) != v.end(); };
      info.start_pending = in(pending_start_);
      info.stop_pending = in(pending_stop_);
    }
    out.push_back(std::move(info));
  }
  return out;
}

std::optional<ControllerInfo> ControllerManager::controller_info(const std::string& name) const {
  for (ControllerInfo& info : list_controllers()) {
    if (info.name == name) return std::move(info);
  }
  return std::nullopt;
}

Controller* ControllerManager::controller(const std::string& name) const {
  std::lock_guard<std::mutex> lock(config_mutex_);
  Entry* e = find(name);
  return e != nullptr ? e->controller.get() : nullptr;
}

ManagerStatistics ControllerManager::statistics() const {
  ManagerStatistics s;
  s.ticks = ticks_.load();
  s.mean_tick_time = s.ticks > 0 ? static_cast<double>(tick_time_sum_ns_.load()) * 1e-9 / static_cast<double>(s.ticks) : 0.0;
  s.max_tick_time = static_cast<double>(tick_time_max_ns_.load()) * 1e-9;
  s.overruns = tick_overruns_.load();
  return s;
}

// ---------------------------------------------------------------- the tick

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
  for (Entry* e : pending_stop_) {
    if (e->state.load() == ControllerLifecycle::Running) stop(*e, time);
  }
  for (Entry* e : pending_start_) {
    if (e->state.load() != ControllerLifecycle::Running) start(*e, time);
  }
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
  e.state.store(ControllerLifecycle::Running);
}

void ControllerManager::run_controllers(const std::vector<Entry*>& list, double time, double period) noexcept {
  const double period_ns = period * 1e9;
  Clock::time_point before = Clock::now();
  for (Entry* e : list) {
    if (e->state.load(std::memory_order_relaxed) != ControllerLifecycle::Running) continue;
    UpdateStatus status;
    bool failed = false;
    try {
      status = e->controller->update(time, period);
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
  if (reset_controllers) {
    // ros_control's ControllerManager::update(time, period, true): every running controller is
    // stopped and started again (gazebo_ros_control asks for it when its e-stop is released).
    // Model plugins are not ros_control controllers: they run on.
    for (Entry* e : list) {
      if (e->model_plugin || e->state.load(std::memory_order_relaxed) != ControllerLifecycle::Running) continue;
      stop(*e, time);
      start(*e, time);
    }
  }
  for (mechanism::JointState& joint : state_.joints) {
    if (joint.command_mode == HardwareInterface::Effort) joint.commanded_effort = 0.0;
  }
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
