#include "control/params.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "control/params_node.hpp"

namespace mechsim::control {

std::string join_param_path(std::string_view parent, std::string_view key) {
  std::string out(parent);
  if (out.empty() || out.back() != '/') out += '/';
  out += key;
  return out;
}

Params::Params() : Params(std::make_shared<Tree>(), nullptr, "/") {
  tree_->root = std::make_unique<Node>();
  tree_->root->kind = Kind::Map;
  node_ = tree_->root.get();
}

Params::Params(std::shared_ptr<Tree> tree, Node* node, std::string path)
    : tree_(std::move(tree)), node_(node), path_(std::move(path)) {}

Params::Kind Params::kind() const { return node_->kind; }

std::string Params::location() const {
  if (node_->line <= 0) return {};
  return node_source(*tree_, *node_) + ":" + std::to_string(node_->line);
}

std::string Params::name() const {
  if (path_ == "/") return {};
  auto slash = path_.rfind('/');
  return path_.substr(slash + 1);
}

void Params::fail(const std::string& path, const Node* node, const std::string& what) const {
  std::string message = "parameter " + path + ": " + what;
  if (node != nullptr && node->line > 0) {
    message += " (" + node_source(*tree_, *node) + ":" + std::to_string(node->line) + ")";
  } else if (node == nullptr && node_->line > 0) {
    message += " (in the map at " + node_source(*tree_, *node_) + ":" + std::to_string(node_->line) + ")";
  }
  throw ParamsError(message, path);
}

namespace {

Params::Node* map_child(Params::Node* node, std::string_view key) {
  if (node->kind != Params::Kind::Map) return nullptr;
  for (auto& [name, child] : node->map) {
    if (name == key) return child.get();
  }
  return nullptr;
}

template <class F>
void for_each_component(std::string_view key, F&& f) {
  while (!key.empty()) {
    auto slash = key.find('/');
    std::string_view part = key.substr(0, slash);
    if (!part.empty()) f(part);
    if (slash == std::string_view::npos) break;
    key.remove_prefix(slash + 1);
  }
}

}  // namespace

Params::Node* Params::resolve(std::string_view key, std::string* resolved_path) const {
  Node* node = node_;
  std::string path = path_;
  for_each_component(key, [&](std::string_view part) {
    path = join_param_path(path, part);
    node = node != nullptr ? map_child(node, part) : nullptr;
    if (node != nullptr) node->read.store(true, std::memory_order_relaxed);
  });
  if (resolved_path != nullptr) *resolved_path = std::move(path);
  return node;
}

Params::Node* Params::create_path(std::string_view key, std::string* resolved_path) {
  Node* node = node_;
  std::string path = path_;
  for_each_component(key, [&](std::string_view part) {
    path = join_param_path(path, part);
    if (node->kind != Kind::Map) {
      // Building in code replaces a scalar by a map, as rosparam set does.
      node->kind = Kind::Map;
      node->list.clear();
      node->text.clear();
    }
    Node* next = map_child(node, part);
    if (next == nullptr) {
      auto fresh = std::make_unique<Node>();
      next = fresh.get();
      node->map.emplace_back(std::string(part), std::move(fresh));
    }
    node = next;
  });
  if (resolved_path != nullptr) *resolved_path = std::move(path);
  return node;
}

bool Params::has(std::string_view key) const { return resolve(key, nullptr) != nullptr; }

std::vector<std::string> Params::keys() const {
  std::vector<std::string> out;
  if (node_->kind != Kind::Map) return out;
  for (const auto& entry : node_->map) out.push_back(entry.first);
  return out;
}

std::size_t Params::size() const {
  if (node_->kind == Kind::Map) return node_->map.size();
  if (node_->kind == Kind::List) return node_->list.size();
  return 0;
}

Params Params::child(std::string_view key) const {
  std::string path;
  Node* node = resolve(key, &path);
  if (node == nullptr) fail(path, nullptr, "not found");
  return Params(tree_, node, path);
}

std::optional<Params> Params::find(std::string_view key) const {
  std::string path;
  Node* node = resolve(key, &path);
  if (node == nullptr) return std::nullopt;
  return Params(tree_, node, path);
}

Params Params::at(std::size_t index) const {
  std::string path = path_ + "[" + std::to_string(index) + "]";
  if (node_->kind != Kind::List) fail(path_, node_, "expected a list");
  if (index >= node_->list.size()) {
    fail(path, nullptr, "index out of range (the list has " + std::to_string(node_->list.size()) + " items)");
  }
  node_->list[index]->read.store(true, std::memory_order_relaxed);
  return Params(tree_, node_->list[index].get(), path);
}

std::vector<Params> Params::items() const {
  std::vector<Params> out;
  if (node_->kind == Kind::List) {
    for (std::size_t i = 0; i < node_->list.size(); ++i) {
      node_->list[i]->read.store(true, std::memory_order_relaxed);
      out.push_back(Params(tree_, node_->list[i].get(), path_ + "[" + std::to_string(i) + "]"));
    }
  } else if (node_->kind == Kind::Map) {
    for (auto& [key, child] : node_->map) {
      child->read.store(true, std::memory_order_relaxed);
      out.push_back(Params(tree_, child.get(), join_param_path(path_, key)));
    }
  }
  return out;
}

// ---------------------------------------------------------------- scalar conversions

namespace {

const char* kind_name(const Params::Node& n) {
  switch (n.kind) {
    case Params::Kind::Null: return "an empty value";
    case Params::Kind::List: return "a list";
    case Params::Kind::Map: return "a map";
    case Params::Kind::Scalar: break;
  }
  switch (n.scalar) {
    case ScalarType::Double: return "a number";
    case ScalarType::Int: return "an integer";
    case ScalarType::Bool: return "a boolean";
    case ScalarType::Quoted: return "a string";
    case ScalarType::Plain: break;
  }
  return "a scalar";
}

std::string describe(const Params::Node& n) {
  std::string out = kind_name(n);
  if (n.kind == Params::Kind::Scalar) out += " '" + n.text + "'";
  return out;
}

std::optional<double> parse_yaml_double(const std::string& text) {
  if (text == ".inf" || text == ".Inf" || text == ".INF" || text == "+.inf") {
    return std::numeric_limits<double>::infinity();
  }
  if (text == "-.inf" || text == "-.Inf" || text == "-.INF") return -std::numeric_limits<double>::infinity();
  if (text == ".nan" || text == ".NaN" || text == ".NAN") return std::numeric_limits<double>::quiet_NaN();
  if (text.empty()) return std::nullopt;
  // strtod also reads "inf", "nan" and hex floats, which YAML does not: refuse them.
  for (char c : text) {
    if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-')) {
      return std::nullopt;
    }
  }
  errno = 0;
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE) return std::nullopt;
  return v;
}

