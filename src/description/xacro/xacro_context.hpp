#pragma once
// Internal state of one xacro expansion: property scopes (with xacro's lazy evaluation), macro
// tables, the file/macro stacks used in messages, caches of parsed expressions.

#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "description/pyexpr/pyexpr_ast.hpp"
#include "description/pyexpr/pyexpr_eval.hpp"
#include "description/xacro/xacro.hpp"
#include "description/xacro/xacro_dom.hpp"

namespace mechsim::description::xacro {

using pyexpr::Value;
class Context;

// An expansion error on its way out: `message` as xacro words it; `located` once the innermost
// node's file:line has been attached; `trace` collects macro/include frames while unwinding.
struct Failure {
  explicit Failure(std::string msg, XacroError::Kind k = XacroError::Kind::Xacro, std::string at = {})
      : message(std::move(msg)), kind(k), located(!at.empty()), where(std::move(at)) {}
  std::string message;
  XacroError::Kind kind = XacroError::Kind::Xacro;
  bool located = false;
  std::string where;               // "FILE:LINE" of the innermost node
  std::vector<std::string> trace;  // "in macro 'x' called from FILE:LINE", ...
};

// A property scope (xacro's Table). Namespaces from <xacro:include ns=".."> are scopes too and
// are reachable from expressions as objects (`ns.prop`).
class Symbols : public pyexpr::Object {
 public:
  // `parent` must outlive this scope: the Context owns every scope (Context::new_scope).
  Symbols(Context& ctx, Symbols* parent, bool is_namespace)
      : ctx_(ctx), parent_(parent), is_namespace_(is_namespace) {}

  struct Entry {
    Value value;        // evaluated value, or the raw text while `unevaluated`
    bool unevaluated = false;
    Node* block = nullptr;  // for "*name"/"**name" block parameters and property blocks
  };

  // Looks `name` up through the parents (not the globals), evaluating lazily. False if unknown.
  bool find(std::string_view name, Value& out);
  bool contains_key(std::string_view name) const;  // through parents
  Node* find_block(std::string_view name) const;   // through parents
  // xacro's _setitem: literal conversion, lazy evaluation of strings when `lazy`.
  void set(const std::string& name, Value value, bool lazy);
  void set_block(const std::string& name, Node* block);
  void remove(const std::string& name);  // from this scope up to the top
  Symbols* parent() const { return parent_; }
  Symbols* top();  // the global scope
  bool is_namespace() const { return is_namespace_; }

  std::string type_name() const override { return "PropertyNameSpace"; }
  bool get_attr(std::string_view name, Value& out) override;
  bool get_item(const Value& key, Value& out) override;
  bool contains(const Value& key, bool& out) override;

 private:
  Context& ctx_;
  Symbols* parent_;
  bool is_namespace_;
  std::unordered_map<std::string, Entry> table_;
  std::vector<std::string> resolving_;  // keys being evaluated (circular definitions)
};

struct Macro {
  std::string name;
  std::vector<std::string> params;  // in order; "*block" and "**block" included
  struct Default {
    bool forward = false;      // ^ or ^|
    bool has_default = false;
    std::string value;
  };
  std::unordered_map<std::string, Default> defaults;
  Node* body = nullptr;
  int file = 0;
  int line = 0;
};

class MacroTable {
 public:
  explicit MacroTable(MacroTable* parent) : parent_(parent) {}
  std::shared_ptr<Macro> find(const std::string& name) const;
  std::shared_ptr<MacroTable> find_namespace(const std::string& name) const;
  void set(const std::string& name, std::shared_ptr<Macro> m) { macros_[name] = std::move(m); }
  void set_namespace(const std::string& name, std::shared_ptr<MacroTable> t) { namespaces_[name] = std::move(t); }

 private:
  MacroTable* parent_;
  std::unordered_map<std::string, std::shared_ptr<Macro>> macros_;
  std::unordered_map<std::string, std::shared_ptr<MacroTable>> namespaces_;
};

// The scope chain seen by an expression: a property scope, then the global symbols.
class ExprScope : public pyexpr::Scope {
 public:
  ExprScope(Context& ctx, Symbols& symbols) : ctx_(ctx), symbols_(symbols) {}
  bool lookup(std::string_view name, Value& out) override;

 private:
  Context& ctx_;
  Symbols& symbols_;
};

class Context {
 public:
  Context(const XacroOptions& options);

  const XacroOptions& options;
  NodeArena arena;
  pyexpr::SymbolMap globals;
  std::map<std::string, std::string> args;  // substitution args ($(arg), xacro:arg)
  std::vector<std::string> files;           // file table: index -> path as given
  std::vector<int> file_stack;              // files being processed (innermost last)
  struct MacroFrame {
    const Macro* macro;
    int call_file;
    int call_line;
  };
  std::vector<MacroFrame> macro_stack;
  int eval_depth = 0;  // nested expression evaluations (lazy property chains)
  int nesting = 0;     // elements, macro bodies and included files being processed, in all
  std::unordered_map<std::string, std::shared_ptr<const pyexpr::Expr>> expr_cache;
  std::map<std::string, std::string> found_packages;  // $(find pkg) answers of this expansion

  // Scopes and macro tables live as long as the expansion (they point at their parents).
  std::shared_ptr<Symbols> new_scope(Symbols* parent, bool is_namespace);
  std::shared_ptr<MacroTable> new_macro_table(MacroTable* parent);
  std::vector<std::shared_ptr<Symbols>> scopes;
  std::vector<std::shared_ptr<MacroTable>> macro_tables;

  std::ostream& warn();
  int add_file(const std::string& path);
  std::string current_file() const;  // path of the innermost file being processed
  std::string location(int file, int line) const;

  // xacro's eval_text: ${...}, $(...), $$ escapes; a single token keeps its type.
  Value eval_text(std::string_view text, Symbols& symbols);
  std::string eval_text_str(std::string_view text, Symbols& symbols);
  Value eval_expression(std::string_view expr, Symbols& symbols);
  std::string eval_extension(std::string_view inner, Symbols& symbols);
  void print_location();
};

// xacro's conversions of property text: 'quoted' strings, int, float, true/false.
Value eval_literal(Value v);
// xacro's get_boolean_value for xacro:if / unless; throws Failure.
bool boolean_value(const Value& v, std::string_view condition);

[[noreturn]] void fail(std::string message);

// Expression-level functions: xacro.*, load_yaml, and the globals they join.
void add_xacro_functions(Context& ctx);
Value load_yaml_file(Context& ctx, const std::string& path);

// Helpers of the document processing (xacro_helpers.cpp).
bool is_space_text(const std::string& s);  // non-empty and all whitespace (Python's isspace)
bool has_non_space(const std::string& s);
std::string trim(std::string_view s);
bool is_identifier(const std::string& s);  // a Python identifier that is not a keyword

// check_attrs: the values of the required attributes (error when missing) and of the optional
// ones (nullptr when absent); warns about any other attribute.
struct Attrs {
  std::vector<const std::string*> values;
};
Attrs check_attrs(Context& ctx, const Node* n, std::initializer_list<const char*> required,
                  std::initializer_list<const char*> optional);

// Parses the first "<param>[:=|=][^|]<default>" of a macro's params list and consumes it from `s`.
// `has_spec` is false for a parameter without any default spec.
std::string parse_macro_arg(std::string_view& s, Macro::Default& def, bool& has_spec);

// The document processing (xacro's eval_all).
void process_document(Context& ctx, Node* document);

}  // namespace mechsim::description::xacro
