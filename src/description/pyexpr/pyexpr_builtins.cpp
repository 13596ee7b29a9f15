// Python builtins, the math module, str/list/dict methods and string formatting.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include "description/pyexpr/pyexpr_eval.hpp"

namespace mechsim::description::pyexpr {

namespace {

[[noreturn]] void type_error(const std::string& msg) { throw PyError("TypeError", msg); }

void expect_args(const std::string& name, const std::vector<Value>& args, std::size_t lo, std::size_t hi) {
  if (args.size() < lo || args.size() > hi) {
    type_error(name + "() takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
               " argument(s) (" + std::to_string(args.size()) + " given)");
  }
}

double num_arg(const std::string& name, const Value& v) {
  if (!v.is_number()) type_error("must be real number, not " + v.type_name() + " (in " + name + "())");
  return v.as_float();
}

std::string_view trim(std::string_view s) {
  const char* ws = " \t\n\r\f\v";
  const auto b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

Value to_int(const Value& v) {
  if (v.is_int()) return v;
  if (v.is_bool()) return Value::integer(v.as_int());
  if (v.is_float()) {
    const double d = v.as_float();
    if (std::isnan(d)) throw PyError("ValueError", "cannot convert float NaN to integer");
    if (std::isinf(d)) throw PyError("OverflowError", "cannot convert float infinity to integer");
    return Value::integer(static_cast<std::int64_t>(std::trunc(d)));
  }
  if (v.is_str()) {
    std::int64_t i = 0;
    if (parse_python_int(v.as_str(), i)) return Value::integer(i);
    throw PyError("ValueError", "invalid literal for int() with base 10: " + str_repr(v.as_str()));
  }
  type_error("int() argument must be a string or a number, not '" + v.type_name() + "'");
}

Value to_float(const Value& v) {
  if (v.is_number()) return Value::real(v.as_float());
  if (v.is_str()) {
    double d = 0;
    if (parse_python_float(v.as_str(), d)) return Value::real(d);
    throw PyError("ValueError", "could not convert string to float: " + str_repr(v.as_str()));
  }
  type_error("float() argument must be a string or a number, not '" + v.type_name() + "'");
}

Value round_value(std::vector<Value>& args) {
  expect_args("round", args, 1, 2);
  const Value& x = args[0];
  if (!x.is_number()) type_error("type " + x.type_name() + " doesn't define __round__ method");
  if (args.size() == 1 || args[1].is_none()) {
    if (!x.is_float()) return Value::integer(x.as_int());
    const double d = x.as_float();
    if (!std::isfinite(d)) throw PyError("ValueError", "cannot round a non-finite float to an integer");
    return Value::integer(static_cast<std::int64_t>(std::nearbyint(d)));  // ties to even
  }
  const std::int64_t nd = args[1].as_int();
  if (!x.is_float()) return Value::integer(x.as_int());
  const double d = x.as_float();
  if (!std::isfinite(d) || nd > 300) return x;
  if (nd < 0) {
    const double p = std::pow(10.0, static_cast<double>(-nd));
    return Value::real(std::nearbyint(d / p) * p);
  }
  // printf rounds the exact binary value half-to-even, as Python's round() does.
  char buf[400];
  std::snprintf(buf, sizeof(buf), "%.*f", static_cast<int>(nd), d);
  return Value::real(std::strtod(buf, nullptr));
}

Value min_max(std::vector<Value>& args, bool is_max) {
  const char* name = is_max ? "max" : "min";
  if (args.empty()) type_error(std::string(name) + " expected at least 1 argument, got 0");
  std::vector<Value> items = args.size() == 1 ? iterate_value(args[0]) : args;
  if (items.empty()) throw PyError("ValueError", std::string(name) + "() arg is an empty sequence");
  Value best = items[0];
  for (std::size_t i = 1; i < items.size(); ++i) {
    if (is_max ? less_than(best, items[i]) : less_than(items[i], best)) best = items[i];
  }
  return best;
}

using MathFn1 = double (*)(double);

void add_math1(SymbolMap& m, const std::string& name, MathFn1 f, bool domain_check = true) {
  m[name] = make_function(name, [name, f, domain_check](std::vector<Value>& a, Kwargs&) {
    expect_args(name, a, 1, 1);
    const double x = num_arg(name, a[0]);
    const double r = f(x);
    if (domain_check && std::isnan(r) && !std::isnan(x)) throw PyError("ValueError", "math domain error");
    return Value::real(r);
  });
}

double deg2rad(double x) { return x * (M_PI / 180.0); }
double rad2deg(double x) { return x * (180.0 / M_PI); }

void add_math(SymbolMap& m) {
  add_math1(m, "sin", [](double x) { return std::sin(x); });
  add_math1(m, "cos", [](double x) { return std::cos(x); });
  add_math1(m, "tan", [](double x) { return std::tan(x); });
  add_math1(m, "asin", [](double x) { return std::asin(x); });
  add_math1(m, "acos", [](double x) { return std::acos(x); });
  add_math1(m, "atan", [](double x) { return std::atan(x); });
  add_math1(m, "sinh", [](double x) { return std::sinh(x); });
  add_math1(m, "cosh", [](double x) { return std::cosh(x); });
  add_math1(m, "tanh", [](double x) { return std::tanh(x); });
  add_math1(m, "asinh", [](double x) { return std::asinh(x); });
  add_math1(m, "acosh", [](double x) { return std::acosh(x); });
  add_math1(m, "atanh", [](double x) { return std::atanh(x); });
  add_math1(m, "exp", [](double x) { return std::exp(x); });
  add_math1(m, "expm1", [](double x) { return std::expm1(x); });
  add_math1(m, "log10", [](double x) { return x <= 0 ? std::nan("") : std::log10(x); });
  add_math1(m, "log2", [](double x) { return x <= 0 ? std::nan("") : std::log2(x); });
  add_math1(m, "log1p", [](double x) { return x <= -1 ? std::nan("") : std::log1p(x); });
  add_math1(m, "sqrt", [](double x) { return std::sqrt(x); });
  add_math1(m, "fabs", [](double x) { return std::fabs(x); });
  add_math1(m, "radians", deg2rad);
  add_math1(m, "degrees", rad2deg);
  add_math1(m, "erf", [](double x) { return std::erf(x); });
  add_math1(m, "erfc", [](double x) { return std::erfc(x); });
  add_math1(m, "gamma", [](double x) { return std::tgamma(x); });
  add_math1(m, "lgamma", [](double x) { return std::lgamma(x); });
  m["log"] = make_function("log", [](std::vector<Value>& a, Kwargs&) {
    expect_args("log", a, 1, 2);
    const double x = num_arg("log", a[0]);
    if (x <= 0) throw PyError("ValueError", "math domain error");
    if (a.size() == 1) return Value::real(std::log(x));
    const double b = num_arg("log", a[1]);
    if (b <= 0 || b == 1) throw PyError("ValueError", "math domain error");
    return Value::real(std::log(x) / std::log(b));
  });
  auto add_math2 = [&m](const std::string& name, double (*f)(double, double)) {
    m[name] = make_function(name, [name, f](std::vector<Value>& a, Kwargs&) {
      expect_args(name, a, 2, 2);
      return Value::real(f(num_arg(name, a[0]), num_arg(name, a[1])));
    });
  };
  add_math2("atan2", [](double y, double x) { return std::atan2(y, x); });
  add_math2("pow", [](double x, double y) { return std::pow(x, y); });
  add_math2("fmod", [](double x, double y) { return std::fmod(x, y); });
  add_math2("copysign", [](double x, double y) { return std::copysign(x, y); });
  add_math2("remainder", [](double x, double y) { return std::remainder(x, y); });
  add_math2("ldexp", [](double x, double y) { return std::ldexp(x, static_cast<int>(y)); });
  m["hypot"] = make_function("hypot", [](std::vector<Value>& a, Kwargs&) {
    double s = 0;
    for (const Value& v : a) s += num_arg("hypot", v) * num_arg("hypot", v);
    return Value::real(a.size() == 2 ? std::hypot(a[0].as_float(), a[1].as_float()) : std::sqrt(s));
  });
  auto add_int_fn = [&m](const std::string& name, double (*f)(double)) {
    m[name] = make_function(name, [name, f](std::vector<Value>& a, Kwargs&) {
      expect_args(name, a, 1, 1);
      if (a[0].is_int() || a[0].is_bool()) return Value::integer(a[0].as_int());
      return to_int(Value::real(f(num_arg(name, a[0]))));
    });
  };
  add_int_fn("floor", [](double x) { return std::floor(x); });
  add_int_fn("ceil", [](double x) { return std::ceil(x); });
  add_int_fn("trunc", [](double x) { return std::trunc(x); });
  auto add_pred = [&m](const std::string& name, bool (*f)(double)) {
    m[name] = make_function(name, [name, f](std::vector<Value>& a, Kwargs&) {
      expect_args(name, a, 1, 1);
      return Value::boolean(f(num_arg(name, a[0])));
    });
  };
  add_pred("isnan", [](double x) { return std::isnan(x); });
  add_pred("isinf", [](double x) { return std::isinf(x); });
  add_pred("isfinite", [](double x) { return std::isfinite(x); });
  m["factorial"] = make_function("factorial", [](std::vector<Value>& a, Kwargs&) {
    expect_args("factorial", a, 1, 1);
    if (!a[0].is_int() || a[0].as_int() < 0) throw PyError("ValueError", "factorial() not defined for negative values");
    std::int64_t r = 1;
    for (std::int64_t i = 2; i <= a[0].as_int(); ++i) {
      if (__builtin_mul_overflow(r, i, &r)) throw PyError("OverflowError", "factorial result too large");
    }
    return Value::integer(r);
  });
  m["gcd"] = make_function("gcd", [](std::vector<Value>& a, Kwargs&) {
    std::int64_t r = 0;
    for (const Value& v : a) r = std::gcd(r, to_int(v).as_int());
    return Value::integer(r);
  });
  m["isclose"] = make_function("isclose", [](std::vector<Value>& a, Kwargs& kw) {
    expect_args("isclose", a, 2, 2);
    double rel = 1e-9;
    double abs_tol = 0.0;
    for (auto& [k, v] : kw) {
      if (k == "rel_tol") rel = v.as_float();
      else if (k == "abs_tol") abs_tol = v.as_float();
    }
    const double x = a[0].as_float();
    const double y = a[1].as_float();
    return Value::boolean(x == y || std::fabs(x - y) <= std::max(rel * std::max(std::fabs(x), std::fabs(y)), abs_tol));
  });
  m["pi"] = Value::real(M_PI);
  m["e"] = Value::real(M_E);
  m["tau"] = Value::real(2 * M_PI);
  m["inf"] = Value::real(std::numeric_limits<double>::infinity());
  m["nan"] = Value::real(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

// A module or namespace: attribute access into a fixed table.
class ModuleObject : public Object {
 public:
  ModuleObject(std::string name, SymbolMap members) : name_(std::move(name)), members_(std::move(members)) {}
  std::string type_name() const override { return "module"; }
  bool get_attr(std::string_view name, Value& out) override {
    auto it = members_.find(std::string(name));
    if (it == members_.end()) return false;
    out = it->second;
    return true;
  }
  std::string repr() const override { return "<module '" + name_ + "'>"; }

 private:
  std::string name_;
  SymbolMap members_;
};

void add_builtins(SymbolMap& g) {
  SymbolMap math;
  add_math(math);
  for (const auto& [k, v] : math) g[k] = v;
  g["math"] = Value::object(std::make_shared<ModuleObject>("math", std::move(math)));

  g["True"] = Value::boolean(true);
  g["False"] = Value::boolean(false);
  g["None"] = Value::none();
  g["int"] = make_function("int", [](std::vector<Value>& a, Kwargs&) {
    expect_args("int", a, 0, 2);
    if (a.empty()) return Value::integer(0);
    if (a.size() == 2) {
      std::int64_t out = 0;
      const std::string s(trim(a[0].as_str()));
      char* end = nullptr;
      out = std::strtoll(s.c_str(), &end, static_cast<int>(a[1].as_int()));
      if (s.empty() || *end != '\0') throw PyError("ValueError", "invalid literal for int(): " + str_repr(s));
      return Value::integer(out);
    }
    return to_int(a[0]);
  });
  g["float"] = make_function("float", [](std::vector<Value>& a, Kwargs&) {
    expect_args("float", a, 0, 1);
    return a.empty() ? Value::real(0.0) : to_float(a[0]);
  });
  g["str"] = make_function("str", [](std::vector<Value>& a, Kwargs&) {
    expect_args("str", a, 0, 1);
    return Value::str(a.empty() ? std::string() : to_str(a[0]));
  });
  g["repr"] = make_function("repr", [](std::vector<Value>& a, Kwargs&) {
    expect_args("repr", a, 1, 1);
    return Value::str(to_repr(a[0]));
  });
  g["bool"] = make_function("bool", [](std::vector<Value>& a, Kwargs&) {
    expect_args("bool", a, 0, 1);
    return Value::boolean(!a.empty() && truthy(a[0]));
  });
  g["len"] = make_function("len", [](std::vector<Value>& a, Kwargs&) {
    expect_args("len", a, 1, 1);
    const Value& v = a[0];
    if (v.is_str()) {
      std::int64_t n = 0;  // code points, as Python counts them
      for (char c : v.as_str()) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      return Value::integer(n);
    }
    if (v.is_sequence()) return Value::integer(static_cast<std::int64_t>(v.items().size()));
    if (v.is_dict()) return Value::integer(static_cast<std::int64_t>(v.as_dict().items.size()));
    type_error("object of type '" + v.type_name() + "' has no len()");
  });
  g["abs"] = make_function("abs", [](std::vector<Value>& a, Kwargs&) {
    expect_args("abs", a, 1, 1);
    if (a[0].is_float()) return Value::real(std::fabs(a[0].as_float()));
    if (a[0].is_number()) return Value::integer(std::llabs(a[0].as_int()));
    type_error("bad operand type for abs(): '" + a[0].type_name() + "'");
  });
  g["min"] = make_function("min", [](std::vector<Value>& a, Kwargs&) { return min_max(a, false); });
  g["max"] = make_function("max", [](std::vector<Value>& a, Kwargs&) { return min_max(a, true); });
  g["round"] = make_function("round", [](std::vector<Value>& a, Kwargs&) { return round_value(a); });
  g["list"] = make_function("list", [](std::vector<Value>& a, Kwargs&) {
    expect_args("list", a, 0, 1);
    return Value::list(a.empty() ? std::vector<Value>{} : iterate_value(a[0]));
  });
  g["tuple"] = make_function("tuple", [](std::vector<Value>& a, Kwargs&) {
    expect_args("tuple", a, 0, 1);
    return Value::tuple(a.empty() ? std::vector<Value>{} : iterate_value(a[0]));
  });
  g["dict"] = make_function("dict", [](std::vector<Value>& a, Kwargs& kw) {
    expect_args("dict", a, 0, 1);
    Value d = Value::dict({});
    if (!a.empty()) {
      if (a[0].is_dict()) {
        d = Value::dict(a[0].as_dict().items);
      } else {
        for (const Value& pair : iterate_value(a[0])) {
          const auto kv = iterate_value(pair);
          if (kv.size() != 2) throw PyError("ValueError", "dictionary update sequence element has wrong length");
          d.as_dict_mut().set(kv[0], kv[1]);
        }
      }
    }
    for (auto& [k, v] : kw) d.as_dict_mut().set(Value::str(k), v);
    return d;
  });
  g["sum"] = make_function("sum", [](std::vector<Value>& a, Kwargs&) {
    expect_args("sum", a, 1, 2);
    Value total = a.size() == 2 ? a[1] : Value::integer(0);
    for (const Value& v : iterate_value(a[0])) total = binary_op(Op::Add, total, v);
    return total;
  });
  g["any"] = make_function("any", [](std::vector<Value>& a, Kwargs&) {
    expect_args("any", a, 1, 1);
    for (const Value& v : iterate_value(a[0])) if (truthy(v)) return Value::boolean(true);
    return Value::boolean(false);
  });
  g["all"] = make_function("all", [](std::vector<Value>& a, Kwargs&) {
    expect_args("all", a, 1, 1);
    for (const Value& v : iterate_value(a[0])) if (!truthy(v)) return Value::boolean(false);
    return Value::boolean(true);
  });
  g["sorted"] = make_function("sorted", [](std::vector<Value>& a, Kwargs& kw) {
    expect_args("sorted", a, 1, 1);
    std::vector<Value> items = iterate_value(a[0]);
    std::stable_sort(items.begin(), items.end(), [](const Value& x, const Value& y) { return less_than(x, y); });
    for (auto& [k, v] : kw) {
      if (k == "reverse" && truthy(v)) std::reverse(items.begin(), items.end());
    }
    return Value::list(std::move(items));
  });
  g["reversed"] = make_function("reversed", [](std::vector<Value>& a, Kwargs&) {
    expect_args("reversed", a, 1, 1);
    std::vector<Value> items = iterate_value(a[0]);
    std::reverse(items.begin(), items.end());
    return Value::list(std::move(items));
  });
  g["range"] = make_function("range", [](std::vector<Value>& a, Kwargs&) {
    expect_args("range", a, 1, 3);
    std::int64_t start = 0;
    std::int64_t stop = 0;
    std::int64_t step = 1;
    if (a.size() == 1) {
      stop = to_int(a[0]).as_int();
    } else {
      start = to_int(a[0]).as_int();
      stop = to_int(a[1]).as_int();
      if (a.size() == 3) step = to_int(a[2]).as_int();
    }
    if (step == 0) throw PyError("ValueError", "range() arg 3 must not be zero");
    std::vector<Value> out;
    for (std::int64_t i = start; step > 0 ? i < stop : i > stop; i += step) {
      out.push_back(Value::integer(i));
      if (out.size() > 10'000'000) throw PyError("MemoryError", "range too large");
    }
    return Value::list(std::move(out));
  });
  g["zip"] = make_function("zip", [](std::vector<Value>& a, Kwargs&) {
    std::vector<std::vector<Value>> seqs;
    std::size_t n = a.empty() ? 0 : SIZE_MAX;
    for (const Value& v : a) {
      seqs.push_back(iterate_value(v));
      n = std::min(n, seqs.back().size());
    }
    std::vector<Value> out;
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<Value> t;
      for (const auto& s : seqs) t.push_back(s[i]);
      out.push_back(Value::tuple(std::move(t)));
    }
    return Value::list(std::move(out));
  });
  g["enumerate"] = make_function("enumerate", [](std::vector<Value>& a, Kwargs&) {
    expect_args("enumerate", a, 1, 2);
    std::int64_t i = a.size() == 2 ? a[1].as_int() : 0;
    std::vector<Value> out;
    for (const Value& v : iterate_value(a[0])) out.push_back(Value::tuple({Value::integer(i++), v}));
    return Value::list(std::move(out));
  });
  g["map"] = make_function("map", [](std::vector<Value>& a, Kwargs& kw) {
    if (a.size() < 2) type_error("map() must have at least two arguments.");
    if (!a[0].is_object() || !a[0].as_object()->callable()) type_error("map(): first argument is not callable");
    std::vector<std::vector<Value>> seqs;
    std::size_t n = SIZE_MAX;
    for (std::size_t i = 1; i < a.size(); ++i) {
      seqs.push_back(iterate_value(a[i]));
      n = std::min(n, seqs.back().size());
    }
    std::vector<Value> out;
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<Value> args;
      for (const auto& s : seqs) args.push_back(s[i]);
      out.push_back(a[0].as_object()->call(args, kw));
    }
    return Value::list(std::move(out));
  });
}

bool parse_python_int(std::string_view text, std::int64_t& out) {
  std::string_view s = trim(text);
  bool neg = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  if (s.empty()) return false;
  std::int64_t v = 0;
  bool prev_underscore = true;
  for (char c : s) {
    if (c == '_') {
      if (prev_underscore) return false;
      prev_underscore = true;
      continue;
    }
    if (c < '0' || c > '9') return false;
    prev_underscore = false;
    if (__builtin_mul_overflow(v, 10, &v) || __builtin_add_overflow(v, c - '0', &v)) return false;
  }
  if (prev_underscore) return false;
  out = neg ? -v : v;
  return true;
}

bool parse_python_float(std::string_view text, double& out) {
  std::string s(trim(text));
  if (s.empty()) return false;
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string_view body = lower;
  bool neg = false;
  if (body[0] == '+' || body[0] == '-') {
    neg = body[0] == '-';
    body.remove_prefix(1);
  }
  if (body == "inf" || body == "infinity") {
    out = neg ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    return true;
  }
  if (body == "nan") {
    out = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  // Python's float grammar: digits [. digits] [e [+-] digits], with at least one digit.
  std::string clean;
  bool digit_seen = false;
  std::size_t i = 0;
  auto digits = [&] {
    bool any = false;
    while (i < body.size() && (std::isdigit(static_cast<unsigned char>(body[i])) || body[i] == '_')) {
      if (body[i] == '_') {
        if (!any || i + 1 >= body.size() || !std::isdigit(static_cast<unsigned char>(body[i + 1]))) return false;
      } else {
        clean += body[i];
        any = true;
      }
      ++i;
    }
    digit_seen = digit_seen || any;
    return true;
  };
  if (!digits()) return false;
  if (i < body.size() && body[i] == '.') {
    clean += '.';
    ++i;
    if (!digits()) return false;
  }
  if (!digit_seen) return false;
  if (i < body.size() && body[i] == 'e') {
    clean += 'e';
    ++i;
    if (i < body.size() && (body[i] == '+' || body[i] == '-')) clean += body[i++];
    const std::size_t before = clean.size();
    if (!digits() || clean.size() == before) return false;
  }
  if (i != body.size()) return false;
  out = std::strtod(clean.c_str(), nullptr);
  if (neg) out = -out;
  return true;
}

}  // namespace mechsim::description::pyexpr
