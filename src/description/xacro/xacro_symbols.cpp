// Property scopes with xacro's lazy evaluation, and macro tables.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <algorithm>

#include "description/xacro/xacro_context.hpp"

namespace mechsim::description::xacro {

bool Symbols::find(std::string_view name, Value& out) {
  for (Symbols* s = this; s != nullptr; s = s->parent_) {
    auto it = s->table_.find(std::string(name));
    if (it == s->table_.end() || it->second.block != nullptr) continue;
    if (it->second.unevaluated) {
      const std::string key(name);
      if (std::find(s->resolving_.begin(), s->resolving_.end(), key) != s->resolving_.end()) {
        std::string chain;
        for (const auto& k : s->resolving_) chain += k + " -> ";
        fail("circular variable definition: " + chain + key +
             "\nConsider disabling lazy evaluation via lazy_eval=\"false\"");
      }
      const std::string raw = it->second.value.as_str();
      s->resolving_.push_back(key);
      Value v;
      try {
        v = eval_literal(ctx_.eval_text(raw, *s));
      } catch (...) {
        s->resolving_.pop_back();
        throw;
      }
      s->resolving_.pop_back();
      Entry& e = s->table_[key];  // re-find: evaluation may have added entries
      e.value = std::move(v);
      e.unevaluated = false;
      out = e.value;
      return true;
    }
    out = it->second.value;
    return true;
  }
  return false;
}

bool Symbols::contains_key(std::string_view name) const {
  for (const Symbols* s = this; s != nullptr; s = s->parent_) {
    if (s->table_.count(std::string(name)) != 0) return true;
  }
  return ctx_.globals.count(std::string(name)) != 0;
}

Node* Symbols::find_block(std::string_view name) const {
  for (const Symbols* s = this; s != nullptr; s = s->parent_) {
    auto it = s->table_.find(std::string(name));
    if (it != s->table_.end()) return it->second.block;
  }
  return nullptr;
}

void Symbols::set(const std::string& name, Value value, bool lazy) {
  if (ctx_.globals.count(name) != 0) {
    ctx_.warn() << "redefining global symbol: " << name << "\n";
    ctx_.print_location();
  }
  value = eval_literal(std::move(value));
  Entry& e = table_[name];
  e.unevaluated = lazy && value.is_str();
  e.value = std::move(value);
  e.block = nullptr;
}

void Symbols::set_block(const std::string& name, Node* block) {
  Entry& e = table_[name];
  e.value = Value();
  e.unevaluated = false;
  e.block = block;
}

void Symbols::remove(const std::string& name) {
  for (Symbols* s = this; s != nullptr; s = s->parent_) s->table_.erase(name);
  if (ctx_.globals.count(name) != 0) ctx_.warn() << "Cannot remove global symbol: " << name << "\n";
}

Symbols* Symbols::top() {
  Symbols* s = this;
  while (s->parent_ != nullptr) s = s->parent_;
  return s;
}

bool Symbols::get_attr(std::string_view name, Value& out) {
  if (find(name, out)) return true;
  throw pyexpr::PyError("NameError", "name '" + std::string(name) + "' is not defined");
}

bool Symbols::get_item(const Value& key, Value& out) {
  return key.is_str() && find(key.as_str(), out);
}

bool Symbols::contains(const Value& key, bool& out) {
  out = key.is_str() && contains_key(key.as_str());
  return true;
}

std::shared_ptr<Macro> MacroTable::find(const std::string& name) const {
  for (const MacroTable* t = this; t != nullptr; t = t->parent_) {
    auto it = t->macros_.find(name);
    if (it != t->macros_.end()) return it->second;
  }
  return nullptr;
}

std::shared_ptr<MacroTable> MacroTable::find_namespace(const std::string& name) const {
  for (const MacroTable* t = this; t != nullptr; t = t->parent_) {
    auto it = t->namespaces_.find(name);
    if (it != t->namespaces_.end()) return it->second;
  }
  return nullptr;
}

std::shared_ptr<Symbols> Context::new_scope(Symbols* parent, bool is_namespace) {
  scopes.push_back(std::make_shared<Symbols>(*this, parent, is_namespace));
  return scopes.back();
}

std::shared_ptr<MacroTable> Context::new_macro_table(MacroTable* parent) {
  macro_tables.push_back(std::make_shared<MacroTable>(parent));
  return macro_tables.back();
}

bool ExprScope::lookup(std::string_view name, Value& out) {
  if (symbols_.find(name, out)) return true;
  auto it = ctx_.globals.find(std::string(name));
  if (it == ctx_.globals.end()) return false;
  out = it->second;
  return true;
}

}  // namespace mechsim::description::xacro
