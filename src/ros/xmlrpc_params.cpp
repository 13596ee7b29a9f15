#include "ros/xmlrpc_params.hpp"

#include <vector>

namespace mechsim::ros {

namespace {

void warn(std::string* warning, const std::string& text) {
  if (warning) *warning += (warning->empty() ? "" : "; ") + text;
}

}  // namespace

bool set_param_from_xmlrpc(control::Params& target, const std::string& key, const XmlRpc::XmlRpcValue& value,
                           std::string* warning) {
  const XmlRpc::XmlRpcValue& v = value;  // read through the const accessors: no copy of the subtree
  const std::string path = control::join_param_path(target.path(), key);
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean: target.set(key, static_cast<bool>(v)); return true;
    case XmlRpc::XmlRpcValue::TypeInt: target.set(key, static_cast<int>(v)); return true;
    case XmlRpc::XmlRpcValue::TypeDouble: target.set(key, static_cast<double>(v)); return true;
    case XmlRpc::XmlRpcValue::TypeString: target.set(key, static_cast<std::string>(v)); return true;
    case XmlRpc::XmlRpcValue::TypeStruct: {
      control::Params child = target.child_or_create(key);
      return fill_params_from_xmlrpc(child, v, warning);
    }
    case XmlRpc::XmlRpcValue::TypeArray: {
      bool all_numbers = true, all_strings = true;
      for (int i = 0; i < v.size(); ++i) {
        const auto t = v[i].getType();
        all_numbers = all_numbers && (t == XmlRpc::XmlRpcValue::TypeInt || t == XmlRpc::XmlRpcValue::TypeDouble);
        all_strings = all_strings && t == XmlRpc::XmlRpcValue::TypeString;
      }
      if (all_numbers) {
        std::vector<double> list;
        for (int i = 0; i < v.size(); ++i) {
          list.push_back(v[i].getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<double>(static_cast<int>(v[i]))
                                                                          : static_cast<double>(v[i]));
        }
        target.set(key, list);
        return true;
      }
      if (all_strings) {
        std::vector<std::string> list;
        for (int i = 0; i < v.size(); ++i) list.push_back(static_cast<std::string>(v[i]));
        target.set(key, list);
        return true;
      }
      warn(warning, path + ": a list of mixed or structured items is not supported (skipped)");
      return false;
    }
    default:
      warn(warning, path + ": unsupported parameter type (skipped)");
      return false;
  }
}

bool fill_params_from_xmlrpc(control::Params& target, const XmlRpc::XmlRpcValue& value, std::string* warning) {
  const XmlRpc::XmlRpcValue& v = value;
  if (v.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    warn(warning, target.path() + ": expected a namespace (struct)");
    return false;
  }
  bool ok = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    ok = set_param_from_xmlrpc(target, it->first, it->second, warning) && ok;
  }
  return ok;
}

}  // namespace mechsim::ros
