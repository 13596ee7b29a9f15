// A node's parameters on the wire (parameters.hpp).
#include "ros2/parameters.hpp"

#include <algorithm>
#include <chrono>
#include <functional>

#include "ros2/conversions.hpp"
#include "ros2/service.hpp"

namespace mechsim::ros2 {

using rcl_interfaces::msg::Parameter;
using rcl_interfaces::msg::ParameterType;

namespace {

template <class T>
std::optional<T> try_as(const control::Params& p) {
  try {
    return p.as<T>();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string dotted_to_path(const std::string& dotted) {
  std::string path = dotted;
  std::replace(path.begin(), path.end(), '.', '/');
  return path;
}

}  // namespace

ParameterValue parameter_value_of(const control::Params& node) {
  ParameterValue v;
  if (node.is_scalar()) {
    if (auto b = try_as<bool>(node)) {
      v.type = ParameterType::PARAMETER_BOOL;
      v.bool_value = *b;
    } else if (auto i = try_as<int>(node)) {
      v.type = ParameterType::PARAMETER_INTEGER;
      v.integer_value = *i;
    } else if (auto d = try_as<double>(node)) {
      v.type = ParameterType::PARAMETER_DOUBLE;
      v.double_value = *d;
    } else if (auto s = try_as<std::string>(node)) {
      v.type = ParameterType::PARAMETER_STRING;
      v.string_value = *s;
    }
    return v;
  }
  if (!node.is_list()) return v;
  const std::vector<control::Params> items = node.items();
  bool all_bool = !items.empty(), all_int = !items.empty(), all_number = !items.empty();
  for (const control::Params& item : items) {
    all_bool = all_bool && item.is_scalar() && try_as<bool>(item).has_value();
    all_int = all_int && item.is_scalar() && try_as<int>(item).has_value();
    all_number = all_number && item.is_scalar() && try_as<double>(item).has_value();
  }
  for (const control::Params& item : items) {
    if (all_bool) v.bool_array_value.push_back(*try_as<bool>(item));
    else if (all_int) v.integer_array_value.push_back(*try_as<int>(item));
    else if (all_number) v.double_array_value.push_back(*try_as<double>(item));
    else v.string_array_value.push_back(try_as<std::string>(item).value_or(""));
  }
  v.type = all_bool ? ParameterType::PARAMETER_BOOL_ARRAY
                    : all_int ? ParameterType::PARAMETER_INTEGER_ARRAY
                              : all_number ? ParameterType::PARAMETER_DOUBLE_ARRAY : ParameterType::PARAMETER_STRING_ARRAY;
  return v;
}

void write_parameter(control::Params params, const std::string& dotted, const ParameterValue& v) {
  const std::string key = dotted_to_path(dotted);
  switch (v.type) {
    case ParameterType::PARAMETER_BOOL: params.set(key, v.bool_value); break;
    case ParameterType::PARAMETER_INTEGER: params.set(key, static_cast<int>(v.integer_value)); break;
    case ParameterType::PARAMETER_DOUBLE: params.set(key, v.double_value); break;
    case ParameterType::PARAMETER_STRING: params.set(key, v.string_value); break;
    case ParameterType::PARAMETER_DOUBLE_ARRAY: params.set(key, v.double_array_value); break;
    case ParameterType::PARAMETER_INTEGER_ARRAY:
      params.set(key, std::vector<double>(v.integer_array_value.begin(), v.integer_array_value.end()));
      break;
    case ParameterType::PARAMETER_STRING_ARRAY: params.set(key, v.string_array_value); break;
    case ParameterType::PARAMETER_BOOL_ARRAY: {
      std::vector<std::string> text;
      for (bool b : v.bool_array_value) text.push_back(b ? "true" : "false");
      params.set(key, text);
      break;
    }
    default: break;  // byte arrays: kept by the server only
  }
}

std::string parameter_type_name(std::uint8_t type) {
  static const char* names[] = {"not set", "bool", "integer", "double", "string", "byte_array",
                                "bool_array", "integer_array", "double_array", "string_array"};
  return type < 10 ? names[type] : "unknown type " + std::to_string(type);
}

std::map<std::string, ParameterValue> flatten_parameters(const control::Params& params, const std::vector<std::string>& skip) {
  std::map<std::string, ParameterValue> out;
  std::function<void(const control::Params&, const std::string&)> walk = [&](const control::Params& p, const std::string& prefix) {
    for (const std::string& key : p.keys()) {
      if (prefix.empty() && std::find(skip.begin(), skip.end(), key) != skip.end()) continue;
      const control::Params child = p.child(key);
      const std::string name = prefix.empty() ? key : prefix + "." + key;
      if (child.is_map()) walk(child, name);
      else {
        ParameterValue v = parameter_value_of(child);
        if (v.type != ParameterType::PARAMETER_NOT_SET) out[name] = v;
      }
    }
  };
  if (params.is_map()) walk(params, "");
  return out;
}

ParameterServer::ParameterServer(Node& node, std::map<std::string, ParameterValue> initial,
                                 std::optional<control::Params> store, Options options)
    : node_(node), options_(std::move(options)), store_(std::move(store)), values_(std::move(initial)) {
  // rclcpp declares use_sim_time on every node.
  if (values_.count("use_sim_time") == 0) {
    ParameterValue t;
    t.type = ParameterType::PARAMETER_BOOL;
    t.bool_value = true;
    values_["use_sim_time"] = t;
  }
  events_ = node_.create_publisher<rcl_interfaces::msg::ParameterEvent>("/parameter_events",
                                                                        Qos{Reliability::Reliable, Durability::Volatile, 1000});
  using namespace rcl_interfaces::srv;
  auto add = [this](auto server) {
    names_.push_back(server->name());
    servers_.push_back(std::move(server));
  };
  // Quick (a map under a lock): answered on the receive thread. rclcpp's parameter services'
  // QoS (rmw_qos_profile_parameters) differs from the services default only in depth, which
  // does not affect matching.
  add(std::make_shared<ServiceServer<ListParameters>>(node_, "~/list_parameters",
      [this](const ListParameters::Request& req, ListParameters::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& [name, value] : values_) {
          bool listed = req.prefixes.empty();
          std::string rest = name;
          for (const std::string& prefix : req.prefixes) {
            if (name == prefix || name.rfind(prefix + ".", 0) == 0) {
              listed = true;
              rest = name == prefix ? "" : name.substr(prefix.size() + 1);
            }
          }
          if (!listed) continue;
          if (req.depth != ListParameters::Request::DEPTH_RECURSIVE &&
              static_cast<std::uint64_t>(std::count(rest.begin(), rest.end(), '.')) >= req.depth) continue;
          res.result.names.push_back(name);
          const auto dot = name.rfind('.');
          if (dot != std::string::npos) {
            const std::string prefix = name.substr(0, dot);
            if (std::find(res.result.prefixes.begin(), res.result.prefixes.end(), prefix) == res.result.prefixes.end())
              res.result.prefixes.push_back(prefix);
          }
        }
        return true;
      }));
  add(std::make_shared<ServiceServer<GetParameters>>(node_, "~/get_parameters",
      [this](const GetParameters::Request& req, GetParameters::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::string& n : req.names) {
          const auto it = values_.find(n);
          res.values.push_back(it == values_.end() ? ParameterValue{} : it->second);
        }
        return true;
      }));
  add(std::make_shared<ServiceServer<GetParameterTypes>>(node_, "~/get_parameter_types",
      [this](const GetParameterTypes::Request& req, GetParameterTypes::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::string& n : req.names) {
          const auto it = values_.find(n);
          res.types.push_back(it == values_.end() ? ParameterType::PARAMETER_NOT_SET : it->second.type);
        }
        return true;
      }));
  add(std::make_shared<ServiceServer<DescribeParameters>>(node_, "~/describe_parameters",
      [this](const DescribeParameters::Request& req, DescribeParameters::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::string& n : req.names) {
          rcl_interfaces::msg::ParameterDescriptor d;
          d.name = n;
          const auto it = values_.find(n);
          d.type = it == values_.end() ? ParameterType::PARAMETER_NOT_SET : it->second.type;
          d.read_only = std::find(options_.read_only.begin(), options_.read_only.end(), n) != options_.read_only.end();
          d.dynamic_typing = options_.allow_undeclared && (it == values_.end() || dynamic_.count(n) > 0);
          res.descriptors.push_back(d);
        }
        return true;
      }));
  add(std::make_shared<ServiceServer<SetParameters>>(node_, "~/set_parameters",
      [this](const SetParameters::Request& req, SetParameters::Response& res) {
        std::vector<Parameter> added, changed, deleted;
        {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const Parameter& p : req.parameters) {
            rcl_interfaces::msg::SetParametersResult r;
            r.reason = check(p.name, p.value);
            r.successful = r.reason.empty();
            if (r.successful) take(p.name, p.value, added, changed, deleted);
            else node_.participant().log(node_.fq_name() + ": set_parameters: " + r.reason);
            res.results.push_back(r);
          }
        }
        publish_event(added, changed, deleted);
        return true;
      }));
  add(std::make_shared<ServiceServer<SetParametersAtomically>>(node_, "~/set_parameters_atomically",
      [this](const SetParametersAtomically::Request& req, SetParametersAtomically::Response& res) {
        std::vector<Parameter> added, changed, deleted;
        {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const Parameter& p : req.parameters) {
            res.result.reason = check(p.name, p.value);
            if (!res.result.reason.empty()) break;
          }
          res.result.successful = res.result.reason.empty();
          if (res.result.successful)
            for (const Parameter& p : req.parameters) take(p.name, p.value, added, changed, deleted);
        }
        publish_event(added, changed, deleted);
        return true;
      }));
}

