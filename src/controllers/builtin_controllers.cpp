#include "controllers/builtin_controllers.hpp"

#include "controllers/joint/forward_command_controllers.hpp"
#include "controllers/joint/joint_state_controller.hpp"
#include "controllers/joint/pid_joint_controllers.hpp"
#include "controllers/trajectory/trajectory_controller.hpp"
#include "controllers/drive/diff_drive_controller.hpp"
#include "controllers/drive/rover_drive_controller.hpp"
#include "controllers/drive/pr2_base_controller.hpp"
#include "controllers/drive/pr2_odometry.hpp"
#include "controllers/gripper/gripper_action_controller.hpp"
#include "controllers/gripper/pr2_gripper_controller.hpp"
#include "controllers/pr2/laser_scanner_traj_controller.hpp"
#include "controllers/sensor/sensor_state_controllers.hpp"

namespace mechsim::control {

void register_builtin_controllers(ControllerRegistry& r) {
  using HI = HardwareInterface;
  const auto single = [](HI iface) {
    return [iface] { return std::make_unique<JointCommandController>(iface); };
  };
  const auto group = [](HI iface) {
    return [iface] { return std::make_unique<JointGroupCommandController>(iface); };
  };
  const auto position_pid = [](ControllerFlavour f) {
    return [f] { return std::make_unique<JointPositionPidController>(f); };
  };
  const auto velocity_pid = [](ControllerFlavour f) {
    return [f] { return std::make_unique<JointVelocityPidController>(f); };
  };

  r.add("effort_controllers/JointEffortController", single(HI::Effort));
  r.add("effort_controllers/JointPositionController", position_pid(ControllerFlavour::RosControl));
  r.add("effort_controllers/JointVelocityController", velocity_pid(ControllerFlavour::RosControl));
  r.add("effort_controllers/JointGroupEffortController", group(HI::Effort));
  r.add("effort_controllers/JointGroupPositionController",
        [] { return std::make_unique<JointGroupPositionPidController>(); });

  r.add("position_controllers/JointPositionController", single(HI::Position));
  r.add("position_controllers/JointGroupPositionController", group(HI::Position));
  r.add("velocity_controllers/JointVelocityController", single(HI::Velocity));
  r.add("velocity_controllers/JointGroupVelocityController", group(HI::Velocity));

  r.add("robot_mechanism_controllers/JointEffortController", single(HI::Effort));
  r.add("robot_mechanism_controllers/JointPositionController", position_pid(ControllerFlavour::Pr2));
  r.add("robot_mechanism_controllers/JointVelocityController", velocity_pid(ControllerFlavour::Pr2));

  r.add("joint_state_controller/JointStateController", [] { return std::make_unique<JointStateController>(); });
  r.add(kImuSensorControllerType, [] { return std::make_unique<ImuSensorController>(); });
  r.add(kForceTorqueSensorControllerType, [] { return std::make_unique<ForceTorqueSensorController>(); });

  const auto trajectory = [](HI iface, ControllerFlavour f) {
    return [iface, f] { return std::make_unique<JointTrajectoryController>(iface, f); };
  };
  r.add("effort_controllers/JointTrajectoryController", trajectory(HI::Effort, ControllerFlavour::RosControl));
  r.add("position_controllers/JointTrajectoryController", trajectory(HI::Position, ControllerFlavour::RosControl));
  r.add("velocity_controllers/JointTrajectoryController", trajectory(HI::Velocity, ControllerFlavour::RosControl));
  r.add("joint_trajectory_controller/JointTrajectoryController",
        [] { return std::make_unique<JointTrajectoryController>(); });
  r.add("robot_mechanism_controllers/JointTrajectoryActionController", trajectory(HI::Effort, ControllerFlavour::Pr2));

  r.add(kRoverDriveControllerType, [] { return std::make_unique<RoverDriveController>(); });
  r.add(kDiffDriveControllerType, [] { return std::make_unique<DiffDriveController>(); });

  r.add(kPr2BaseController2Type, [] { return std::make_unique<Pr2BaseController>(); });
  r.add(kPr2BaseControllerType, [] { return std::make_unique<Pr2BaseController>(); });
  r.add(kPr2OdometryType, [] { return std::make_unique<Pr2OdometryController>(); });
  r.add(kPr2GripperControllerType, [] { return std::make_unique<Pr2GripperController>(); });
  r.add(kPositionGripperActionType, [] { return std::make_unique<GripperActionController>(HI::Position); });
  r.add(kEffortGripperActionType, [] { return std::make_unique<GripperActionController>(HI::Effort); });
  r.add(kLaserScannerTrajControllerType, [] { return std::make_unique<LaserScannerTrajController>(); });
}

ControllerRegistry builtin_controller_registry() {
  ControllerRegistry registry;
  register_builtin_controllers(registry);
  return registry;
}

ControllerRegistry controller_registry_with_plugins(const ControllerPluginSet& plugins) {
  ControllerRegistry registry = builtin_controller_registry();
  register_controller_plugins(registry, plugins);
  return registry;
}

}  // namespace mechsim::control
