#include "control/params_edit.hpp"

#include <memory>

#include "control/params_node.hpp"

namespace mechsim::control {
namespace {

// `source`: with it, each copied node keeps its line and the file it is in (its own source, or
// `source` for the from-tree's); without it, lines are dropped.
void copy_node(const Params::Node& from, Params::Node& to, const std::shared_ptr<const std::string>& source = nullptr) {
  to.map.clear();
  to.list.clear();
  to.kind = from.kind;
  to.scalar = from.scalar;
  to.text = from.text;
  to.number = from.number;
  to.integer = from.integer;
  to.boolean = from.boolean;
  to.line = source ? from.line : 0;
  to.source = source ? (from.source ? from.source : source) : nullptr;
  to.read.store(false, std::memory_order_relaxed);
  for (const auto& [key, child] : from.map) {
    auto copy = std::make_unique<Params::Node>();
    copy_node(*child, *copy, source);
    to.map.emplace_back(key, std::move(copy));
  }
  for (const auto& item : from.list) {
    auto copy = std::make_unique<Params::Node>();
    copy_node(*item, *copy, source);
    to.list.push_back(std::move(copy));
  }
}

std::shared_ptr<const std::string> source_of(const Params& p) {
  return std::make_shared<const std::string>(ParamsAccess::tree(p).source);
}

void merge_node(const Params::Node& from, Params::Node& to, const std::shared_ptr<const std::string>& source) {
  if (from.kind != Params::Kind::Map || to.kind != Params::Kind::Map) {
    copy_node(from, to, source);
    return;
  }
  if (to.line == 0) {
    to.line = from.line;
    to.source = from.source ? from.source : source;
  }
  for (const auto& [key, child] : from.map) {
    Params::Node* target = nullptr;
    for (auto& [k, existing] : to.map)
      if (k == key) target = existing.get();
    if (target == nullptr) {
      auto fresh = std::make_unique<Params::Node>();
      target = fresh.get();
      to.map.emplace_back(key, std::move(fresh));
      copy_node(*child, *target, source);
    } else {
      merge_node(*child, *target, source);
    }
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

void graft(Params at, std::string_view key, const Params& value) {
  const auto source = source_of(value);
  Params::Node copy;
  copy_node(*ParamsAccess::node(value), copy, source);
  Params target = key.empty() ? at : at.child_or_create(key);
  // The copy's nodes already carry their sources.
  copy_node(copy, *ParamsAccess::mutable_node(target), source);
}

void merge(Params at, std::string_view key, const Params& value) {
  const auto source = source_of(value);
  Params::Node copy;
  copy_node(*ParamsAccess::node(value), copy, source);
  Params target = key.empty() ? at : at.child_or_create(key);
  Params::Node* to = ParamsAccess::mutable_node(target);
  // A fresh node (created just now) takes the value whole.
  if (to->kind == Params::Kind::Null) {
    copy_node(copy, *to, source);
    return;
  }
  merge_node(copy, *to, source);
}

}  // namespace mechsim::control
