#pragma once
// ros2_control's controller manager on the wire: node `<ns>/controller_manager` with
// controller_manager_msgs' services (each distro's layout), controllers going through
// ros2_control's lifecycle as `ros2 control list_controllers` shows it, and the parameters of the
// manager and of each controller's node (parameters.hpp). mechsim's controller manager
// (bridge::SimBridge) does the work; this maps the services onto it:
//
//   load_controller       the controller must be declared (`<name>.type` in the manager's
//                         parameters, from the YAML or set by the spawner); it becomes
//                         `unconfigured` (its node and parameters exist, mechsim has not built it)
//   configure_controller  mechsim builds it from its node's parameters: `inactive` (an inactive
//                         one is built again, with the parameters as they are now)
//   switch_controller     activate/deactivate (STRICT or BEST_EFFORT, timeout), in one tick
//   unload_controller     an unconfigured or inactive one; an active one is refused
//   list_*                as ros2_control fills them; set_hardware_component_state: mechsim's
//                         simulated hardware is always active (other targets are refused)
//   reload_controller_libraries  refused while controllers are loaded, unless force_kill
//
// A refusal answers ok = false and logs why (ros2_control logs it too); the world goes on.
// Threads: requests run on the manager's worker, in order.

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "bridge/sim_bridge.hpp"
#include "ros2/node.hpp"
#include "ros2/worker.hpp"

namespace mechsim::ros2 {

class SimNode;
class ParameterServer;

class ControllerManagerNode {
 public:
  explicit ControllerManagerNode(SimNode& model);
  ~ControllerManagerNode();
  ControllerManagerNode(const ControllerManagerNode&) = delete;
  ControllerManagerNode& operator=(const ControllerManagerNode&) = delete;

  std::vector<std::string> service_lines() const;
  // The model is leaving: every record goes (its controllers are unloaded by the caller).
  void forget_all();
  void on_tick(double time);  // loop thread: the actions' feedback

  // ---- the services' work (public for tests and the command line)
  struct Result {
    bool ok = true;
    std::string why;  // logged on a refusal
  };
  Result load(const std::string& name);
  Result configure(const std::string& name);
  Result unload(const std::string& name);
  // strictness: 1 BEST_EFFORT, 2 STRICT (0: BEST_EFFORT with a warning, as ros2_control)
  Result switch_controllers(std::vector<std::string> activate, std::vector<std::string> deactivate, int strictness,
                            double timeout);
  Result reload_libraries(bool force_kill);
  struct ControllerRow {
    std::string name, state, type;
    std::vector<std::string> claimed, required_command, required_state;
  };
  std::vector<ControllerRow> list();
  struct InterfaceRow {
    std::string name;
    bool available = true, claimed = false;
  };
  void hardware_interfaces(std::vector<InterfaceRow>& command, std::vector<InterfaceRow>& state);
  std::string component_name() const;
  std::string component_plugin() const;

 private:
  struct Record {
    std::string state;  // unconfigured, inactive, active
    std::string type;
  };
  void sync();  // records <- what mechsim's manager has (under mutex_)
  std::string declared_type(const std::string& name) const;
  template <class Msgs>
  void advertise_distro();
  void advertise_common();
  void make_controller_node(const std::string& name);  // its parameters (under mutex_)

  SimNode& model_;
  bridge::SimBridge& bridge_;
  std::unique_ptr<Node> node_;
  std::unique_ptr<Worker> worker_;
  std::unique_ptr<ParameterServer> parameters_;  // the manager's own
  mutable std::mutex mutex_;
  std::map<std::string, Record> records_;
  std::map<std::string, std::unique_ptr<Node>> controller_nodes_;  // unconfigured controllers' nodes
  std::map<std::string, std::unique_ptr<ParameterServer>> controller_parameters_;
  std::vector<std::shared_ptr<void>> servers_;
  std::vector<std::string> lines_;
};

}  // namespace mechsim::ros2
