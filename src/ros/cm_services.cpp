// The controller manager services under <robot namespace>/controller_manager/, with
// controller_manager_msgs types, as ros_control's controller_manager offers them. A refused
// request answers ok=false (the call itself succeeds) and logs why, as ros_control does.
#include <controller_manager_msgs/ListControllerTypes.h>
#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/ReloadControllerLibraries.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>

#include "ros/sim_node.hpp"

namespace mechsim::ros {

namespace cmm = controller_manager_msgs;

int switch_strictness(int strictness) {
  // ros_control's controller_manager: 0 (what a request that leaves the field out carries, e.g.
  // `rosservice call .../switch_controller "{start_controllers: [x]}"`) is taken as BEST_EFFORT
  // with a warning. Other values ros_control silently treats as BEST_EFFORT; mechsim refuses
  // them as the typo they most likely are.
  if (strictness == 0) {
    ROS_WARN_STREAM("mechsim: switch_controller: strictness 0 given; it must be STRICT ("
                    << int{cmm::SwitchController::Request::STRICT} << ") or BEST_EFFORT ("
                    << int{cmm::SwitchController::Request::BEST_EFFORT}
                    << "): defaulting to BEST_EFFORT, as ros_control does");
    return cmm::SwitchController::Request::BEST_EFFORT;
  }
  if (strictness != cmm::SwitchController::Request::STRICT && strictness != cmm::SwitchController::Request::BEST_EFFORT) {
    ROS_ERROR_STREAM("mechsim: switch_controller refused: strictness " << strictness
                                                                       << " is neither BEST_EFFORT (1) nor STRICT (2)");
    return -1;
  }
  return strictness;
}

void SimNode::advertise_controller_manager() {
  ::ros::NodeHandle cm(robot_nh_, "controller_manager");

  services_.push_back(cm.advertiseService<cmm::ListControllers::Request, cmm::ListControllers::Response>(
      "list_controllers", [this](cmm::ListControllers::Request&, cmm::ListControllers::Response& res) {
        std::lock_guard<std::mutex> lock(manager_mutex_);
        for (const ControllerSummary& c : bridge_->list_controllers()) {
          cmm::ControllerState s;
          s.name = c.name;
          s.type = c.type;
          s.state = c.state;
          for (const ClaimedResources& claim : c.claims) {
            cmm::HardwareInterfaceResources r;
            r.hardware_interface = claim.hardware_interface;
            r.resources = claim.resources;
            s.claimed_resources.push_back(r);
          }
          res.controller.push_back(s);
        }
        return true;
      }));

  services_.push_back(cm.advertiseService<cmm::ListControllerTypes::Request, cmm::ListControllerTypes::Response>(
      "list_controller_types",
      [this](cmm::ListControllerTypes::Request&, cmm::ListControllerTypes::Response& res) {
        for (const std::string& type : bridge_->list_controller_types()) {
          res.types.push_back(type);
          // mechsim's controllers are built in; "base classes" are the interfaces they claim.
          res.base_classes.push_back("controller_interface::ControllerBase");
        }
        return true;
      }));

  services_.push_back(cm.advertiseService<cmm::LoadController::Request, cmm::LoadController::Response>(
      "load_controller", [this](cmm::LoadController::Request& req, cmm::LoadController::Response& res) {
        const BridgeResult r = load(req.name);
        res.ok = r.ok;
        if (!r.ok) ROS_ERROR_STREAM("mechsim: could not load controller '" << req.name << "': " << r.error);
        return true;
      }));

  services_.push_back(cm.advertiseService<cmm::UnloadController::Request, cmm::UnloadController::Response>(
      "unload_controller", [this](cmm::UnloadController::Request& req, cmm::UnloadController::Response& res) {
        const BridgeResult r = unload(req.name);
        res.ok = r.ok;
        if (!r.ok) ROS_ERROR_STREAM("mechsim: could not unload controller '" << req.name << "': " << r.error);
        return true;
      }));

  services_.push_back(cm.advertiseService<cmm::SwitchController::Request, cmm::SwitchController::Response>(
      "switch_controller", [this](cmm::SwitchController::Request& req, cmm::SwitchController::Response& res) {
        const int strictness = switch_strictness(req.strictness);
        if (strictness < 0) {
          res.ok = false;
          return true;
        }
        // start_asap needs no handling: a switch is applied at the start of the next tick.
        std::lock_guard<std::mutex> lock(manager_mutex_);
        const BridgeResult r = bridge_->switch_controllers(
            req.start_controllers, req.stop_controllers, strictness == cmm::SwitchController::Request::STRICT,
            req.timeout);
        res.ok = r.ok;
        if (!r.ok) {
          ROS_ERROR_STREAM("mechsim: switch_controller refused: " << r.error);
        } else if (!r.error.empty()) {
          ROS_WARN_STREAM("mechsim: switch_controller (BEST_EFFORT) skipped: " << r.error);
        }
        return true;
      }));

  services_.push_back(
      cm.advertiseService<cmm::ReloadControllerLibraries::Request, cmm::ReloadControllerLibraries::Response>(
          "reload_controller_libraries",
          [this](cmm::ReloadControllerLibraries::Request& req, cmm::ReloadControllerLibraries::Response& res) {
            // Controllers are compiled in: nothing to reload. As ros_control, refuse while
            // controllers are loaded unless force_kill, which stops and unloads them first.
            std::vector<ControllerSummary> loaded;
            {
              std::lock_guard<std::mutex> lock(manager_mutex_);
              loaded = bridge_->list_controllers();
            }
            if (!loaded.empty() && !req.force_kill) {
              ROS_ERROR_STREAM("mechsim: reload_controller_libraries: " << loaded.size()
                                                                        << " controllers loaded and force_kill is false");
              res.ok = false;
              return true;
            }
            std::vector<std::string> running;
            for (const ControllerSummary& c : loaded) {
              if (c.state == "running") running.push_back(c.name);
            }
            bool ok = true;
            if (!running.empty()) {
              std::lock_guard<std::mutex> lock(manager_mutex_);
              ok = bridge_->switch_controllers({}, running, true, 5.0).ok;
            }
            for (const ControllerSummary& c : loaded) ok = unload(c.name).ok && ok;
            res.ok = ok;
            return true;
          }));
}

}  // namespace mechsim::ros
