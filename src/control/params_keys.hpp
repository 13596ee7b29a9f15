#pragma once
// The first key of a parameter map outside an allowed set, and the message that names the set:
// every reader that rejects misspelt keys (scenarios, sweeps) words it the same way.
#include <initializer_list>
#include <optional>
#include <string>

#include "control/params.hpp"

namespace mechsim::control {

struct UnknownKey {
  std::string key;
  std::string message;  // "unknown key 'k' (expected one of: a, b, c)"
};

// `map` must be a map (the caller says otherwise in its own words).
inline std::optional<UnknownKey> unknown_key(const Params& map, std::initializer_list<const char*> allowed) {
  for (const std::string& k : map.keys()) {
    bool ok = false;
    std::string list;
    for (const char* a : allowed) {
      ok = ok || k == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!ok) return UnknownKey{k, "unknown key '" + k + "' (expected one of: " + list + ")"};
  }
  return std::nullopt;
}

}  // namespace mechsim::control
