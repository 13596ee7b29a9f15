#pragma once
// The ROS 2 message, service and action field lists the test peers use, written from the official
// definitions (rosidl's .msg/.srv/.action files of Humble and Jazzy): nothing of mechsim's
// generated code. A message is "pkg/Name", a service part "pkg/srv/Name_Request", an action part
// "pkg/action/Name_Goal" (and rosidl's _SendGoal_Request, _GetResult_Response, _FeedbackMessage,
// ...). Field types: int8..uint64, float32, float64, bool, string, another name; T[N] an array,
// T[] a sequence.

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mechsim::ros2::peers {

// ROS 2 message fields, from the official .msg files (Humble and Jazzy have the same ones, but
// rmw_dds_common/Gid: 24 bytes in Humble, 16 from Iron on).
using Fields = std::vector<std::pair<std::string, std::string>>;
inline std::map<std::string, Fields> definitions(const std::string& distro) {
  std::map<std::string, Fields> defs = {
      {"builtin_interfaces/Time", {{"sec", "int32"}, {"nanosec", "uint32"}}},
      {"builtin_interfaces/Duration", {{"sec", "int32"}, {"nanosec", "uint32"}}},
      {"rosgraph_msgs/Clock", {{"clock", "builtin_interfaces/Time"}}},
      {"std_msgs/Header", {{"stamp", "builtin_interfaces/Time"}, {"frame_id", "string"}}},
      {"std_msgs/String", {{"data", "string"}}},
      {"std_msgs/MultiArrayDimension", {{"label", "string"}, {"size", "uint32"}, {"stride", "uint32"}}},
      {"std_msgs/MultiArrayLayout", {{"dim", "std_msgs/MultiArrayDimension[]"}, {"data_offset", "uint32"}}},
      {"std_msgs/Float64MultiArray", {{"layout", "std_msgs/MultiArrayLayout"}, {"data", "float64[]"}}},
      {"geometry_msgs/Vector3", {{"x", "float64"}, {"y", "float64"}, {"z", "float64"}}},
      {"geometry_msgs/Point", {{"x", "float64"}, {"y", "float64"}, {"z", "float64"}}},
      {"geometry_msgs/Quaternion", {{"x", "float64"}, {"y", "float64"}, {"z", "float64"}, {"w", "float64"}}},
      {"geometry_msgs/Pose", {{"position", "geometry_msgs/Point"}, {"orientation", "geometry_msgs/Quaternion"}}},
      {"geometry_msgs/PoseWithCovariance", {{"pose", "geometry_msgs/Pose"}, {"covariance", "float64[36]"}}},
      {"geometry_msgs/Twist", {{"linear", "geometry_msgs/Vector3"}, {"angular", "geometry_msgs/Vector3"}}},
      {"geometry_msgs/TwistStamped", {{"header", "std_msgs/Header"}, {"twist", "geometry_msgs/Twist"}}},
      {"geometry_msgs/TwistWithCovariance", {{"twist", "geometry_msgs/Twist"}, {"covariance", "float64[36]"}}},
      {"geometry_msgs/Transform", {{"translation", "geometry_msgs/Vector3"}, {"rotation", "geometry_msgs/Quaternion"}}},
      {"geometry_msgs/TransformStamped",
       {{"header", "std_msgs/Header"}, {"child_frame_id", "string"}, {"transform", "geometry_msgs/Transform"}}},
      {"tf2_msgs/TFMessage", {{"transforms", "geometry_msgs/TransformStamped[]"}}},
      {"sensor_msgs/JointState",
       {{"header", "std_msgs/Header"}, {"name", "string[]"}, {"position", "float64[]"}, {"velocity", "float64[]"},
        {"effort", "float64[]"}}},
      {"sensor_msgs/LaserScan",
       {{"header", "std_msgs/Header"}, {"angle_min", "float32"}, {"angle_max", "float32"}, {"angle_increment", "float32"},
        {"time_increment", "float32"}, {"scan_time", "float32"}, {"range_min", "float32"}, {"range_max", "float32"},
        {"ranges", "float32[]"}, {"intensities", "float32[]"}}},
      {"sensor_msgs/Image",
       {{"header", "std_msgs/Header"}, {"height", "uint32"}, {"width", "uint32"}, {"encoding", "string"},
        {"is_bigendian", "uint8"}, {"step", "uint32"}, {"data", "uint8[]"}}},
      {"sensor_msgs/RegionOfInterest",
       {{"x_offset", "uint32"}, {"y_offset", "uint32"}, {"height", "uint32"}, {"width", "uint32"}, {"do_rectify", "bool"}}},
      {"sensor_msgs/CameraInfo",
       {{"header", "std_msgs/Header"}, {"height", "uint32"}, {"width", "uint32"}, {"distortion_model", "string"},
        {"d", "float64[]"}, {"k", "float64[9]"}, {"r", "float64[9]"}, {"p", "float64[12]"}, {"binning_x", "uint32"},
        {"binning_y", "uint32"}, {"roi", "sensor_msgs/RegionOfInterest"}}},
      {"sensor_msgs/Imu",
       {{"header", "std_msgs/Header"}, {"orientation", "geometry_msgs/Quaternion"}, {"orientation_covariance", "float64[9]"},
        {"angular_velocity", "geometry_msgs/Vector3"}, {"angular_velocity_covariance", "float64[9]"},
        {"linear_acceleration", "geometry_msgs/Vector3"}, {"linear_acceleration_covariance", "float64[9]"}}},
      {"nav_msgs/Odometry",
       {{"header", "std_msgs/Header"}, {"child_frame_id", "string"}, {"pose", "geometry_msgs/PoseWithCovariance"},
        {"twist", "geometry_msgs/TwistWithCovariance"}}},
      {"trajectory_msgs/JointTrajectoryPoint",
       {{"positions", "float64[]"}, {"velocities", "float64[]"}, {"accelerations", "float64[]"}, {"effort", "float64[]"},
        {"time_from_start", "builtin_interfaces/Duration"}}},
      {"trajectory_msgs/JointTrajectory",
       {{"header", "std_msgs/Header"}, {"joint_names", "string[]"}, {"points", "trajectory_msgs/JointTrajectoryPoint[]"}}},
      {"std_srvs/srv/Empty_Request", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"std_srvs/srv/Empty_Response", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"rmw_dds_common/Gid", {{"data", distro == "humble" ? "uint8[24]" : "uint8[16]"}}},
      // Services of issue 37, from the official definitions (gazebo_ros_pkgs ros2, ros2_control
      // humble and jazzy, rcl_interfaces, action_msgs, control_msgs).
      {"geometry_msgs/Pose", {{"position", "geometry_msgs/Point"}, {"orientation", "geometry_msgs/Quaternion"}}},
      {"gazebo_msgs/EntityState",
       {{"name", "string"}, {"pose", "geometry_msgs/Pose"}, {"twist", "geometry_msgs/Twist"}, {"reference_frame", "string"}}},
      {"gazebo_msgs/srv/SpawnEntity_Request",
       {{"name", "string"}, {"xml", "string"}, {"robot_namespace", "string"}, {"initial_pose", "geometry_msgs/Pose"},
        {"reference_frame", "string"}}},
      {"gazebo_msgs/srv/SpawnEntity_Response", {{"success", "bool"}, {"status_message", "string"}}},
      {"gazebo_msgs/srv/DeleteEntity_Request", {{"name", "string"}}},
      {"gazebo_msgs/srv/DeleteEntity_Response", {{"success", "bool"}, {"status_message", "string"}}},
      {"gazebo_msgs/srv/GetEntityState_Request", {{"name", "string"}, {"reference_frame", "string"}}},
      {"gazebo_msgs/srv/GetEntityState_Response",
       {{"header", "std_msgs/Header"}, {"state", "gazebo_msgs/EntityState"}, {"success", "bool"}}},
      {"gazebo_msgs/srv/SetEntityState_Request", {{"state", "gazebo_msgs/EntityState"}}},
      {"gazebo_msgs/srv/SetEntityState_Response", {{"success", "bool"}}},
      {"gazebo_msgs/srv/GetModelList_Request", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"gazebo_msgs/srv/GetModelList_Response", {{"header", "std_msgs/Header"}, {"model_names", "string[]"}, {"success", "bool"}}},
      {"controller_manager_msgs/ChainConnection", {{"name", "string"}, {"reference_interfaces", "string[]"}}},
      {"controller_manager_msgs/ControllerState",
       distro == "humble"
           ? Fields{{"name", "string"}, {"state", "string"}, {"type", "string"}, {"claimed_interfaces", "string[]"},
                    {"required_command_interfaces", "string[]"}, {"required_state_interfaces", "string[]"},
                    {"is_chainable", "bool"}, {"is_chained", "bool"},
                    {"chain_connections", "controller_manager_msgs/ChainConnection[]"}}
           : Fields{{"name", "string"}, {"state", "string"}, {"type", "string"}, {"claimed_interfaces", "string[]"},
                    {"required_command_interfaces", "string[]"}, {"required_state_interfaces", "string[]"},
                    {"is_chainable", "bool"}, {"is_chained", "bool"}, {"exported_state_interfaces", "string[]"},
                    {"reference_interfaces", "string[]"}, {"chain_connections", "controller_manager_msgs/ChainConnection[]"}}},
      {"controller_manager_msgs/HardwareInterface", {{"name", "string"}, {"is_available", "bool"}, {"is_claimed", "bool"}}},
      {"lifecycle_msgs/State", {{"id", "uint8"}, {"label", "string"}}},
      {"controller_manager_msgs/HardwareComponentState",
       {{"name", "string"}, {"type", "string"}, {distro == "humble" ? "class_type" : "plugin_name", "string"},
        {"state", "lifecycle_msgs/State"}, {"command_interfaces", "controller_manager_msgs/HardwareInterface[]"},
        {"state_interfaces", "controller_manager_msgs/HardwareInterface[]"}}},
      {"controller_manager_msgs/srv/ListControllers_Request", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"controller_manager_msgs/srv/ListControllers_Response", {{"controller", "controller_manager_msgs/ControllerState[]"}}},
      {"controller_manager_msgs/srv/ListControllerTypes_Request", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"controller_manager_msgs/srv/ListControllerTypes_Response", {{"types", "string[]"}, {"base_classes", "string[]"}}},
      {"controller_manager_msgs/srv/ListHardwareInterfaces_Request", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"controller_manager_msgs/srv/ListHardwareInterfaces_Response",
       {{"command_interfaces", "controller_manager_msgs/HardwareInterface[]"},
        {"state_interfaces", "controller_manager_msgs/HardwareInterface[]"}}},
      {"controller_manager_msgs/srv/ListHardwareComponents_Request", {{"structure_needs_at_least_one_member", "uint8"}}},
      {"controller_manager_msgs/srv/ListHardwareComponents_Response",
       {{"component", "controller_manager_msgs/HardwareComponentState[]"}}},
      {"controller_manager_msgs/srv/LoadController_Request", {{"name", "string"}}},
      {"controller_manager_msgs/srv/LoadController_Response", {{"ok", "bool"}}},
      {"controller_manager_msgs/srv/ConfigureController_Request", {{"name", "string"}}},
      {"controller_manager_msgs/srv/ConfigureController_Response", {{"ok", "bool"}}},
      {"controller_manager_msgs/srv/UnloadController_Request", {{"name", "string"}}},
      {"controller_manager_msgs/srv/UnloadController_Response", {{"ok", "bool"}}},
      {"controller_manager_msgs/srv/ReloadControllerLibraries_Request", {{"force_kill", "bool"}}},
      {"controller_manager_msgs/srv/ReloadControllerLibraries_Response", {{"ok", "bool"}}},
      {"controller_manager_msgs/srv/SetHardwareComponentState_Request", {{"name", "string"}, {"target_state", "lifecycle_msgs/State"}}},
      {"controller_manager_msgs/srv/SetHardwareComponentState_Response", {{"ok", "bool"}, {"state", "lifecycle_msgs/State"}}},
      {"controller_manager_msgs/srv/SwitchController_Request",
       distro == "humble"
           ? Fields{{"activate_controllers", "string[]"}, {"deactivate_controllers", "string[]"},
                    {"start_controllers", "string[]"}, {"stop_controllers", "string[]"}, {"strictness", "int32"},
                    {"activate_asap", "bool"}, {"start_asap", "bool"}, {"timeout", "builtin_interfaces/Duration"}}
           : Fields{{"activate_controllers", "string[]"}, {"deactivate_controllers", "string[]"}, {"strictness", "int32"},
                    {"activate_asap", "bool"}, {"timeout", "builtin_interfaces/Duration"}}},
      {"controller_manager_msgs/srv/SwitchController_Response", {{"ok", "bool"}}},
      {"rcl_interfaces/ParameterValue",
       {{"type", "uint8"}, {"bool_value", "bool"}, {"integer_value", "int64"}, {"double_value", "float64"},
        {"string_value", "string"}, {"byte_array_value", "uint8[]"}, {"bool_array_value", "bool[]"},
        {"integer_array_value", "int64[]"}, {"double_array_value", "float64[]"}, {"string_array_value", "string[]"}}},
      {"rcl_interfaces/Parameter", {{"name", "string"}, {"value", "rcl_interfaces/ParameterValue"}}},
      {"rcl_interfaces/ParameterEvent",
       {{"stamp", "builtin_interfaces/Time"}, {"node", "string"}, {"new_parameters", "rcl_interfaces/Parameter[]"},
        {"changed_parameters", "rcl_interfaces/Parameter[]"}, {"deleted_parameters", "rcl_interfaces/Parameter[]"}}},
      {"rcl_interfaces/SetParametersResult", {{"successful", "bool"}, {"reason", "string"}}},
      {"rcl_interfaces/ListParametersResult", {{"names", "string[]"}, {"prefixes", "string[]"}}},
      {"rcl_interfaces/FloatingPointRange", {{"from_value", "float64"}, {"to_value", "float64"}, {"step", "float64"}}},
      {"rcl_interfaces/IntegerRange", {{"from_value", "int64"}, {"to_value", "int64"}, {"step", "uint64"}}},
      {"rcl_interfaces/ParameterDescriptor",
       {{"name", "string"}, {"type", "uint8"}, {"description", "string"}, {"additional_constraints", "string"},
        {"read_only", "bool"}, {"dynamic_typing", "bool"}, {"floating_point_range", "rcl_interfaces/FloatingPointRange[]"},
        {"integer_range", "rcl_interfaces/IntegerRange[]"}}},
      {"rcl_interfaces/srv/ListParameters_Request", {{"prefixes", "string[]"}, {"depth", "uint64"}}},
      {"rcl_interfaces/srv/ListParameters_Response", {{"result", "rcl_interfaces/ListParametersResult"}}},
      {"rcl_interfaces/srv/GetParameters_Request", {{"names", "string[]"}}},
      {"rcl_interfaces/srv/GetParameters_Response", {{"values", "rcl_interfaces/ParameterValue[]"}}},
      {"rcl_interfaces/srv/SetParameters_Request", {{"parameters", "rcl_interfaces/Parameter[]"}}},
      {"rcl_interfaces/srv/SetParameters_Response", {{"results", "rcl_interfaces/SetParametersResult[]"}}},
      {"rcl_interfaces/srv/DescribeParameters_Request", {{"names", "string[]"}}},
      {"rcl_interfaces/srv/DescribeParameters_Response", {{"descriptors", "rcl_interfaces/ParameterDescriptor[]"}}},
      {"rcl_interfaces/srv/GetParameterTypes_Request", {{"names", "string[]"}}},
      {"rcl_interfaces/srv/GetParameterTypes_Response", {{"types", "uint8[]"}}},
      // Actions (rosidl's action -> messages mapping): control_msgs (Humble 4.x and Jazzy 5.x alike),
      // action_msgs, unique_identifier_msgs.
      {"unique_identifier_msgs/UUID", {{"uuid", "uint8[16]"}}},
      {"action_msgs/GoalInfo", {{"goal_id", "unique_identifier_msgs/UUID"}, {"stamp", "builtin_interfaces/Time"}}},
      {"action_msgs/GoalStatus", {{"goal_info", "action_msgs/GoalInfo"}, {"status", "int8"}}},
      {"action_msgs/GoalStatusArray", {{"status_list", "action_msgs/GoalStatus[]"}}},
      {"action_msgs/srv/CancelGoal_Request", {{"goal_info", "action_msgs/GoalInfo"}}},
      {"action_msgs/srv/CancelGoal_Response", {{"return_code", "int8"}, {"goals_canceling", "action_msgs/GoalInfo[]"}}},
      {"geometry_msgs/Transform", {{"translation", "geometry_msgs/Vector3"}, {"rotation", "geometry_msgs/Quaternion"}}},
      {"trajectory_msgs/MultiDOFJointTrajectoryPoint",
       {{"transforms", "geometry_msgs/Transform[]"}, {"velocities", "geometry_msgs/Twist[]"},
        {"accelerations", "geometry_msgs/Twist[]"}, {"time_from_start", "builtin_interfaces/Duration"}}},
      {"trajectory_msgs/MultiDOFJointTrajectory",
       {{"header", "std_msgs/Header"}, {"joint_names", "string[]"}, {"points", "trajectory_msgs/MultiDOFJointTrajectoryPoint[]"}}},
      {"control_msgs/JointTolerance", {{"name", "string"}, {"position", "float64"}, {"velocity", "float64"}, {"acceleration", "float64"}}},
      {"control_msgs/JointComponentTolerance",
       {{"joint_name", "string"}, {"component", "uint16"}, {"position", "float64"}, {"velocity", "float64"}, {"acceleration", "float64"}}},
      {"control_msgs/GripperCommand", {{"position", "float64"}, {"max_effort", "float64"}}},
      {"control_msgs/action/FollowJointTrajectory_Goal",
       {{"trajectory", "trajectory_msgs/JointTrajectory"}, {"multi_dof_trajectory", "trajectory_msgs/MultiDOFJointTrajectory"},
        {"path_tolerance", "control_msgs/JointTolerance[]"}, {"component_path_tolerance", "control_msgs/JointComponentTolerance[]"},
        {"goal_tolerance", "control_msgs/JointTolerance[]"}, {"component_goal_tolerance", "control_msgs/JointComponentTolerance[]"},
        {"goal_time_tolerance", "builtin_interfaces/Duration"}}},
      {"control_msgs/action/FollowJointTrajectory_Result", {{"error_code", "int32"}, {"error_string", "string"}}},
      {"control_msgs/action/FollowJointTrajectory_Feedback",
       {{"header", "std_msgs/Header"}, {"joint_names", "string[]"}, {"desired", "trajectory_msgs/JointTrajectoryPoint"},
        {"actual", "trajectory_msgs/JointTrajectoryPoint"}, {"error", "trajectory_msgs/JointTrajectoryPoint"},
        {"multi_dof_joint_names", "string[]"}, {"multi_dof_desired", "trajectory_msgs/MultiDOFJointTrajectoryPoint"},
        {"multi_dof_actual", "trajectory_msgs/MultiDOFJointTrajectoryPoint"},
        {"multi_dof_error", "trajectory_msgs/MultiDOFJointTrajectoryPoint"}}},
      {"control_msgs/action/GripperCommand_Goal", {{"command", "control_msgs/GripperCommand"}}},
      {"control_msgs/action/GripperCommand_Result",
       {{"position", "float64"}, {"effort", "float64"}, {"stalled", "bool"}, {"reached_goal", "bool"}}},
      {"control_msgs/action/GripperCommand_Feedback",
       {{"position", "float64"}, {"effort", "float64"}, {"stalled", "bool"}, {"reached_goal", "bool"}}},
      {"rmw_dds_common/NodeEntitiesInfo",
       {{"node_namespace", "string"}, {"node_name", "string"}, {"reader_gid_seq", "rmw_dds_common/Gid[]"},
        {"writer_gid_seq", "rmw_dds_common/Gid[]"}}},
      {"rmw_dds_common/ParticipantEntitiesInfo",
       {{"gid", "rmw_dds_common/Gid"}, {"node_entities_info_seq", "rmw_dds_common/NodeEntitiesInfo[]"}}},
  };
  // rosidl's action services and feedback message for each action: <A>_SendGoal_Request {goal_id, goal},
  // _Response {accepted, stamp}; <A>_GetResult_Request {goal_id}, _Response {status, result};
  // <A>_FeedbackMessage {goal_id, feedback}.
  for (const char* action : {"control_msgs/action/FollowJointTrajectory", "control_msgs/action/GripperCommand"}) {
    const std::string a = action;
    defs[a + "_SendGoal_Request"] = {{"goal_id", "unique_identifier_msgs/UUID"}, {"goal", a + "_Goal"}};
    defs[a + "_SendGoal_Response"] = {{"accepted", "bool"}, {"stamp", "builtin_interfaces/Time"}};
    defs[a + "_GetResult_Request"] = {{"goal_id", "unique_identifier_msgs/UUID"}};
    defs[a + "_GetResult_Response"] = {{"status", "int8"}, {"result", a + "_Result"}};
    defs[a + "_FeedbackMessage"] = {{"goal_id", "unique_identifier_msgs/UUID"}, {"feedback", a + "_Feedback"}};
  }
  return defs;
}


// How rmw names a type on the wire: "sensor_msgs/Image" -> sensor_msgs::msg::dds_::Image_,
// "pkg/srv/X_Request" -> pkg::srv::dds_::X_Request_, "pkg/action/X_Goal" -> pkg::action::dds_::X_Goal_.
inline std::string dds_type_name(const std::string& name) {
  const auto slash = name.find('/');
  const bool srv = name.find("/srv/") != std::string::npos;
  const bool action = name.find("/action/") != std::string::npos;
  return name.substr(0, slash) + (srv ? "::srv::dds_::" : action ? "::action::dds_::" : "::msg::dds_::") +
         name.substr(name.rfind('/') + 1) + "_";
}

}  // namespace mechsim::ros2::peers