ParameterServer::~ParameterServer() {
  servers_.clear();
  events_.reset();
}

std::map<std::string, ParameterValue> ParameterServer::values() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return values_;
}

bool ParameterServer::has(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return values_.count(name) > 0;
}

std::vector<std::string> ParameterServer::service_names() const { return names_; }

std::string ParameterServer::check(const std::string& name, const ParameterValue& value) const {
  if (name.empty()) return "parameter name is empty";
  if (value.type > ParameterType::PARAMETER_STRING_ARRAY) return "parameter '" + name + "': unknown type " + std::to_string(value.type);
  const auto it = values_.find(name);
  if (std::find(options_.read_only.begin(), options_.read_only.end(), name) != options_.read_only.end())
    return "parameter '" + name + "' cannot be set because it is read-only";
  if (it == values_.end() && !options_.allow_undeclared)
    return "parameter '" + name + "' cannot be set because it was not declared";
  if (it != values_.end() && value.type != ParameterType::PARAMETER_NOT_SET && value.type != it->second.type &&
      dynamic_.count(name) == 0) {
    return "Wrong parameter type, parameter {" + name + "} is of type {" + parameter_type_name(it->second.type) +
           "}, setting it to {" + parameter_type_name(value.type) + "} is not allowed.";
  }
  if (options_.validate) return options_.validate(name, value);
  return "";
}

