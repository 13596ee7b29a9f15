#include "control/controller_manager.hpp"
#include "control/controller_manager_entry.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstring>
#include <exception>
#include <thread>

#include "mechanism/propagation.hpp"

namespace mechsim::control {

using namespace manager_detail;

const char* lifecycle_name(ControllerLifecycle state) {
  switch (state) {
    case ControllerLifecycle::Initialized: return "initialized";
    case ControllerLifecycle::Running: return "running";
    case ControllerLifecycle::Stopped: return "stopped";
  }
  return "?";
}


namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

ControllerManager::ControllerManager(const mechanism::MechanismModel& model, mechanism::MechanismState& state,
                                     Params params, ControllerRegistry registry)
    : model_(model), state_(state), params_(std::move(params)), registry_(std::move(registry)) {
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    if (model_.joints[j].hold_when_unclaimed) hold_joints_.push_back(static_cast<int>(j));
  }
  claimed_.assign(model_.joints.size(), 0);
  held_.assign(model_.joints.size(), 0);
  hold_position_.assign(model_.joints.size(), 0.0);
}

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
  if (update_rate_ > 0.0 && params->has("update_rate")) {
    // ros2_control: a controller's own rate; at or above the manager's it runs at the manager's.
    double rate = 0.0;
    try {
      rate = params->get<double>("update_rate");
    } catch (const ParamsError& e) {
      return ControlResult::failure("could not load controller '" + name + "': " + e.what());
    }
    if (!(rate >= 0.0) || !std::isfinite(rate)) {
      return ControlResult::failure("could not load controller '" + name + "': parameter " +
                                    join_param_path(path, "update_rate") + " must be a rate >= 0 Hz");
    }
    if (rate > 0.0 && rate < update_rate_) entry->update_period = 1.0 / rate;
  }
  if (update_rate_ > 0.0 && params->has("update_rate")) {
    // ros2_control: a controller's own rate; at or above the manager's it runs at the manager's.
    double rate = 0.0;
    try {
      rate = params->get<double>("update_rate");
    } catch (const ParamsError& e) {
      return ControlResult::failure("could not load controller '" + name + "': " + e.what());
    }
    if (!(rate >= 0.0) || !std::isfinite(rate)) {
      return ControlResult::failure("could not load controller '" + name + "': parameter " +
                                    join_param_path(path, "update_rate") + " must be a rate >= 0 Hz");
    }
    if (rate > 0.0 && rate < update_rate_) entry->update_period = 1.0 / rate;
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
  // Read between two equal, even values of transitions_: no switch or restart under way in the
  // tick meanwhile. Such a change lasts a tick at most; a tick stalled longer (or a caller inside
  // the tick) gets the states as they are after 200 ms rather than no answer.
  const auto deadline = Clock::now() + std::chrono::milliseconds(200);
  for (;;) {
    const std::uint32_t before = transitions_.load(std::memory_order_acquire);
    const bool late = Clock::now() >= deadline;
    if ((before & 1U) == 0 || late) {
      std::vector<ControllerInfo> out = list_entries();
      if (late || transitions_.load(std::memory_order_acquire) == before) return out;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
}

std::vector<ControllerInfo> ControllerManager::list_entries() const {
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

}  // namespace mechsim::control
