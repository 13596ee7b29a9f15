#pragma once
// A controller of a plugin library (include/mechsim/controller_api.hpp) as the controller manager
// sees it: a control::Controller forwarding the lifecycle to the plugin's object, with the API's
// Setup, Parameters, Joint, CommandInput and StateOutput implemented over mechsim's hardware
// view, parameter tree and ports ("command": ScalarCommandPort, "state":
// StatePort<JointControllerState>). Loading the library and finding the class is
// control/controller_plugins.hpp's part.

#include <memory>
#include <string>
#include <vector>

#include <mechsim/controller_api.hpp>

#include "control/controller.hpp"

namespace mechsim::control {

class PluginController : public Controller {
 public:
  // `library` keeps the plugin's code loaded for as long as `plugin` lives.
  PluginController(std::shared_ptr<void> library, std::unique_ptr<controller_api::Controller> plugin);
  ~PluginController() override;

  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override;

  struct Bindings;  // the API's objects the plugin holds: joints, command input, state output

 private:
  std::shared_ptr<void> library_;  // declared first: destroyed after the plugin's object
  std::unique_ptr<ScalarCommandPort> command_;
  std::unique_ptr<StatePort<JointControllerState>> state_;
  std::unique_ptr<Bindings> bindings_;
  std::unique_ptr<controller_api::Controller> plugin_;
};

}  // namespace mechsim::control
