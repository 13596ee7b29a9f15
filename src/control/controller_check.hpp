#pragma once
// Checking a controller YAML against a robot without running it (`mechsim check ROBOT
// --controllers FILE.yaml`): every controller found is loaded into a controller manager over a
// fresh mechanism state, and reported with its claims or its error.
//
// Where controllers are: a map with a `type` key is a controller; a map without one is a
// namespace and is searched (so both `cc8: {ctrl: {type: ...}}` and top-level controllers are
// found, as rosparam load + controller_manager spawner see them). Other values are ignored.

#include <string>
#include <vector>

#include "control/controller_registry.hpp"
#include "control/hardware.hpp"
#include "control/params.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::control {

struct ControllerCheck {
  std::string name;       // the controller's name in its namespace, e.g. steering_FL_position_controller
  std::string ns;         // its namespace's parameter path, e.g. /cc8 ("/" at top level)
  std::string path;       // its parameter path, e.g. /cc8/steering_FL_position_controller
  std::string type;       // as written; "" when missing
  std::vector<ResourceClaim> claims;  // what it would claim, when it loaded
  std::vector<SensorUse> sensors;     // the sensor interfaces it would read
  std::string error;      // "" when it loaded
  bool ok() const { return error.empty(); }
};

// One line for a report: "/cc8/x (effort_controllers/JointPositionController): effort [steering_FL]"
// (then "; reads ImuSensorInterface [zed2_imu_sensor]" for sensors read)
// or "/cc8/x (type): ERROR <message>".
std::string describe(const ControllerCheck& check);

// One entry per controller found, in document order. `registry` holds the types a manager can
// load (mechsim's: controllers/builtin_controllers.hpp).
// `sensors`: the robot's IMU and force-torque handles (make_sensor_hardware), null for none.
std::vector<ControllerCheck> check_controllers(const mechanism::MechanismModel& model, const Params& root,
                                               const ControllerRegistry& registry,
                                               const SensorHardware* sensors = nullptr);
// Reads the file first; a malformed or unreadable file throws ParamsError naming file and line.
std::vector<ControllerCheck> check_controllers_file(const mechanism::MechanismModel& model,
                                                    const std::string& yaml_path,
                                                    const ControllerRegistry& registry);

}  // namespace mechsim::control
