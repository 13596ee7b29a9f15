#pragma once
// Evaluates parsed Python expressions against a name scope, with Python's semantics for the
// operators, indexing, slicing, comparisons, calls and a few str/list/dict methods.

#include <string>
#include <string_view>
#include <unordered_map>

#include "description/pyexpr/pyexpr_ast.hpp"
#include "description/pyexpr/pyexpr_value.hpp"

namespace mechsim::description::pyexpr {

// Where names are looked up (local properties, then the global builtins).
class Scope {
 public:
  virtual ~Scope() = default;
  virtual bool lookup(std::string_view name, Value& out) = 0;
};

// A plain name -> value table used for the global symbols.
using SymbolMap = std::unordered_map<std::string, Value>;

// Evaluates `expr`; throws PyError for Python-level errors (NameError, TypeError, ...).
Value evaluate(const Expr& expr, Scope& scope);

// Adds the builtins (int, float, str, len, min, max, round, abs, ...) and the math module
// (as `math` and, as xacro does, each member directly: sin, pi, radians, ...).
void add_builtins(SymbolMap& globals);

// Python conversions used by builtins and by xacro's literal evaluation.
bool parse_python_int(std::string_view text, std::int64_t& out);   // int(str)
bool parse_python_float(std::string_view text, double& out);       // float(str)

// `format % args` and str.format(...)
std::string percent_format(const std::string& format, const Value& args);
std::string format_value(const Value& v, std::string_view spec);

// Python's binary operators on values (+ - * / // % ** | ^ & << >>).
Value binary_op(Op op, const Value& a, const Value& b);

// The items of an iterable (list, tuple, str, dict keys).
std::vector<Value> iterate_value(const Value& v);

// Attribute access on any value (methods of str/list/dict, dict keys, object attributes).
Value get_attribute(const Value& obj, const std::string& name);

}  // namespace mechsim::description::pyexpr
