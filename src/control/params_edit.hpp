#pragma once
// Editing a Params tree beyond Params::set: what a scenario's `controllers.params` overlay and
// mechsim sweep's overrides need. Configuration-time code (allocates, throws ParamsError).

#include <string_view>

#include "control/params.hpp"

namespace mechsim::control {

// Whether the node behind `p` was looked up (child, find, has, get, at, items) through any handle
// since it was read or last replaced: a reader can tell which keys it never consumed.
bool was_read(const Params& p);

// Replaces the value at `key` under `at` (created, with the maps on the way, when absent; an
// empty key replaces `at`'s own node, a list item say) by a deep copy of `value`'s subtree:
// scalar types are kept (a plain YAML scalar still converts on demand); line numbers are dropped,
// as they belong to another source.
void replace(Params at, std::string_view key, const Params& value);

// replace() that keeps where each copied node came from: its file and line stay in messages
// (a tree merged from several parameter files, control/ros2_params.hpp). Maps are replaced, not
// merged; merge() merges.
void graft(Params at, std::string_view key, const Params& value);

// Lays `value` over the node at `key` under `at` as ROS 2 merges parameter files: maps merge key
// by key (recursively), anything else replaces; sources and lines kept as graft() keeps them.
void merge(Params at, std::string_view key, const Params& value);

}  // namespace mechsim::control
