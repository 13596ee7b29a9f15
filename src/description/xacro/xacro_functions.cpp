// The `xacro` namespace of expression functions (xacro.arg, xacro.message, xacro.load_yaml, ...)
// and load_yaml: YAML documents become dicts/lists whose keys are also attributes.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>

#include "description/xacro/xacro_context.hpp"

namespace mechsim::description::xacro {
namespace fs = std::filesystem;
using pyexpr::Kwargs;
using pyexpr::PyError;

namespace {

class Namespace : public pyexpr::Object {
 public:
  Namespace(std::string name, pyexpr::SymbolMap members) : name_(std::move(name)), members_(std::move(members)) {}
  std::string type_name() const override { return "namespace"; }
  bool get_attr(std::string_view name, Value& out) override {
    auto it = members_.find(std::string(name));
    if (it == members_.end()) return false;
    out = it->second;
    return true;
  }
  std::string repr() const override { return "<namespace '" + name_ + "'>"; }

 private:
  std::string name_;
  pyexpr::SymbolMap members_;
};

std::string join_args(const std::vector<Value>& a) {
  std::string out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (i > 0) out += ' ';
    pyexpr::append_str(out, a[i]);
  }
  return out;
}

std::string abs_filename_spec(Context& ctx, const std::string& spec) {
  if (fs::path(spec).is_absolute()) return spec;
  const std::string parent = ctx.current_file();
  const std::string dir = parent.empty() ? "." : fs::path(parent).parent_path().string();
  return (fs::path(dir.empty() ? "." : dir) / spec).string();
}

// PyYAML's (YAML 1.1) resolution of plain scalars.
Value yaml_scalar(const std::string& s) {
  static const char* const trues[] = {"yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"};
  static const char* const falses[] = {"no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"};
  for (const char* t : trues) if (s == t) return Value::boolean(true);
  for (const char* f : falses) if (s == f) return Value::boolean(false);
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return Value::none();
  std::int64_t i = 0;
  if (pyexpr::parse_python_int(s, i) && s.find_first_of(" \t") == std::string::npos) return Value::integer(i);
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    char* end = nullptr;
    const long long v = std::strtoll(s.c_str() + 2, &end, 16);
    if (*end == '\0') return Value::integer(v);
  }
  const std::string lower = [&] {
    std::string l = s;
    for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return l;
  }();
  if (lower == ".inf" || lower == "+.inf") return Value::real(INFINITY);
  if (lower == "-.inf") return Value::real(-INFINITY);
  if (lower == ".nan") return Value::real(NAN);
  double d = 0;
  // YAML 1.1 floats need a '.'; exponents need a sign in PyYAML but are accepted more loosely here.
  if (s.find('.') != std::string::npos && s.find_first_of("inIN") == std::string::npos &&
      pyexpr::parse_python_float(s, d)) {
    return Value::real(d);
  }
  return Value::str(s);
}

Value yaml_to_value(Context& ctx, const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null: return Value::none();
    case YAML::NodeType::Scalar: {
      const std::string& tag = node.Tag();
      const std::string& text = node.Scalar();
      static const std::pair<const char*, double> units[] = {
          {"!radians", 1.0}, {"!degrees", M_PI / 180.0}, {"!meters", 1.0}, {"!millimeters", 0.001},
          {"!foot", 0.3048}, {"!inches", 0.0254}};
      for (const auto& [name, factor] : units) {
        if (tag != name) continue;
        auto ast = pyexpr::parse_expression(text);
        class GlobalScope : public pyexpr::Scope {
         public:
          explicit GlobalScope(Context& c) : c_(c) {}
          bool lookup(std::string_view n, Value& out) override {
            auto it = c_.globals.find(std::string(n));
            if (it == c_.globals.end()) return false;
            out = it->second;
            return true;
          }

         private:
          Context& c_;
        } scope(ctx);
        const Value v = pyexpr::evaluate(*ast, scope);
        if (!v.is_number()) throw PyError("ValueError", std::string(name) + " needs a number: " + text);
        if (std::string_view(name) == "!degrees") return Value::real(v.as_float() * (M_PI / 180.0));
        return Value::real(factor == 1.0 ? v.as_float() : v.as_float() * factor);
      }
      if (tag == "!") return Value::str(text);  // quoted scalar
      return yaml_scalar(text);
    }
    case YAML::NodeType::Sequence: {
      std::vector<Value> items;
      for (const auto& item : node) items.push_back(yaml_to_value(ctx, item));
      return Value::list(std::move(items));
    }
    case YAML::NodeType::Map: {
      Value d = Value::dict({});
      for (const auto& kv : node) d.as_dict_mut().set(yaml_to_value(ctx, kv.first), yaml_to_value(ctx, kv.second));
      return d;
    }
    case YAML::NodeType::Undefined: break;
  }
  return Value::none();
}

}  // namespace

