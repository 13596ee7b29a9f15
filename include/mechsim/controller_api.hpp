#pragma once
// mechsim's controller plugin API, version 1: what a controller type built outside mechsim (a
// shared library loaded at run time) sees of the simulator. Header-only and self-contained: a
// plugin includes this file and nothing else of mechsim, links nothing of mechsim, and every call
// into mechsim is a virtual call on an object mechsim hands it. How to write, build and export a
// plugin: examples/controller_plugin/README.md.
//
// The lifecycle is ros_control's (mechsim's control/controller.hpp):
//   init(setup)            configuration time: read parameters, claim joints, add a command input
//                          and a state output. May allocate; throw std::runtime_error (or let the
//                          Setup's errors through) to refuse the configuration.
//   starting(time)         in the tick, when the controller is switched on
//   update(time, period)   in the tick, every period while running: no allocation, no blocking,
//                          no exceptions (noexcept); returns a Status
//   stopping(time)         in the tick, when switched off
// Times are simulation seconds; the period is the tick's (s, 0.001 by default).
//
// Binary compatibility: a library exports one C function, `mechsim_controller_library` (declare it
// with MECHSIM_CONTROLLER_LIBRARY below), returning a Library whose first field is the API version
// the library was built against. mechsim reads that field before anything else and refuses a
// library of another version with a message naming both versions. kApiVersion changes whenever
// anything in this file changes its layout (a virtual function added, removed or reordered, a
// struct field). Build plugins with the same C++ compiler family and standard library as mechsim
// (Debian 12's GCC 12 / libstdc++): std::string crosses the boundary.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mechsim::controller_api {

inline constexpr std::uint32_t kApiVersion = 1;

// The hardware interface a joint is claimed through (ros_control's Effort/Position/
// VelocityJointInterface); the joint's transmission must offer it.
enum class Interface : std::uint32_t { Effort = 0, Position = 1, Velocity = 2 };

// A claimed joint, valid from init() until the controller is destroyed. Real-time safe.
class Joint {
 public:
  virtual const std::string& name() const noexcept = 0;
  virtual double position() const noexcept = 0;  // rad or m
  virtual double velocity() const noexcept = 0;  // rad/s or m/s
  virtual double effort() const noexcept = 0;    // measured, N m or N
  // The command of the claimed interface: effort (N m or N), position (rad or m) or velocity
  // (rad/s or m/s). Written every update; the safety limits and the transmission apply after.
  virtual void set_command(double value) noexcept = 0;
  virtual double command() const noexcept = 0;

 protected:
  virtual ~Joint() = default;
};

// A scalar command from outside (a scenario timeline's `command:`, the ROS topic
// <controller>/command as std_msgs/Float64). Non-finite values are refused before they get here.
class CommandInput {
 public:
  virtual double read() noexcept = 0;             // real-time: the latest accepted value
  virtual void reset(double value) noexcept = 0;  // real-time: drop pending writes (starting())

 protected:
  virtual ~CommandInput() = default;
};

// What control_msgs/JointControllerState carries, published from the tick (the ROS topic
// <controller>/state, a scenario's `tracking` check, the report's controllers.csv).
struct ControllerState {
  double set_point = 0.0;          // what the controller aims at (rad, m, rad/s, N m ...)
  double process_value = 0.0;      // the measured quantity of the same kind
  double process_value_dot = 0.0;  // its rate
  double error = 0.0;              // set_point - process_value
  double command = 0.0;            // what was written to the joint
};

class StateOutput {
 public:
  virtual void publish(double time, double period, const ControllerState& state) noexcept = 0;  // real-time

 protected:
  virtual ~StateOutput() = default;
};

// The controller's parameters (its map in the controllers YAML or on the ROS parameter server).
// Lookups by key, with the same rules as mechsim's built-in controllers: a missing key without a
// fallback, or a value of the wrong kind, throws std::runtime_error naming the full parameter
// path (and the file and line for YAML).
class Parameters {
 public:
  virtual const std::string& path() const noexcept = 0;  // e.g. /gripper/finger_bang_bang
  virtual bool has(const std::string& key) const = 0;
  virtual double get_double(const std::string& key) const = 0;
  virtual double get_double_or(const std::string& key, double fallback) const = 0;
  virtual std::int64_t get_int_or(const std::string& key, std::int64_t fallback) const = 0;
  virtual bool get_bool_or(const std::string& key, bool fallback) const = 0;
  virtual std::string get_string(const std::string& key) const = 0;
  virtual std::string get_string_or(const std::string& key, const std::string& fallback) const = 0;
  virtual std::vector<std::string> get_string_list(const std::string& key) const = 0;
  virtual std::vector<double> get_double_list(const std::string& key) const = 0;

 protected:
  virtual ~Parameters() = default;
};

// What init() may use; valid during init() only (the objects it returns live on).
class Setup {
 public:
  virtual const Parameters& params() const noexcept = 0;
  // Claims `joint` through `iface`. Throws std::runtime_error naming the joint, `param_key` (the
  // parameter that named it) and what is available, for an unknown joint or an interface its
  // transmission does not offer. Two controllers claiming one joint are refused by the manager.
  virtual Joint& claim_joint(const std::string& joint, Interface iface, const std::string& param_key) = 0;
  // Adds the scalar command input "command" (at most one), starting at `initial`.
  virtual CommandInput& add_command_input(double initial) = 0;
  // Adds the state output "state" (at most one).
  virtual StateOutput& add_state_output() = 0;

 protected:
  virtual ~Setup() = default;
};

// What update() returns: ok, or a fault with a reason (a string literal: no allocation in the
// tick). A fault stops the controller and is reported with the reason.
struct Status {
  bool ok = true;
  const char* reason = "";
};

class Controller {
 public:
  virtual ~Controller() = default;
  Controller() = default;
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  virtual void init(Setup& setup) = 0;
  virtual void starting(double /*time*/) noexcept {}
  virtual Status update(double time, double period) noexcept = 0;
  virtual void stopping(double /*time*/) noexcept {}
};

// One controller class of a library: `type` is the C++ type name the plugin description's
// <class type="..."> gives (pluginlib's form, e.g. "my_pkg::MyController"); `create` makes one.
struct ControllerClass {
  const char* type;
  Controller* (*create)();
};

// What mechsim_controller_library() returns. api_version first, always.
struct Library {
  std::uint32_t api_version;
  std::uint32_t library_size;  // sizeof(Library) as the plugin saw it
  const ControllerClass* classes;
  std::size_t class_count;
};

template <class T>
Controller* create_controller() {
  return new T();
}

}  // namespace mechsim::controller_api

// The entry point's name, as mechsim looks it up with dlsym.
#define MECHSIM_CONTROLLER_LIBRARY_SYMBOL "mechsim_controller_library"

// Declares the library's entry point over a list of ControllerClass:
//   MECHSIM_CONTROLLER_LIBRARY({"my_pkg::MyController", mechsim::controller_api::create_controller<MyController>})
#define MECHSIM_CONTROLLER_LIBRARY(...)                                                                      \
  extern "C" __attribute__((visibility("default"))) const ::mechsim::controller_api::Library*               \
  mechsim_controller_library() {                                                                             \
    static const ::mechsim::controller_api::ControllerClass classes[] = {__VA_ARGS__};                      \
    static const ::mechsim::controller_api::Library library{                                                 \
        ::mechsim::controller_api::kApiVersion, sizeof(::mechsim::controller_api::Library), classes,         \
        sizeof(classes) / sizeof(classes[0])};                                                               \
    return &library;                                                                                         \
  }