std::optional<long long> parse_yaml_int(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::size_t start = (text[0] == '+' || text[0] == '-') ? 1 : 0;
  if (start == text.size()) return std::nullopt;
  for (std::size_t i = start; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
  }
  errno = 0;
  long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE) return std::nullopt;
  return v;
}

// YAML 1.1 booleans, as rosparam (PyYAML) reads them.
std::optional<bool> parse_yaml_bool(const std::string& t) {
  if (t == "true" || t == "True" || t == "TRUE" || t == "yes" || t == "Yes" || t == "YES" || t == "on" ||
      t == "On" || t == "ON") {
    return true;
  }
  if (t == "false" || t == "False" || t == "FALSE" || t == "no" || t == "No" || t == "NO" || t == "off" ||
      t == "Off" || t == "OFF") {
    return false;
  }
  return std::nullopt;
}

}  // namespace

namespace {

double scalar_double(const Params& p) {
  const Params::Node& n = *ParamsAccess::node(p);
  if (n.kind == Params::Kind::Scalar) {
    if (n.scalar == ScalarType::Double) return n.number;
    if (n.scalar == ScalarType::Int) return static_cast<double>(n.integer);
    if (n.scalar == ScalarType::Plain) {
      if (auto v = parse_yaml_double(n.text)) return *v;
    }
  }
  ParamsAccess::fail(p, "expected a number, got " + describe(n));
}

int scalar_int(const Params& p) {
  const Params::Node& n = *ParamsAccess::node(p);
  std::optional<long long> v;
  if (n.kind == Params::Kind::Scalar) {
    if (n.scalar == ScalarType::Int) v = n.integer;
    if (n.scalar == ScalarType::Plain) v = parse_yaml_int(n.text);
  }
  if (!v) ParamsAccess::fail(p, "expected an integer, got " + describe(n));
  if (*v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max()) {
    ParamsAccess::fail(p, "integer " + n.text + " out of range");
  }
  return static_cast<int>(*v);
}

bool scalar_bool(const Params& p) {
  const Params::Node& n = *ParamsAccess::node(p);
  if (n.kind == Params::Kind::Scalar) {
    if (n.scalar == ScalarType::Bool) return n.boolean;
    if (n.scalar == ScalarType::Plain) {
      if (auto v = parse_yaml_bool(n.text)) return *v;
    }
  }
  ParamsAccess::fail(p, "expected a boolean (true/false), got " + describe(n));
}

std::string scalar_string(const Params& p) {
  const Params::Node& n = *ParamsAccess::node(p);
  if (n.kind == Params::Kind::Scalar && (n.scalar == ScalarType::Plain || n.scalar == ScalarType::Quoted)) {
    return n.text;
  }
  ParamsAccess::fail(p, "expected a string, got " + describe(n));
}

template <class T, class F>
std::vector<T> list_of(const Params& p, F&& convert, const char* what) {
  if (!p.is_list()) ParamsAccess::fail(p, std::string("expected a list of ") + what + ", got " + describe(*ParamsAccess::node(p)));
  std::vector<T> out;
  for (const Params& item : p.items()) out.push_back(convert(item));
  return out;
}

template <class T, class F>
std::map<std::string, T> map_of(const Params& p, F&& convert, const char* what) {
  if (!p.is_map()) ParamsAccess::fail(p, std::string("expected a map of ") + what + ", got " + describe(*ParamsAccess::node(p)));
  std::map<std::string, T> out;
  for (const std::string& key : p.keys()) out.emplace(key, convert(p.child(key)));
  return out;
}

}  // namespace