void ParameterServer::take(const std::string& name, const ParameterValue& value, std::vector<Parameter>& added,
                           std::vector<Parameter>& changed, std::vector<Parameter>& deleted) {
  Parameter p;
  p.name = name;
  p.value = value;
  const auto it = values_.find(name);
  if (value.type == ParameterType::PARAMETER_NOT_SET) {
    if (it != values_.end()) {
      p.value = it->second;
      values_.erase(it);
      dynamic_.erase(name);
      deleted.push_back(p);
    }
    return;
  }
  if (it == values_.end()) dynamic_.insert(name);
  (it == values_.end() ? added : changed).push_back(p);
  values_[name] = value;
  if (store_) {
    try {
      write_parameter(*store_, name, value);
    } catch (const std::exception& e) {
      node_.participant().log(node_.fq_name() + ": parameter '" + name + "' kept by the node only: " + e.what());
    }
  }
  if (options_.on_set) options_.on_set(name, value);
}

std::string ParameterServer::set(const std::string& name, const ParameterValue& value) {
  std::vector<Parameter> added, changed, deleted;
  std::string why;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    why = check(name, value);
    if (why.empty()) take(name, value, added, changed, deleted);
  }
  publish_event(added, changed, deleted);
  return why;
}

void ParameterServer::publish_event(const std::vector<Parameter>& added, const std::vector<Parameter>& changed,
                                    const std::vector<Parameter>& deleted) {
  if (added.empty() && changed.empty() && deleted.empty()) return;
  rcl_interfaces::msg::ParameterEvent e;
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  e.stamp = to_time(std::chrono::duration<double>(now).count());
  e.node = node_.fq_name();
  e.new_parameters = added;
  e.changed_parameters = changed;
  e.deleted_parameters = deleted;
  events_->publish(e);
}

}  // namespace mechsim::ros2
