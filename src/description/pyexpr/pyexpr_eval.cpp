// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include "description/pyexpr/pyexpr_eval.hpp"

#include <cmath>
#include <limits>

namespace mechsim::description::pyexpr {
namespace {

[[noreturn]] void type_error(const std::string& msg) { throw PyError("TypeError", msg); }

std::string operand_error(const char* op, const Value& a, const Value& b) {
  return std::string("unsupported operand type(s) for ") + op + ": '" + a.type_name() + "' and '" +
         b.type_name() + "'";
}

// Integer arithmetic that overflows 64 bits falls back to float (Python would use big ints).
Value int_or_float(bool overflow, std::int64_t r, double fallback) {
  return overflow ? Value::real(fallback) : Value::integer(r);
}

double py_fmod(double a, double b) {
  double m = std::fmod(a, b);
  if (m != 0.0 && ((b < 0) != (m < 0))) m += b;
  if (m == 0.0) m = std::copysign(0.0, b);
  return m;
}

Value repeat(const Value& seq, std::int64_t n) {
  if (seq.is_str()) {
    std::string out;
    if (n > 0) {
      out.reserve(seq.as_str().size() * static_cast<std::size_t>(n));
      for (std::int64_t i = 0; i < n; ++i) out += seq.as_str();
    }
    return Value::str(std::move(out));
  }
  std::vector<Value> out;
  for (std::int64_t i = 0; i < n; ++i) out.insert(out.end(), seq.items().begin(), seq.items().end());
  return seq.is_list() ? Value::list(std::move(out)) : Value::tuple(std::move(out));
}

}  // namespace

Value binary_op(Op op, const Value& a, const Value& b) {
  const bool nums = a.is_number() && b.is_number();
  const bool ints = nums && !a.is_float() && !b.is_float();
  switch (op) {
    case Op::Add:
      if (ints) {
        std::int64_t r;
        bool o = __builtin_add_overflow(a.as_int(), b.as_int(), &r);
        return int_or_float(o, r, a.as_float() + b.as_float());
      }
      if (nums) return Value::real(a.as_float() + b.as_float());
      if (a.is_str() && b.is_str()) return Value::str(a.as_str() + b.as_str());
      if ((a.is_list() && b.is_list()) || (a.is_tuple() && b.is_tuple())) {
        std::vector<Value> out = a.items();
        out.insert(out.end(), b.items().begin(), b.items().end());
        return a.is_list() ? Value::list(std::move(out)) : Value::tuple(std::move(out));
      }
      if (a.is_str() || b.is_str()) {
        const Value& other = a.is_str() ? b : a;
        type_error("can only concatenate str (not \"" + other.type_name() + "\") to str");
      }
      type_error(operand_error("+", a, b));
    case Op::Sub:
      if (ints) {
        std::int64_t r;
        bool o = __builtin_sub_overflow(a.as_int(), b.as_int(), &r);
        return int_or_float(o, r, a.as_float() - b.as_float());
      }
      if (nums) return Value::real(a.as_float() - b.as_float());
      type_error(operand_error("-", a, b));
    case Op::Mul:
      if (ints) {
        std::int64_t r;
        bool o = __builtin_mul_overflow(a.as_int(), b.as_int(), &r);
        return int_or_float(o, r, a.as_float() * b.as_float());
      }
      if (nums) return Value::real(a.as_float() * b.as_float());
      if ((a.is_str() || a.is_sequence()) && (b.is_int() || b.is_bool())) return repeat(a, b.as_int());
      if ((b.is_str() || b.is_sequence()) && (a.is_int() || a.is_bool())) return repeat(b, a.as_int());
      if (a.is_str() || b.is_str()) type_error("can't multiply sequence by non-int of type '" +
                                               (a.is_str() ? b : a).type_name() + "'");
      type_error(operand_error("*", a, b));
    case Op::Div:
      if (nums) {
        if (b.as_float() == 0.0) throw PyError("ZeroDivisionError", ints ? "division by zero" : "float division by zero");
        return Value::real(a.as_float() / b.as_float());
      }
      type_error(operand_error("/", a, b));
    case Op::FloorDiv:
      if (ints) {
        const std::int64_t x = a.as_int();
        const std::int64_t y = b.as_int();
        if (y == 0) throw PyError("ZeroDivisionError", "integer division or modulo by zero");
        std::int64_t q = x / y;
        if ((x % y != 0) && ((x < 0) != (y < 0))) --q;
        return Value::integer(q);
      }
      if (nums) {
        if (b.as_float() == 0.0) throw PyError("ZeroDivisionError", "float floor division by zero");
        const double x = a.as_float();
        const double y = b.as_float();
        double mod = std::fmod(x, y);
        double div = (x - mod) / y;
        if (mod != 0.0 && ((y < 0) != (mod < 0))) div -= 1.0;
        double fl = 0.0;
        if (div != 0.0) {
          fl = std::floor(div);
          if (div - fl > 0.5) fl += 1.0;
        } else {
          fl = std::copysign(0.0, x / y);
        }
        return Value::real(fl);
      }
      type_error(operand_error("//", a, b));
    case Op::Mod:
      if (a.is_str()) return Value::str(percent_format(a.as_str(), b));
      if (ints) {
        const std::int64_t x = a.as_int();
        const std::int64_t y = b.as_int();
        if (y == 0) throw PyError("ZeroDivisionError", "integer division or modulo by zero");
        std::int64_t m = x % y;
        if (m != 0 && ((m < 0) != (y < 0))) m += y;
        return Value::integer(m);
      }
      if (nums) {
        if (b.as_float() == 0.0) throw PyError("ZeroDivisionError", "float modulo");
        return Value::real(py_fmod(a.as_float(), b.as_float()));
      }
      type_error(operand_error("%", a, b));
    case Op::Pow:
      if (ints && b.as_int() >= 0) {
        std::int64_t base = a.as_int();
        std::int64_t e = b.as_int();
        std::int64_t r = 1;
        bool o = false;
        while (e > 0 && !o) {
          if (e & 1) o = __builtin_mul_overflow(r, base, &r);
          e >>= 1;
          if (e > 0 && !o) o = __builtin_mul_overflow(base, base, &base);
        }
        return int_or_float(o, r, std::pow(a.as_float(), b.as_float()));
      }
      if (nums) {
        if (a.as_float() == 0.0 && b.as_float() < 0) {
          throw PyError("ZeroDivisionError", "0.0 cannot be raised to a negative power");
        }
        const double r = std::pow(a.as_float(), b.as_float());
        if (std::isnan(r) && !std::isnan(a.as_float()) && !std::isnan(b.as_float())) {
          throw PyError("ValueError", "complex results are not supported");
        }
        return Value::real(r);
      }
      type_error(operand_error("** or pow()", a, b));
    case Op::BitOr:
    case Op::BitXor:
    case Op::BitAnd:
    case Op::LShift:
    case Op::RShift: {
      if (!ints) type_error(operand_error("bitwise operator", a, b));
      const std::int64_t x = a.as_int();
      const std::int64_t y = b.as_int();
      if (op == Op::BitOr) return (a.is_bool() && b.is_bool()) ? Value::boolean(x | y) : Value::integer(x | y);
      if (op == Op::BitXor) return (a.is_bool() && b.is_bool()) ? Value::boolean(x ^ y) : Value::integer(x ^ y);
      if (op == Op::BitAnd) return (a.is_bool() && b.is_bool()) ? Value::boolean(x & y) : Value::integer(x & y);
      if (y < 0) throw PyError("ValueError", "negative shift count");
      if (op == Op::LShift) return Value::integer(y >= 63 ? 0 : x << y);
      return Value::integer(y >= 63 ? (x < 0 ? -1 : 0) : x >> y);
    }
    default: break;
  }
  type_error("unsupported operator");
}

namespace {

bool contains(const Value& container, const Value& item) {
  if (container.is_str()) {
    if (!item.is_str()) type_error("'in <string>' requires string as left operand, not " + item.type_name());
    return container.as_str().find(item.as_str()) != std::string::npos;
  }
  if (container.is_sequence()) {
    for (const Value& v : container.items()) {
      if (equals(v, item)) return true;
    }
    return false;
  }
  if (container.is_dict()) return container.as_dict().find(item) != nullptr;
  if (container.is_object()) {
    bool result = false;
    if (container.as_object()->contains(item, result)) return result;
  }
  type_error("argument of type '" + container.type_name() + "' is not iterable");
}

bool identical(const Value& a, const Value& b) {
  if (a.kind() != b.kind()) return false;
  if (a.is_none()) return true;
  if (a.is_object()) return a.as_object() == b.as_object();
  return equals(a, b);
}

bool compare(Op op, const Value& a, const Value& b) {
  switch (op) {
    case Op::Eq: return equals(a, b);
    case Op::Ne: return !equals(a, b);
    case Op::Lt: return less_than(a, b);
    case Op::Gt: return less_than(b, a);
    case Op::Le: return !less_than(b, a);
    case Op::Ge: return !less_than(a, b);
    case Op::In: return contains(b, a);
    case Op::NotIn: return !contains(b, a);
    case Op::Is: return identical(a, b);
    case Op::IsNot: return !identical(a, b);
    default: return false;
  }
}

std::int64_t normalize_index(std::int64_t i, std::size_t size, const char* what) {
  const auto n = static_cast<std::int64_t>(size);
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw PyError("IndexError", std::string(what) + " index out of range");
  return i;
}

Value subscript(const Value& obj, const Value& key) {
  if (obj.is_sequence() || obj.is_str()) {
    if (!key.is_int() && !key.is_bool()) {
      type_error(obj.type_name() + " indices must be integers or slices, not " + key.type_name());
    }
    if (obj.is_str()) {
      const auto i = normalize_index(key.as_int(), obj.as_str().size(), "string");
      return Value::str(std::string(1, obj.as_str()[static_cast<std::size_t>(i)]));
    }
    const auto i = normalize_index(key.as_int(), obj.items().size(), obj.is_list() ? "list" : "tuple");
    return obj.items()[static_cast<std::size_t>(i)];
  }
  if (obj.is_dict()) {
    const Value* v = obj.as_dict().find(key);
    if (v == nullptr) throw PyError("KeyError", to_repr(key));
    return *v;
  }
  if (obj.is_object()) {
    Value out;
    if (obj.as_object()->get_item(key, out)) return out;
    throw PyError("KeyError", to_repr(key));
  }
  type_error("'" + obj.type_name() + "' object is not subscriptable");
}

Value slice(const Value& obj, const Value& lo, const Value& hi, const Value& st) {
  std::int64_t step = st.is_none() ? 1 : st.as_int();
  if (step == 0) throw PyError("ValueError", "slice step cannot be zero");
  const std::size_t size = obj.is_str() ? obj.as_str().size() : obj.items().size();
  const auto n = static_cast<std::int64_t>(size);
  auto clamp = [&](const Value& v, std::int64_t def) {
    if (v.is_none()) return def;
    std::int64_t i = v.as_int();
    if (i < 0) i += n;
    if (step > 0) return std::clamp<std::int64_t>(i, 0, n);
    return std::clamp<std::int64_t>(i, -1, n - 1);
  };
  const std::int64_t start = clamp(lo, step > 0 ? 0 : n - 1);
  const std::int64_t stop = clamp(hi, step > 0 ? n : -1);
  if (obj.is_str()) {
    std::string out;
    for (std::int64_t i = start; step > 0 ? i < stop : i > stop; i += step) out += obj.as_str()[static_cast<std::size_t>(i)];
    return Value::str(std::move(out));
  }
  std::vector<Value> out;
  for (std::int64_t i = start; step > 0 ? i < stop : i > stop; i += step) out.push_back(obj.items()[static_cast<std::size_t>(i)]);
  return obj.is_list() ? Value::list(std::move(out)) : Value::tuple(std::move(out));
}

std::vector<Value> iterate(const Value& v) {
  if (v.is_sequence()) return v.items();
  if (v.is_str()) {
    std::vector<Value> out;
    for (char c : v.as_str()) out.push_back(Value::str(std::string(1, c)));
    return out;
  }
  if (v.is_dict()) {
    std::vector<Value> out;
    for (const auto& kv : v.as_dict().items) out.push_back(kv.first);
    return out;
  }
  type_error("'" + v.type_name() + "' object is not iterable");
}

class Evaluator {
 public:
  explicit Evaluator(Scope& scope) : scope_(scope) {}

