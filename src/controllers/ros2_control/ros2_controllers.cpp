#include "controllers/ros2_control/ros2_controllers.hpp"

#include <algorithm>

#include "controllers/builtin_controllers.hpp"
#include "controllers/drive/diff_drive_controller.hpp"
#include "controllers/joint/forward_command_controllers.hpp"
#include "controllers/ros2_control/imu_sensor_broadcaster.hpp"
#include "controllers/ros2_control/joint_state_broadcaster.hpp"
#include "controllers/ros2_control/tricycle_controller.hpp"
#include "controllers/trajectory/trajectory_controller.hpp"

namespace mechsim::control {

const std::vector<std::string>& ros2_controller_types() {
  static const std::vector<std::string> types = [] {
    std::vector<std::string> t{kJointStateBroadcasterType,
                               kImuSensorBroadcasterType,
                               kForwardCommandControllerType,
                               "position_controllers/JointGroupPositionController",
                               "velocity_controllers/JointGroupVelocityController",
                               "effort_controllers/JointGroupEffortController",
                               "joint_trajectory_controller/JointTrajectoryController",
                               kDiffDriveControllerType,
                               kTricycleControllerType};
    std::sort(t.begin(), t.end());
    return t;
  }();
  return types;
}

void register_ros2_controllers(ControllerRegistry& r) {
  using HI = HardwareInterface;
  const auto group = [](HI iface) {
    return [iface] { return std::make_unique<JointGroupCommandController>(iface); };
  };
  r.add(kJointStateBroadcasterType, [] { return std::make_unique<JointStateBroadcaster>(); });
  r.add(kImuSensorBroadcasterType, [] { return std::make_unique<ImuSensorBroadcaster>(); });
  r.add(kForwardCommandControllerType, [] { return std::make_unique<JointGroupCommandController>(); });
  r.add("position_controllers/JointGroupPositionController", group(HI::Position));
  r.add("velocity_controllers/JointGroupVelocityController", group(HI::Velocity));
  r.add("effort_controllers/JointGroupEffortController", group(HI::Effort));
  r.add("joint_trajectory_controller/JointTrajectoryController", [] { return JointTrajectoryController::ros2(); });
  r.add(kDiffDriveControllerType, [] { return std::make_unique<DiffDriveController>(true); });
  r.add(kTricycleControllerType, [] { return std::make_unique<TricycleController>(); });
}

ControllerRegistry ros2_controller_registry(const ControllerPluginSet& plugins) {
  ControllerRegistry registry = controller_registry_with_plugins(plugins);
  register_ros2_controllers(registry);
  return registry;
}

}  // namespace mechsim::control
