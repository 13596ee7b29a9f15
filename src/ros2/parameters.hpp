#pragma once
// A ROS 2 node's parameters as rclcpp's ParameterService serves them (`ros2 param list/get/set/
// describe/dump`, the spawner): ~/list_parameters, ~/get_parameters, ~/set_parameters,
// ~/set_parameters_atomically, ~/describe_parameters, ~/get_parameter_types (rcl_interfaces,
// QoS rmw_qos_profile_parameters), and rcl_interfaces/msg/ParameterEvent on /parameter_events
// for every change. The values live in a control::Params map (a controller's parameters as
// mechsim's controllers read them at configure time; dotted ROS 2 names are nested maps), so a
// parameter set before `configure_controller` is what the controller gets.
//
// Rules as rclcpp applies them: a parameter keeps its type (a set to another type is refused,
// naming both); a read-only one is refused; an undeclared one is refused unless the node allows
// undeclared parameters (ros2_control's controller manager does: the spawner sets
// `<controller>.type` and `<controller>.params_file` on it); setting NOT_SET undeclares one.

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <mechsim_ros2_msgs/rcl_interfaces.hpp>

#include "control/params.hpp"
#include "ros2/node.hpp"

namespace mechsim::ros2 {

using ParameterValue = rcl_interfaces::msg::ParameterValue;

// ParameterValue of a YAML value (bool, integer, double, string, their arrays; PARAMETER_NOT_SET
// for a map or an empty list's unknown type: an empty list is a string array).
ParameterValue parameter_value_of(const control::Params& node);
// Writes `value` at `key` (dotted: nested maps) of `params`.
void write_parameter(control::Params params, const std::string& dotted, const ParameterValue& value);
// "bool", "integer", "double", "string", "byte_array", ..., "not set".
std::string parameter_type_name(std::uint8_t type);
// Every scalar and list under `params` by dotted name (maps flattened), skipping `skip` keys at the top.
std::map<std::string, ParameterValue> flatten_parameters(const control::Params& params,
                                                         const std::vector<std::string>& skip = {});

class ParameterServer {
 public:
  struct Options {
    bool allow_undeclared = false;
    std::vector<std::string> read_only;  // names
    // Called (under the server's lock) before a set is taken: "" accepts, else the reason.
    std::function<std::string(const std::string& name, const ParameterValue& value)> validate;
    // Called after a set was taken (under the server's lock).
    std::function<void(const std::string& name, const ParameterValue& value)> on_set;
  };
  // `initial`: the node's parameters; `store` (may be a null Params handle: values stay here) is
  // where set values are written too. Throws std::runtime_error when the endpoints cannot be made.
  ParameterServer(Node& node, std::map<std::string, ParameterValue> initial, std::optional<control::Params> store,
                  Options options);
  ~ParameterServer();
  ParameterServer(const ParameterServer&) = delete;
  ParameterServer& operator=(const ParameterServer&) = delete;

  std::map<std::string, ParameterValue> values() const;
  bool has(const std::string& name) const;
  // Sets one as a set_parameters request would; "" on success, else why.
  std::string set(const std::string& name, const ParameterValue& value);
  std::vector<std::string> service_names() const;

 private:
  void publish_event(const std::vector<rcl_interfaces::msg::Parameter>& added,
                     const std::vector<rcl_interfaces::msg::Parameter>& changed,
                     const std::vector<rcl_interfaces::msg::Parameter>& deleted);
  std::string check(const std::string& name, const ParameterValue& value) const;  // under mutex_
  void take(const std::string& name, const ParameterValue& value,              // under mutex_
            std::vector<rcl_interfaces::msg::Parameter>& added, std::vector<rcl_interfaces::msg::Parameter>& changed,
            std::vector<rcl_interfaces::msg::Parameter>& deleted);

  Node& node_;
  Options options_;
  std::optional<control::Params> store_;
  mutable std::mutex mutex_;
  std::map<std::string, ParameterValue> values_;
  // Names first set while undeclared (allow_undeclared): any type later, as rclcpp's implicitly
  // declared parameters; declared ones keep their type.
  std::set<std::string> dynamic_;
  std::unique_ptr<Publisher<rcl_interfaces::msg::ParameterEvent>> events_;
  std::vector<std::shared_ptr<void>> servers_;
  std::vector<std::string> names_;
};

}  // namespace mechsim::ros2
