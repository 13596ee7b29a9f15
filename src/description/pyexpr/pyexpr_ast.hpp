#pragma once
// The syntax tree of one Python expression (the subset robot descriptions use) and its parser.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "description/pyexpr/pyexpr_value.hpp"

namespace mechsim::description::pyexpr {

enum class Op : std::uint8_t {
  Add, Sub, Mul, Div, FloorDiv, Mod, Pow, BitOr, BitXor, BitAnd, LShift, RShift,  // binary
  Neg, Pos, Invert, Not,                                                          // unary
  Lt, Le, Gt, Ge, Eq, Ne, In, NotIn, Is, IsNot,                                   // comparison
  And, Or
};

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

// One `for targets in iter if cond...` clause of a comprehension.
struct CompClause {
  std::vector<std::string> targets;  // one name, or several for tuple unpacking
  ExprPtr iter;
  std::vector<ExprPtr> conditions;
};

struct Expr {
  enum class Kind : std::uint8_t {
    Const, Name, Attr, Subscript, Slice, Call, Unary, Binary, BoolOp, Compare, IfExp, List, Tuple,
    Dict, ListComp, Lambda
  };
  Kind kind = Kind::Const;
  Op op = Op::Add;
  int height = 1;                    // longest path to a leaf (bounded by the parser)
  Value value;                       // Const
  std::string name;                  // Name, Attr
  std::vector<ExprPtr> args;         // operands / elements / call arguments (nullptr: slice gap)
  std::vector<Op> ops;               // Compare: the chain's operators
  std::vector<std::string> kwnames;  // Call: names of the trailing keyword arguments;
                                     // Lambda: parameter names
  std::vector<CompClause> clauses;   // ListComp
};

// Parses a whole expression; throws PyError("SyntaxError", ...) on bad syntax and
// PyError("NameError", "Use of invalid name(s): ...") for names starting with "__" (as xacro).
ExprPtr parse_expression(std::string_view source);

}  // namespace mechsim::description::pyexpr
