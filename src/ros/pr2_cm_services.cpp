// The PR2's controller manager services (pr2_mechanism_msgs) under /pr2_controller_manager/,
// for a robot with the PR2 gazebo plugin or with the node's pr2 parameter set. Same manager as
// <ns>/controller_manager; pr2_controller_manager lists states as "running"/"stopped".
#include <pr2_mechanism_msgs/ListControllerTypes.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <pr2_mechanism_msgs/LoadController.h>
#include <pr2_mechanism_msgs/SwitchController.h>
#include <pr2_mechanism_msgs/UnloadController.h>

#include "ros/sim_node.hpp"

namespace mechsim::ros {

namespace pmm = pr2_mechanism_msgs;

void SimNode::advertise_pr2_controller_manager() {
  ::ros::NodeHandle cm("/pr2_controller_manager");
  services_.push_back(cm.advertiseService<pmm::ListControllers::Request, pmm::ListControllers::Response>(
      "list_controllers", [this](pmm::ListControllers::Request&, pmm::ListControllers::Response& res) {
        std::lock_guard<std::mutex> lock(manager_mutex_);
        for (const ControllerSummary& c : bridge_->list_controllers()) {
          res.controllers.push_back(c.name);
          res.state.push_back(c.state == "running" ? "running" : "stopped");
        }
        return true;
      }));
  services_.push_back(cm.advertiseService<pmm::ListControllerTypes::Request, pmm::ListControllerTypes::Response>(
      "list_controller_types", [this](pmm::ListControllerTypes::Request&, pmm::ListControllerTypes::Response& res) {
        res.types = bridge_->list_controller_types();
        return true;
      }));
  services_.push_back(cm.advertiseService<pmm::LoadController::Request, pmm::LoadController::Response>(
      "load_controller", [this](pmm::LoadController::Request& req, pmm::LoadController::Response& res) {
        const BridgeResult r = load(req.name);
        res.ok = r.ok;
        if (!r.ok) ROS_ERROR_STREAM("mechsim: could not load controller '" << req.name << "': " << r.error);
        return true;
      }));
  services_.push_back(cm.advertiseService<pmm::UnloadController::Request, pmm::UnloadController::Response>(
      "unload_controller", [this](pmm::UnloadController::Request& req, pmm::UnloadController::Response& res) {
        const BridgeResult r = unload(req.name);
        res.ok = r.ok;
        if (!r.ok) ROS_ERROR_STREAM("mechsim: could not unload controller '" << req.name << "': " << r.error);
        return true;
      }));
  services_.push_back(cm.advertiseService<pmm::SwitchController::Request, pmm::SwitchController::Response>(
      "switch_controller", [this](pmm::SwitchController::Request& req, pmm::SwitchController::Response& res) {
        const int strictness = switch_strictness(req.strictness);
        if (strictness < 0) {
          res.ok = false;
          return true;
        }
        std::lock_guard<std::mutex> lock(manager_mutex_);
        const BridgeResult r = bridge_->switch_controllers(
            req.start_controllers, req.stop_controllers, strictness == pmm::SwitchController::Request::STRICT, 5.0);
        res.ok = r.ok;
        if (!r.ok) ROS_ERROR_STREAM("mechsim: switch_controller refused: " << r.error);
        return true;
      }));
}

}  // namespace mechsim::ros
