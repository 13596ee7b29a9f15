#pragma once
// Internal: the node storage behind control::Params (params.cpp, params_yaml.cpp).

#include <atomic>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "control/params.hpp"

namespace mechsim::control {

// How a scalar was written: Plain YAML scalars convert on demand (like rosparam's YAML 1.1
// reading); quoted YAML scalars are strings; values set in code keep their C++ type.
enum class ScalarType : std::uint8_t { Plain, Quoted, Double, Int, Bool };

struct Params::Node {
  Kind kind = Kind::Null;
  ScalarType scalar = ScalarType::Plain;
  std::string text;  // the scalar as written (or formatted, when set in code)
  double number = 0.0;
  long long integer = 0;
  bool boolean = false;
  std::vector<std::pair<std::string, std::unique_ptr<Node>>> map;  // document order
  std::vector<std::unique_ptr<Node>> list;
  int line = 0;  // 1-based line in the source, 0 when built in code
  // The file `line` is in when it is not the tree's own (a node grafted from another tree,
  // control/params_edit.hpp's graft); null: the tree's source.
  std::shared_ptr<const std::string> source;
  // Looked up through a handle (Params::was_read). Atomic: handles to one tree may be read from
  // several threads, and a lookup marks the node.
  mutable std::atomic<bool> read{false};
};

struct Params::Tree {
  std::string source;  // file name or "<string>"
  std::unique_ptr<Node> root;
};

// The file a node's line is in: its own source or the tree's.
inline const std::string& node_source(const Params::Tree& tree, const Params::Node& node) {
  return node.source ? *node.source : tree.source;
}

struct ParamsAccess {
  static const Params::Tree& tree(const Params& p) { return *p.tree_; }
  static const Params::Node* node(const Params& p) { return p.node_; }
  static Params::Node* mutable_node(const Params& p) { return p.node_; }
  [[noreturn]] static void fail(const Params& p, const std::string& what) { p.fail(p.path_, p.node_, what); }
  static Params make(std::shared_ptr<Params::Tree> tree) {
    Params::Node* root = tree->root.get();
    return Params(std::move(tree), root, "/");
  }
};

}  // namespace mechsim::control