Value load_yaml_file(Context& ctx, const std::string& spec) {
  const std::string path = abs_filename_spec(ctx, spec);
  if (!fs::exists(path)) throw PyError("FileNotFoundError", "[Errno 2] No such file or directory: '" + path + "'");
  try {
    const YAML::Node root = YAML::LoadFile(path);
    return yaml_to_value(ctx, root);
  } catch (const YAML::Exception& e) {
    throw PyError("YAMLError", "cannot load " + path + ": " + e.what());
  }
}

void add_xacro_functions(Context& ctx) {
  pyexpr::SymbolMap x;
  Context* c = &ctx;
  x["arg"] = pyexpr::make_function("arg", [c](std::vector<Value>& a, Kwargs&) {
    if (a.size() != 1) throw PyError("TypeError", "xacro.arg() takes exactly one argument");
    auto it = c->args.find(pyexpr::to_str(a[0]));
    if (it == c->args.end()) throw PyError("KeyError", pyexpr::to_repr(a[0]));
    return Value::str(it->second);
  });
  for (const char* level : {"message", "warning", "error"}) {
    x[level] = pyexpr::make_function(level, [c](std::vector<Value>& a, Kwargs&) {
      c->warn() << join_args(a) << "\n";
      return Value::str("");
    });
  }
  x["fatal"] = pyexpr::make_function("fatal", [](std::vector<Value>& a, Kwargs&) -> Value { fail(join_args(a)); });
  x["print_location"] = pyexpr::make_function("print_location", [c](std::vector<Value>&, Kwargs&) {
    c->print_location();
    return Value::str("");
  });
  x["abs_filename"] = pyexpr::make_function("abs_filename", [c](std::vector<Value>& a, Kwargs&) {
    if (a.size() != 1 || !a[0].is_str()) throw PyError("TypeError", "abs_filename() takes one file name");
    return Value::str(abs_filename_spec(*c, a[0].as_str()));
  });
  x["dotify"] = pyexpr::make_function("dotify", [](std::vector<Value>& a, Kwargs&) {
    if (a.size() != 1 || !a[0].is_dict()) throw PyError("TypeError", "dotify() takes one dict");
    return a[0];  // dict keys are attributes already
  });
  x["load_yaml"] = pyexpr::make_function("load_yaml", [c](std::vector<Value>& a, Kwargs&) {
    if (a.size() != 1 || !a[0].is_str()) throw PyError("TypeError", "load_yaml() takes one file name");
    return load_yaml_file(*c, a[0].as_str());
  });
  x["tokenize"] = pyexpr::make_function("tokenize", [](std::vector<Value>& a, Kwargs& kw) {
    if (a.empty() || !a[0].is_str()) throw PyError("TypeError", "tokenize() takes a string");
    std::string sep = a.size() > 1 ? pyexpr::to_str(a[1]) : ",; ";
    bool skip_empty = a.size() > 2 ? pyexpr::truthy(a[2]) : true;
    for (auto& [k, v] : kw) {
      if (k == "sep") sep = pyexpr::to_str(v);
      if (k == "skip_empty") skip_empty = pyexpr::truthy(v);
    }
    std::vector<Value> out;
    std::string cur;
    for (char ch : a[0].as_str()) {
      if (sep.find(ch) != std::string::npos) {
        if (!cur.empty() || !skip_empty) out.push_back(Value::str(cur));
        cur.clear();
      } else {
        cur += ch;
      }
    }
    if (!cur.empty() || !skip_empty) out.push_back(Value::str(cur));
    return Value::list(std::move(out));
  });
  // xacro 1.14 also exposes these directly (deprecated there, kept for old files).
  ctx.globals["load_yaml"] = x["load_yaml"];
  ctx.globals["abs_filename"] = x["abs_filename"];
  ctx.globals["dotify"] = x["dotify"];
  ctx.globals["xacro"] = Value::object(std::make_shared<Namespace>("xacro", std::move(x)));
}

}  // namespace mechsim::description::xacro
