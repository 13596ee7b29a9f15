#pragma once
// The controller manager: loads controllers by name from a parameter namespace (type from
// `<name>/type`), switches them on and off with ros_control's semantics, and runs the
// manager's part of the tick (DESIGN.md, "The tick"):
//
//   update(time, period):
//     propagate_actuator_to_joint_position
//     apply a pending switch (stop, then start: at the start of the tick, as requested)
//     zero the effort commands (the PR2 loop does the same: a joint nobody drives gets 0)
//     every running controller's update(); a controller that returns an error or throws is
//       stopped and reported, the others keep running
//     enforce_safety_limits
//     propagate_joint_to_actuator_effort
//
// Threads: update() is called by one real-time thread; every other member by non-real-time
// threads (serialised by an internal mutex that the tick never takes). update() allocates
// nothing, takes no lock a non-real-time thread can hold, and throws nothing. Loading and
// unloading publish a new controller list that the tick picks up; the caller waits at most one
// tick for the old list to be released. A switch request is validated at once and applied by
// the next tick.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "control/controller_registry.hpp"
#include "control/hardware.hpp"
#include "control/params.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::control {

// ros_control's strictness: STRICT refuses the whole switch on any problem (unknown name,
// wrong state, resource conflict); BEST_EFFORT skips unknown names and controllers already in
// the requested state and reports them, but, as ros_control's controller_manager, refuses the
// whole switch on a resource conflict. SkipConflicts is mechsim's own, for its tools (tune,
// bench): BEST_EFFORT that also drops a controller whose joints are taken, first come first
// served.
enum class SwitchStrictness : std::uint8_t { BestEffort, Strict, SkipConflicts };

// ros_control's states: "initialized" (loaded, never started), "running", "stopped".
enum class ControllerLifecycle : std::uint8_t { Initialized, Running, Stopped };
const char* lifecycle_name(ControllerLifecycle state);

struct ControllerStatistics {
  std::uint64_t updates = 0;
  double mean_update_time = 0.0;  // s, over all updates since load
  double max_update_time = 0.0;   // s
  std::uint64_t overruns = 0;     // updates that took longer than the period
  std::uint64_t failures = 0;     // times the manager stopped it (error status or exception)
};

struct ControllerInfo {
  std::string name;
  std::string type;
  ControllerLifecycle state = ControllerLifecycle::Initialized;
  std::vector<ResourceClaim> claims;  // per hardware interface
  std::vector<SensorUse> sensors;     // sensor interfaces read (no claim), per interface
  ControllerStatistics statistics;
  std::string failure;  // why the manager last stopped it; "" if it never failed
  // Part of a switch that was accepted and not applied yet (the next tick applies it; a paused
  // simulation does not tick): it will start, or stop, then.
  bool start_pending = false;
  bool stop_pending = false;
  // A Gazebo model plugin (add_model_plugin): `type` is its library file name, `origin` where its
  // <plugin> element is ("file:line").
  bool model_plugin = false;
  std::string origin;
  bool claims_base = false;  // moves the floating base (control/hardware.hpp)
};

struct ManagerStatistics {
  std::uint64_t ticks = 0;
  double mean_tick_time = 0.0;  // s, whole update()
  double max_tick_time = 0.0;   // s
  std::uint64_t overruns = 0;   // ticks longer than their period
};

struct ControlResult {
  bool ok = true;
  std::string error;
  explicit operator bool() const { return ok; }
  static ControlResult failure(std::string why) { return {false, std::move(why)}; }
};

struct SwitchResult {
  bool ok = true;
  std::string error;                 // why a STRICT switch was refused
  std::vector<std::string> starting; // what the next tick will start
  std::vector<std::string> stopping; // what the next tick will stop
  std::vector<std::string> skipped;  // BEST_EFFORT: "name: reason" for each request dropped
  explicit operator bool() const { return ok; }
};

class ControllerManager {
 public:
  // `params` is the namespace the controllers live in (e.g. the `cc8` map of a controller
  // YAML, path /cc8). The model and state must outlive the manager; `state` must be sized
  // like `model`. `registry` holds the types it can load (mechsim's:
  // controllers/builtin_controllers.hpp); more can be added through registry().
  ControllerManager(const mechanism::MechanismModel& model, mechanism::MechanismState& state,
                    Params params = Params(), ControllerRegistry registry = ControllerRegistry());
  ~ControllerManager();
  ControllerManager(const ControllerManager&) = delete;
  ControllerManager& operator=(const ControllerManager&) = delete;

  ControllerRegistry& registry() { return registry_; }
  // ros2_control's controller manager rate (Hz; its update_rate parameter), set before loading:
  // a controller whose parameters hold `update_rate` (Hz, > 0, below this rate) then updates at
  // its own rate, as ros2_control runs it: whenever at least 1/update_rate s passed since its
  // last update (the first update right after it starts), with that time as its period. 0 (the
  // default, ROS 1): every controller updates at every manager update.
  void set_update_rate(double hz) { update_rate_ = hz; }
  double update_rate() const { return update_rate_; }
  // The robot's IMU and force-torque sensors (control/sensor_hardware.hpp), offered to every
  // controller loaded from now on; must outlive the manager. Null: the robot has none.
  void set_sensor_hardware(const SensorHardware* sensors) { sensors_ = sensors; }
  const Params& params() const { return params_; }