template <> double Params::as<double>() const { return scalar_double(*this); }
template <> int Params::as<int>() const { return scalar_int(*this); }
template <> bool Params::as<bool>() const { return scalar_bool(*this); }
template <> std::string Params::as<std::string>() const { return scalar_string(*this); }
template <> std::vector<double> Params::as<std::vector<double>>() const {
  return list_of<double>(*this, scalar_double, "numbers");
}
template <> std::vector<int> Params::as<std::vector<int>>() const {
  return list_of<int>(*this, scalar_int, "integers");
}
template <> std::vector<std::string> Params::as<std::vector<std::string>>() const {
  return list_of<std::string>(*this, scalar_string, "strings");
}
template <> std::map<std::string, double> Params::as<std::map<std::string, double>>() const {
  return map_of<double>(*this, scalar_double, "numbers");
}
template <> std::map<std::string, std::string> Params::as<std::map<std::string, std::string>>() const {
  return map_of<std::string>(*this, scalar_string, "strings");
}

template <class T>
T Params::get(std::string_view key) const {
  return child(key).as<T>();
}

template <class T>
T Params::get(std::string_view key, const T& fallback) const {
  auto found = find(key);
  if (!found || found->kind() == Kind::Null) return fallback;
  return found->as<T>();
}

#define MECHSIM_PARAMS_INSTANTIATE(T)                          \
  template T Params::get<T>(std::string_view) const;            \
  template T Params::get<T>(std::string_view, const T&) const;
MECHSIM_PARAMS_INSTANTIATE(double)
MECHSIM_PARAMS_INSTANTIATE(int)
MECHSIM_PARAMS_INSTANTIATE(bool)
MECHSIM_PARAMS_INSTANTIATE(std::string)
MECHSIM_PARAMS_INSTANTIATE(std::vector<double>)
MECHSIM_PARAMS_INSTANTIATE(std::vector<int>)
MECHSIM_PARAMS_INSTANTIATE(std::vector<std::string>)
using StringDoubleMap = std::map<std::string, double>;
using StringStringMap = std::map<std::string, std::string>;
MECHSIM_PARAMS_INSTANTIATE(StringDoubleMap)
MECHSIM_PARAMS_INSTANTIATE(StringStringMap)
#undef MECHSIM_PARAMS_INSTANTIATE

// ---------------------------------------------------------------- building

namespace {

void reset_node(Params::Node& n) {
  n.map.clear();
  n.list.clear();
  n.text.clear();
  n.line = 0;
  n.read.store(false, std::memory_order_relaxed);
}

void set_scalar(Params::Node& n, ScalarType type, std::string text) {
  reset_node(n);
  n.kind = Params::Kind::Scalar;
  n.scalar = type;
  n.text = std::move(text);
}

}  // namespace

Params& Params::set(std::string_view key, double value) {
  Node* n = create_path(key, nullptr);
  set_scalar(*n, ScalarType::Double, std::to_string(value));
  n->number = value;
  return *this;
}

Params& Params::set(std::string_view key, int value) {
  Node* n = create_path(key, nullptr);
  set_scalar(*n, ScalarType::Int, std::to_string(value));
  n->integer = value;
  return *this;
}

Params& Params::set(std::string_view key, bool value) {
  Node* n = create_path(key, nullptr);
  set_scalar(*n, ScalarType::Bool, value ? "true" : "false");
  n->boolean = value;
  return *this;
}

Params& Params::set(std::string_view key, const char* value) { return set(key, std::string(value)); }

Params& Params::set(std::string_view key, const std::string& value) {
  set_scalar(*create_path(key, nullptr), ScalarType::Quoted, value);
  return *this;
}

Params& Params::set(std::string_view key, const std::vector<double>& value) {
  Node* n = create_path(key, nullptr);
  reset_node(*n);
  n->kind = Kind::List;
  for (double v : value) {
    auto item = std::make_unique<Node>();
    set_scalar(*item, ScalarType::Double, std::to_string(v));
    item->number = v;
    n->list.push_back(std::move(item));
  }
  return *this;
}

Params& Params::set(std::string_view key, const std::vector<std::string>& value) {
  Node* n = create_path(key, nullptr);
  reset_node(*n);
  n->kind = Kind::List;
  for (const std::string& v : value) {
    auto item = std::make_unique<Node>();
    set_scalar(*item, ScalarType::Quoted, v);
    n->list.push_back(std::move(item));
  }
  return *this;
}

Params Params::child_or_create(std::string_view key) {
  std::string path;
  Node* n = create_path(key, &path);
  if (n->kind == Kind::Null) n->kind = Kind::Map;
  return Params(tree_, n, path);
}

}  // namespace mechsim::control
