#pragma once
// Params: the tree of controller configuration (maps, lists, scalars), as ros_control users
// write it in YAML and as the ROS parameter server holds it. Loaded from a YAML file or string
// (yaml-cpp), or built in code (the ROS layer fills it from the parameter server).
//
// A Params value is a handle to one node of a shared tree, like YAML::Node or ros::NodeHandle:
// copies refer to the same tree, and building through any handle is seen by all of them.
// Every node knows its full path ("/cc8/steering_FL_position_controller/pid/p"); every error
// names it, and for trees read from YAML also the file and line.
//
// Keys may be nested with '/': get<double>("pid/p") is child("pid").get<double>("p").
// Configuration-time code: getters allocate and throw ParamsError. Never use from update().

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::control {

// A missing, mistyped or malformed parameter. what() names the full parameter path (and the
// file:line it came from where known); path() is the path alone.
class ParamsError : public std::runtime_error {
 public:
  ParamsError(const std::string& message, std::string path)
      : std::runtime_error(message), path_(std::move(path)) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

class Params {
 public:
  enum class Kind : std::uint8_t { Null, Scalar, List, Map };

  // An empty map at path "/" (build it in code with set()/child_or_create()).
  Params();

  // Throws ParamsError naming the file and line (1-based) for malformed YAML or an unreadable
  // file. The root's path is "/"; a top-level key `cc8` has path "/cc8".
  static Params from_yaml_file(const std::string& file_path);
  // `source_name` stands in for a file name in messages.
  static Params from_yaml_string(std::string_view yaml, const std::string& source_name = "<string>");

  // ---- inspection
  Kind kind() const;
  bool is_map() const { return kind() == Kind::Map; }
  bool is_list() const { return kind() == Kind::List; }
  bool is_scalar() const { return kind() == Kind::Scalar; }
  const std::string& path() const { return path_; }
  // "file:line" of this node where read from YAML, "" when built in code.
  std::string location() const;
  // The last path component ("p" for "/cc8/x/pid/p"); "" for the root.
  std::string name() const;

  bool has(std::string_view key) const;  // nested keys allowed
  std::vector<std::string> keys() const;  // map keys in document order; empty unless a map
  std::size_t size() const;               // map entries or list items; 0 for scalars
  Params child(std::string_view key) const;  // throws naming the missing path
  std::optional<Params> find(std::string_view key) const;
  Params at(std::size_t index) const;     // list item; throws naming the path
  std::vector<Params> items() const;      // list items, or map values in order

  // ---- typed getters. Supported T: double, int, bool, std::string, std::vector<double>,
  // std::vector<int>, std::vector<std::string>, std::map<std::string, double>,
  // std::map<std::string, std::string>. An int converts to double; nothing else converts.
  template <class T>
  T get(std::string_view key) const;  // throws if absent or of another type
  template <class T>
  T get(std::string_view key, const T& fallback) const;  // fallback only when absent
  template <class T>
  T as() const;  // this node's own value

  // ---- building in code (the ROS layer, tests). Intermediate maps are created as needed.
  // Replaces an existing value at `key`. Returns *this for chaining.
  Params& set(std::string_view key, double value);
  Params& set(std::string_view key, int value);
  Params& set(std::string_view key, bool value);
  Params& set(std::string_view key, const char* value);
  Params& set(std::string_view key, const std::string& value);
  Params& set(std::string_view key, const std::vector<double>& value);
  Params& set(std::string_view key, const std::vector<std::string>& value);
  Params child_or_create(std::string_view key);  // a map child, created when absent

  struct Node;  // params_node.hpp
  struct Tree;

 private:
  Params(std::shared_ptr<Tree> tree, Node* node, std::string path);
  Node* resolve(std::string_view key, std::string* resolved_path) const;
  Node* create_path(std::string_view key, std::string* resolved_path);
  [[noreturn]] void fail(const std::string& path, const Node* node, const std::string& what) const;
  friend struct ParamsAccess;

  std::shared_ptr<Tree> tree_;
  Node* node_ = nullptr;
  std::string path_;
};

// Joins a parameter path and a key: ("/", "cc8") -> "/cc8", ("/cc8", "x") -> "/cc8/x".
std::string join_param_path(std::string_view parent, std::string_view key);

}  // namespace mechsim::control