  Value eval(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::Const: return e.value;
      case Expr::Kind::Name: return lookup(e.name);
      case Expr::Kind::Attr: return get_attribute(eval(*e.args[0]), e.name);
      case Expr::Kind::Subscript: {
        Value obj = eval(*e.args[0]);
        const Expr& key = *e.args[1];
        if (key.kind == Expr::Kind::Slice) {
          if (!obj.is_sequence() && !obj.is_str()) type_error("'" + obj.type_name() + "' object is not subscriptable");
          auto opt = [&](const ExprPtr& p) { return p ? eval(*p) : Value::none(); };
          return slice(obj, opt(key.args[0]), opt(key.args[1]), opt(key.args[2]));
        }
        return subscript(obj, eval(key));
      }
      case Expr::Kind::Slice: type_error("invalid slice");
      case Expr::Kind::Call: return call(e);
      case Expr::Kind::Unary: {
        Value v = eval(*e.args[0]);
        switch (e.op) {
          case Op::Not: return Value::boolean(!truthy(v));
          case Op::Neg:
            if (v.is_float()) return Value::real(-v.as_float());
            if (v.is_number()) return Value::integer(-v.as_int());
            type_error("bad operand type for unary -: '" + v.type_name() + "'");
          case Op::Pos:
            if (v.is_float()) return v;
            if (v.is_number()) return Value::integer(v.as_int());
            type_error("bad operand type for unary +: '" + v.type_name() + "'");
          case Op::Invert:
            if (v.is_int() || v.is_bool()) return Value::integer(~v.as_int());
            type_error("bad operand type for unary ~: '" + v.type_name() + "'");
          default: type_error("bad unary operator");
        }
      }
      case Expr::Kind::Binary: {
        Value a = eval(*e.args[0]);
        Value b = eval(*e.args[1]);
        return binary_op(e.op, a, b);
      }
      case Expr::Kind::BoolOp: {
        Value a = eval(*e.args[0]);
        if (e.op == Op::And ? !truthy(a) : truthy(a)) return a;
        return eval(*e.args[1]);
      }
      case Expr::Kind::Compare: {
        Value left = eval(*e.args[0]);
        for (std::size_t i = 0; i < e.ops.size(); ++i) {
          Value right = eval(*e.args[i + 1]);
          if (!compare(e.ops[i], left, right)) return Value::boolean(false);
          left = std::move(right);
        }
        return Value::boolean(true);
      }
      case Expr::Kind::IfExp: return truthy(eval(*e.args[0])) ? eval(*e.args[1]) : eval(*e.args[2]);
      case Expr::Kind::List:
      case Expr::Kind::Tuple: {
        std::vector<Value> items;
        items.reserve(e.args.size());
        for (const auto& a : e.args) items.push_back(eval(*a));
        return e.kind == Expr::Kind::List ? Value::list(std::move(items)) : Value::tuple(std::move(items));
      }
      case Expr::Kind::Dict: {
        Value d = Value::dict({});
        for (std::size_t i = 0; i + 1 < e.args.size(); i += 2) {
          Value k = eval(*e.args[i]);
          d.as_dict_mut().set(std::move(k), eval(*e.args[i + 1]));
        }
        return d;
      }
      case Expr::Kind::ListComp: {
        std::vector<Value> out;
        comprehend(e, 0, out);
        return Value::list(std::move(out));
      }
      case Expr::Kind::Lambda: type_error("lambda expressions are not supported");
    }
    type_error("unsupported expression");
  }

