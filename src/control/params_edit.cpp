#include "control/params_edit.hpp"

#include <memory>

#include "control/params_node.hpp"

namespace mechsim::control {
namespace {

void copy_node(const Params::Node& from, Params::Node& to) {
  to.map.clear();
  to.list.clear();
  to.kind = from.kind;
  to.scalar = from.scalar;
  to.text = from.text;
  to.number = from.number;
  to.integer = from.integer;
  to.boolean = from.boolean;
  to.line = 0;
  to.read.store(false, std::memory_order_relaxed);
  for (const auto& [key, child] : from.map) {
    auto copy = std::make_unique<Params::Node>();
    copy_node(*child, *copy);
    to.map.emplace_back(key, std::move(copy));
  }
  for (const auto& item : from.list) {
    auto copy = std::make_unique<Params::Node>();
    copy_node(*item, *copy);
    to.list.push_back(std::move(copy));
  }
}

}  // namespace

bool was_read(const Params& p) { return ParamsAccess::node(p)->read.load(std::memory_order_relaxed); }

void replace(Params at, std::string_view key, const Params& value) {
  // Copied aside first: `value` may be the node replaced or lie below it.
  Params::Node copy;
  copy_node(*ParamsAccess::node(value), copy);
  Params target = key.empty() ? at : at.child_or_create(key);
  copy_node(copy, *ParamsAccess::mutable_node(target));
}

}  // namespace mechsim::control
