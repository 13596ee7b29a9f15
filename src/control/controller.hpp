#pragma once
// The controller interface, with ros_control's lifecycle:
//   init(hardware, params, error)  configuration time: read parameters, claim joints through
//                                  the hardware view, create ports. May allocate and throw
//                                  (ParamsError, ControllerConfigError); returning false with
//                                  `error` set works too. Either way the manager reports it.
//   starting(time)                 in the tick, when the controller is switched on
//   update(time, period)           in the tick, every period while running: no allocation, no
//                                  blocking, no exceptions; returns a status
//   stopping(time)                 in the tick, when switched off (or after a failure)
// Times are simulation seconds; period is the tick period in seconds.

#include <string>
#include <vector>

#include "control/hardware.hpp"
#include "control/params.hpp"
#include "control/ports.hpp"

namespace mechsim::control {

struct UpdateStatus {
  bool ok = true;
  const char* reason = "";  // a string literal (no allocation in the tick)

  static constexpr UpdateStatus Ok() { return {}; }
  static constexpr UpdateStatus Error(const char* why) { return {false, why}; }
};

class Controller {
 public:
  virtual ~Controller() = default;
  Controller() = default;
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  virtual bool init(RobotHardware& hardware, const Params& params, std::string& error) = 0;
  virtual void starting(double /*time*/) {}
  virtual UpdateStatus update(double time, double period) = 0;
  virtual void stopping(double /*time*/) {}

  // The controller's ports, valid from a successful init() until destruction. Non-real-time
  // (builds a vector): look ports up once, then use them from any thread.
  virtual std::vector<Port*> ports() { return {}; }
  Port* port(const std::string& name);  // null when absent
  template <class P>
  P* port_as(const std::string& name) {
    return dynamic_cast<P*>(port(name));
  }
};

inline Port* Controller::port(const std::string& name) {
  for (Port* p : ports()) {
    if (p->name() == name) return p;
  }
  return nullptr;
}

}  // namespace mechsim::control