 private:
  Value lookup(const std::string& name) {
    for (auto it = locals_.rbegin(); it != locals_.rend(); ++it) {
      if (it->first == name) return it->second;
    }
    Value out;
    if (scope_.lookup(name, out)) return out;
    throw PyError("NameError", "name '" + name + "' is not defined");
  }

  void comprehend(const Expr& e, std::size_t level, std::vector<Value>& out) {
    if (level == e.clauses.size()) {
      out.push_back(eval(*e.args[0]));
      return;
    }
    const CompClause& c = e.clauses[level];
    const std::vector<Value> seq = iterate(eval(*c.iter));
    for (const Value& item : seq) {
      const std::size_t mark = locals_.size();
      if (c.targets.size() == 1) {
        locals_.emplace_back(c.targets[0], item);
      } else {
        const std::vector<Value> parts = iterate(item);
        if (parts.size() != c.targets.size()) throw PyError("ValueError", "cannot unpack: wrong number of values");
        for (std::size_t i = 0; i < parts.size(); ++i) locals_.emplace_back(c.targets[i], parts[i]);
      }
      bool keep = true;
      for (const auto& cond : c.conditions) {
        if (!truthy(eval(*cond))) {
          keep = false;
          break;
        }
      }
      if (keep) comprehend(e, level + 1, out);
      locals_.resize(mark);
    }
  }

  Value call(const Expr& e) {
    Value fn = eval(*e.args[0]);
    const std::size_t nkw = e.kwnames.size();
    const std::size_t npos = e.args.size() - 1 - nkw;
    std::vector<Value> args;
    args.reserve(npos);
    for (std::size_t i = 0; i < npos; ++i) args.push_back(eval(*e.args[1 + i]));
    Kwargs kwargs;
    for (std::size_t i = 0; i < nkw; ++i) kwargs.emplace_back(e.kwnames[i], eval(*e.args[1 + npos + i]));
    if (!fn.is_object() || !fn.as_object()->callable()) {
      type_error("'" + fn.type_name() + "' object is not callable");
    }
    return fn.as_object()->call(args, kwargs);
  }

  Scope& scope_;
  std::vector<std::pair<std::string, Value>> locals_;
};

}  // namespace

Value evaluate(const Expr& expr, Scope& scope) {
  Evaluator ev(scope);
  return ev.eval(expr);
}

std::vector<Value> iterate_value(const Value& v) { return iterate(v); }

}  // namespace mechsim::description::pyexpr