  // Loads `name` (parameters at <namespace>/<name>, type at <namespace>/<name>/type). Errors
  // name the controller, the parameter path, and the joint where one is at fault.
  ControlResult load_controller(const std::string& name);
  // A Gazebo model plugin (DESIGN.md, "Gazebo plugins in a description"): a controller built
  // from the description's <plugin> element instead of the YAML. `controller` is initialised over
  // `params` with model-plugin hardware access (control/hardware.hpp: any joint of the mechanism,
  // any mode, the floating base) and started at once at `time`, as Gazebo loads a model's plugins
  // with the model: call it before the simulation ticks. It then runs for the life of the
  // manager: switch_controllers() and unload_controller() refuse to stop or unload it (a restart,
  // the same name in stop and start, is allowed: a simulation reset). `origin` ("file:line" of
  // the <plugin> element) appears in every message about it. Refused, naming both, when a joint
  // or the base it claims is claimed by another plugin or by a loaded controller.
  ControlResult add_model_plugin(const std::string& name, const std::string& type, std::unique_ptr<Controller> controller,
                                 const Params& params, const std::string& origin, double time);
  // Only a controller that is not running (and not part of a pending switch), and not a model plugin.
  ControlResult unload_controller(const std::string& name);
  SwitchResult switch_controllers(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                                  SwitchStrictness strictness);
  bool switch_pending() const { return switch_state_.load(std::memory_order_acquire) != kNoSwitch; }
  // Waits until the tick has applied the pending switch; false on timeout (seconds).
  bool wait_for_switch(double timeout) const;
  // Takes back the pending switch if no tick has begun to apply it: true when taken back (no
  // controller changes state), false when there was none or a tick applies (or applied) it. A
  // caller that gives up waiting calls this, so that its "not applied" answer stays true.
  bool cancel_pending_switch();
  // Applies a pending switch now, outside the tick (`time` in s): only for the owner of the tick
  // while no tick can run (its loop thread stopped, e.g. a model about to be deleted).
  void apply_pending_switch(double time) noexcept { try_apply_switch(time); }

  std::vector<ControllerInfo> list_controllers() const;
  std::optional<ControllerInfo> controller_info(const std::string& name) const;
  std::vector<std::string> list_controller_types() const { return registry_.types(); }
  // The controller object (for its ports), valid until it is unloaded; null when not loaded.
  Controller* controller(const std::string& name) const;
  ManagerStatistics statistics() const;

  // The real-time tick. `time` and `period` in seconds. `reset_controllers`: ros_control's flag of
  // the same name; every running controller (model plugins aside) is stopped and started again
  // before this tick's update (gazebo_ros_control sets it on the tick its e-stop is released).
  void update(double time, double period, bool reset_controllers = false) noexcept;
  // Asks the next update() to stop and start again every controller running then, model plugins
  // included, after any pending switch (a simulation reset: each starting() sees the spawn
  // state). Any thread; switches stay free meanwhile, as with gazebo_ros_control's reset flag.
  void request_restart() noexcept { restart_requested_.store(true, std::memory_order_release); }

 private:
  struct Entry;
  Entry* find(const std::string& name) const;
  std::vector<ControllerInfo> list_entries() const;  // under config_mutex_
  // Why `entry` may not claim what it claims beside the others loaded ("" when it may).
  std::string claim_conflict(const Entry& entry) const;
  void publish_list(std::vector<Entry*> list);
  void run_controllers(const std::vector<Entry*>& list, double time, double period) noexcept;
  // The hold_joints_ no running controller claims are held where they were when it let go.
  void hold_unclaimed_joints(const std::vector<Entry*>& list) noexcept;
  // Applies the pending switch unless cancel_pending_switch() takes it back first.
  void try_apply_switch(double time) noexcept;
  void apply_switch(double time) noexcept;
  // stopping() / starting() of one entry, in the tick: a throw from starting() leaves it stopped
  // with the reason recorded; a throw from stopping() still stops it.
  void stop(Entry& entry, double time) noexcept;
  void start(Entry& entry, double time) noexcept;
  void fail(Entry& entry, const char* prefix, const char* reason, double time) noexcept;

  const mechanism::MechanismModel& model_;
  mechanism::MechanismState& state_;
  Params params_;
  ControllerRegistry registry_;
  const SensorHardware* sensors_ = nullptr;
  double update_rate_ = 0.0;  // Hz; 0: no per-controller rates
  // gazebo_ros2_control's hold_joints: the joints that hold still while no running controller
  // claims them (JointInfo::hold_when_unclaimed), the tick's scratch of claims, and per joint
  // whether it is held and where (its position when it became unclaimed).
  std::vector<int> hold_joints_;
  std::vector<std::uint8_t> claimed_, held_;
  std::vector<double> hold_position_;

  mutable std::mutex config_mutex_;  // non-real-time callers only
  std::vector<std::unique_ptr<Entry>> entries_;

  // The controller list the tick iterates, double buffered (read-copy-update).
  std::vector<Entry*> lists_[2];
  std::atomic<int> current_list_{0};
  std::atomic<int> list_in_use_{-1};

  std::vector<Entry*> pending_start_;
  std::vector<Entry*> pending_stop_;
  // kPending: accepted, waiting for a tick; kApplying: a tick took it (cancel_pending_switch
  // can no longer take it back). Only switch_controllers() sets kPending, under config_mutex_.
  static constexpr int kNoSwitch = 0, kPending = 1, kApplying = 2;
  std::atomic<int> switch_state_{kNoSwitch};
  // A sequence lock over the tick's state changes of several controllers at once (a switch
  // applied, update()'s reset_controllers restart): odd while one is under way. Readers
  // (list_controllers) retry until they read the states between two equal even values, so that
  // a list never shows a switch half applied; the tick never waits for them.
  std::atomic<std::uint32_t> transitions_{0};
  std::atomic<bool> restart_requested_{false};

  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<std::uint64_t> tick_time_sum_ns_{0};
  std::atomic<std::uint64_t> tick_time_max_ns_{0};
  std::atomic<std::uint64_t> tick_overruns_{0};
};

}  // namespace mechsim::control
