// Attribute access (dict keys as attributes, str/list/dict methods) and string formatting
// (`%` and str.format) for the Python expression subset.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "description/pyexpr/pyexpr_eval.hpp"

namespace mechsim::description::pyexpr {
namespace {

[[noreturn]] void type_error(const std::string& msg) { throw PyError("TypeError", msg); }

Value method(const std::string& name, NativeFn fn) { return make_function(name, std::move(fn)); }

const std::string& str_arg(const std::string& fn, const std::vector<Value>& a, std::size_t i) {
  if (i >= a.size() || !a[i].is_str()) type_error(fn + "() argument must be str");
  return a[i].as_str();
}

std::vector<Value> split(const std::string& s, const std::vector<Value>& a) {
  std::vector<Value> out;
  if (a.empty() || a[0].is_none()) {
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i >= s.size()) break;
      std::size_t j = i;
      while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      out.push_back(Value::str(s.substr(i, j - i)));
      i = j;
    }
    return out;
  }
  const std::string& sep = str_arg("split", a, 0);
  if (sep.empty()) throw PyError("ValueError", "empty separator");
  std::size_t start = 0;
  while (true) {
    const std::size_t p = s.find(sep, start);
    if (p == std::string::npos) break;
    out.push_back(Value::str(s.substr(start, p - start)));
    start = p + sep.size();
  }
  out.push_back(Value::str(s.substr(start)));
  return out;
}

std::string strip(const std::string& s, const std::vector<Value>& a, bool left, bool right) {
  const std::string chars = (a.empty() || a[0].is_none()) ? std::string(" \t\n\r\f\v") : a[0].as_str();
  std::size_t b = 0;
  std::size_t e = s.size();
  if (left) while (b < e && chars.find(s[b]) != std::string::npos) ++b;
  if (right) while (e > b && chars.find(s[e - 1]) != std::string::npos) --e;
  return s.substr(b, e - b);
}

Value str_method(const std::string& self, const std::string& name) {
  const std::string s = self;
  if (name == "lower" || name == "upper") {
    const bool up = name == "upper";
    return method(name, [s, up](std::vector<Value>&, Kwargs&) {
      std::string r = s;
      for (char& c : r) c = static_cast<char>(up ? std::toupper(static_cast<unsigned char>(c)) : std::tolower(static_cast<unsigned char>(c)));
      return Value::str(std::move(r));
    });
  }
  if (name == "strip" || name == "lstrip" || name == "rstrip") {
    const bool l = name != "rstrip";
    const bool r = name != "lstrip";
    return method(name, [s, l, r](std::vector<Value>& a, Kwargs&) { return Value::str(strip(s, a, l, r)); });
  }
  if (name == "split") {
    return method(name, [s](std::vector<Value>& a, Kwargs&) { return Value::list(split(s, a)); });
  }
  if (name == "join") {
    return method(name, [s](std::vector<Value>& a, Kwargs&) {
      if (a.size() != 1) type_error("join() takes exactly one argument");
      std::string out;
      bool first = true;
      for (const Value& v : iterate_value(a[0])) {
        if (!v.is_str()) type_error("sequence item: expected str instance, " + v.type_name() + " found");
        if (!first) out += s;
        first = false;
        out += v.as_str();
      }
      return Value::str(std::move(out));
    });
  }
  if (name == "replace") {
    return method(name, [s](std::vector<Value>& a, Kwargs&) {
      const std::string& from = str_arg("replace", a, 0);
      const std::string& to = str_arg("replace", a, 1);
      std::int64_t count = a.size() > 2 ? a[2].as_int() : -1;
      std::string out;
      std::size_t start = 0;
      while (count != 0) {
        const std::size_t p = from.empty() ? (start <= s.size() ? start : std::string::npos) : s.find(from, start);
        if (p == std::string::npos) break;
        out.append(s, start, p - start);
        out += to;
        if (from.empty()) {
          if (p < s.size()) out += s[p];
          start = p + 1;
        } else {
          start = p + from.size();
        }
        --count;
      }
      if (start < s.size()) out.append(s, start);
      return Value::str(std::move(out));
    });
  }
  if (name == "startswith" || name == "endswith") {
    const bool starts = name == "startswith";
    return method(name, [s, starts](std::vector<Value>& a, Kwargs&) {
      std::vector<Value> options = (!a.empty() && a[0].is_tuple()) ? a[0].items() : a;
      for (const Value& o : options) {
        if (!o.is_str()) type_error("startswith/endswith argument must be str");
        if (starts ? s.starts_with(o.as_str()) : s.ends_with(o.as_str())) return Value::boolean(true);
      }
      return Value::boolean(false);
    });
  }
  if (name == "find" || name == "count" || name == "index") {
    return method(name, [s, name](std::vector<Value>& a, Kwargs&) {
      const std::string& sub = str_arg(name, a, 0);
      if (name == "count") {
        std::int64_t n = 0;
        if (sub.empty()) return Value::integer(static_cast<std::int64_t>(s.size()) + 1);
        for (std::size_t p = s.find(sub); p != std::string::npos; p = s.find(sub, p + sub.size())) ++n;
        return Value::integer(n);
      }
      const std::size_t p = s.find(sub);
      if (p == std::string::npos) {
        if (name == "index") throw PyError("ValueError", "substring not found");
        return Value::integer(-1);
      }
      return Value::integer(static_cast<std::int64_t>(p));
    });
  }
  if (name == "format") {
    return method(name, [s](std::vector<Value>& a, Kwargs& kw) {
      std::string out;
      std::size_t auto_index = 0;
      for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '{' && i + 1 < s.size() && s[i + 1] == '{') {
          out += '{';
          ++i;
          continue;
        }
        if (c == '}' && i + 1 < s.size() && s[i + 1] == '}') {
          out += '}';
          ++i;
          continue;
        }
        if (c != '{') {
          out += c;
          continue;
        }
        const std::size_t close = s.find('}', i);
        if (close == std::string::npos) throw PyError("ValueError", "Single '{' encountered in format string");
        std::string field = s.substr(i + 1, close - i - 1);
        i = close;
        std::string spec;
        if (const auto colon = field.find(':'); colon != std::string::npos) {
          spec = field.substr(colon + 1);
          field.resize(colon);
        }
        bool repr = false;
        if (field.size() >= 2 && field[field.size() - 2] == '!') {
          repr = field.back() == 'r';
          field.resize(field.size() - 2);
        }
        Value v;
        if (field.empty()) {
          if (auto_index >= a.size()) throw PyError("IndexError", "Replacement index out of range");
          v = a[auto_index++];
        } else if (std::isdigit(static_cast<unsigned char>(field[0]))) {
          const auto idx = static_cast<std::size_t>(std::stoul(field));
          if (idx >= a.size()) throw PyError("IndexError", "Replacement index out of range");
          v = a[idx];
        } else {
          bool found = false;
          for (auto& [k, val] : kw) {
            if (k == field) {
              v = val;
              found = true;
            }
          }
          if (!found) throw PyError("KeyError", str_repr(field));
        }
        out += repr ? to_repr(v) : format_value(v, spec);
      }
      return Value::str(std::move(out));
    });
  }
  throw PyError("AttributeError", "'str' object has no attribute '" + name + "'");
}

Value dict_method(const Value& self, const std::string& name) {
  if (name == "keys" || name == "values" || name == "items") {
    return method(name, [self, name](std::vector<Value>&, Kwargs&) {
      std::vector<Value> out;
      for (const auto& [k, v] : self.as_dict().items) {
        if (name == "keys") out.push_back(k);
        else if (name == "values") out.push_back(v);
        else out.push_back(Value::tuple({k, v}));
      }
      return Value::list(std::move(out));
    });
  }
  if (name == "get") {
    return method(name, [self](std::vector<Value>& a, Kwargs&) {
      if (a.empty()) type_error("get expected at least 1 argument");
      const Value* v = self.as_dict().find(a[0]);
      if (v != nullptr) return *v;
      return a.size() > 1 ? a[1] : Value::none();
    });
  }
  throw PyError("AttributeError", "The yaml dictionary has no key '" + name + "'");
}

Value list_method(const Value& self, const std::string& name) {
  if (name == "index" || name == "count") {
    return method(name, [self, name](std::vector<Value>& a, Kwargs&) {
      if (a.size() != 1) type_error(name + "() takes exactly one argument");
      std::int64_t n = 0;
      for (std::size_t i = 0; i < self.items().size(); ++i) {
        if (equals(self.items()[i], a[0])) {
          if (name == "index") return Value::integer(static_cast<std::int64_t>(i));
          ++n;
        }
      }
      if (name == "index") throw PyError("ValueError", to_repr(a[0]) + " is not in list");
      return Value::integer(n);
    });
  }
  throw PyError("AttributeError", "'" + self.type_name() + "' object has no attribute '" + name + "'");
}

}  // namespace

Value get_attribute(const Value& obj, const std::string& name) {
  switch (obj.kind()) {
    case Value::Kind::Dict: {
      // xacro's yaml dicts (and xacro.dotify) expose their keys as attributes.
      if (const Value* v = obj.as_dict().find(Value::str(name))) return *v;
      return dict_method(obj, name);
    }
    case Value::Kind::Str: return str_method(obj.as_str(), name);
    case Value::Kind::List:
    case Value::Kind::Tuple: return list_method(obj, name);
    case Value::Kind::Object: {
      Value out;
      if (obj.as_object()->get_attr(name, out)) return out;
      break;
    }
    case Value::Kind::Float:
      if (name == "real") return obj;
      if (name == "is_integer") {
        const double d = obj.as_float();
        return method(name, [d](std::vector<Value>&, Kwargs&) { return Value::boolean(std::floor(d) == d); });
      }
      break;
    default: break;
  }
  throw PyError("AttributeError", "'" + obj.type_name() + "' object has no attribute '" + name + "'");
}

// One conversion of printf style: flags, width, precision, type.
std::string printf_one(const Value& v, const std::string& flags, int width, int precision, char type) {
  std::string body;
  if (type == 's' || type == 'r') {
    body = type == 's' ? to_str(v) : to_repr(v);
    if (precision >= 0 && static_cast<std::size_t>(precision) < body.size()) body.resize(static_cast<std::size_t>(precision));
  } else if (type == 'd' || type == 'i' || type == 'x' || type == 'X' || type == 'o') {
    if (!v.is_number()) type_error("%" + std::string(1, type) + " format: a real number is required, not " + v.type_name());
    const long long i = v.is_float() ? static_cast<long long>(std::trunc(v.as_float())) : v.as_int();
    std::string fmt = "%" + flags;
    if (precision >= 0) fmt += "." + std::to_string(precision);
    fmt += "ll";
    fmt += type == 'i' ? 'd' : type;
    char buf[128];
    std::snprintf(buf, sizeof(buf), fmt.c_str(), i);
    body = buf;
  } else if (std::string_view("eEfFgG").find(type) != std::string_view::npos) {
    if (!v.is_number()) type_error("must be real number, not " + v.type_name());
    std::string fmt = "%" + flags + "." + std::to_string(precision < 0 ? 6 : precision) + type;
    char buf[512];
    std::snprintf(buf, sizeof(buf), fmt.c_str(), v.as_float());
    body = buf;
  } else {
    throw PyError("ValueError", std::string("unsupported format character '") + type + "'");
  }
  if (width > 0 && body.size() < static_cast<std::size_t>(width)) {
    const std::size_t pad = static_cast<std::size_t>(width) - body.size();
    if (flags.find('-') != std::string::npos) body.append(pad, ' ');
    else if (flags.find('0') != std::string::npos && type != 's' && type != 'r') {
      const std::size_t sign = (!body.empty() && (body[0] == '-' || body[0] == '+')) ? 1 : 0;
      body.insert(sign, pad, '0');
    } else body.insert(0, pad, ' ');
  }
  return body;
}

std::string percent_format(const std::string& format, const Value& args) {
  std::vector<Value> list = args.is_tuple() ? args.items() : std::vector<Value>{args};
  std::size_t next = 0;
  std::string out;
  for (std::size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '%') {
      out += format[i];
      continue;
    }
    ++i;
    if (i >= format.size()) throw PyError("ValueError", "incomplete format");
    if (format[i] == '%') {
      out += '%';
      continue;
    }
    const Value* mapped = nullptr;
    Value mapped_value;
    if (format[i] == '(') {
      const std::size_t close = format.find(')', i);
      if (close == std::string::npos || !args.is_dict()) throw PyError("TypeError", "format requires a mapping");
      const Value* v = args.as_dict().find(Value::str(format.substr(i + 1, close - i - 1)));
      if (v == nullptr) throw PyError("KeyError", str_repr(format.substr(i + 1, close - i - 1)));
      mapped_value = *v;
      mapped = &mapped_value;
      i = close + 1;
    }
    std::string flags;
    while (i < format.size() && std::string_view("-+ #0").find(format[i]) != std::string_view::npos) flags += format[i++];
    int width = 0;
    while (i < format.size() && std::isdigit(static_cast<unsigned char>(format[i]))) width = width * 10 + (format[i++] - '0');
    int precision = -1;
    if (i < format.size() && format[i] == '.') {
      ++i;
      precision = 0;
      while (i < format.size() && std::isdigit(static_cast<unsigned char>(format[i]))) precision = precision * 10 + (format[i++] - '0');
    }
    if (i >= format.size()) throw PyError("ValueError", "incomplete format");
    const char type = format[i];
    if (mapped == nullptr) {
      if (next >= list.size()) throw PyError("TypeError", "not enough arguments for format string");
      mapped = &list[next++];
    }
    out += printf_one(*mapped, flags, width, precision, type);
  }
  if (next < list.size() && !args.is_dict()) {
    throw PyError("TypeError", "not all arguments converted during string formatting");
  }
  return out;
}

std::string format_value(const Value& v, std::string_view spec) {
  if (spec.empty()) return to_str(v);
  // [[fill]align][sign][#][0][width][,][.precision][type]
  std::size_t i = 0;
  char fill = ' ';
  char align = 0;
  if (spec.size() >= 2 && std::string_view("<>^=").find(spec[1]) != std::string_view::npos) {
    fill = spec[0];
    align = spec[1];
    i = 2;
  } else if (!spec.empty() && std::string_view("<>^=").find(spec[0]) != std::string_view::npos) {
    align = spec[0];
    i = 1;
  }
  std::string flags;
  if (i < spec.size() && (spec[i] == '+' || spec[i] == '-' || spec[i] == ' ')) {
    if (spec[i] != '-') flags += spec[i];
    ++i;
  }
  if (i < spec.size() && spec[i] == '#') flags += spec[i++];
  if (i < spec.size() && spec[i] == '0') {
    if (align == 0) {
      fill = '0';
      align = '=';
    }
    ++i;
  }
  int width = 0;
  while (i < spec.size() && std::isdigit(static_cast<unsigned char>(spec[i]))) width = width * 10 + (spec[i++] - '0');
  int precision = -1;
  if (i < spec.size() && spec[i] == '.') {
    ++i;
    precision = 0;
    while (i < spec.size() && std::isdigit(static_cast<unsigned char>(spec[i]))) precision = precision * 10 + (spec[i++] - '0');
  }
  char type = i < spec.size() ? spec[i] : 0;
  std::string body;
  if (type == 0) {
    if (v.is_float() && precision >= 0) body = printf_one(v, flags, 0, precision, 'g');
    else if (v.is_str() && precision >= 0) body = printf_one(v, "", 0, precision, 's');
    else body = to_str(v);
  } else if (type == '%') {
    body = printf_one(Value::real(v.as_float() * 100.0), flags, 0, precision, 'f') + "%";
  } else if (type == 'n') {
    body = printf_one(v, flags, 0, precision, 'g');
  } else if (type == 'b') {
    std::int64_t n = v.as_int();
    std::string bits;
    const bool neg = n < 0;
    auto u = static_cast<std::uint64_t>(neg ? -n : n);
    do {
      bits.insert(bits.begin(), static_cast<char>('0' + (u & 1)));
      u >>= 1;
    } while (u != 0);
    body = (neg ? "-" : "") + bits;
  } else {
    body = printf_one(v, flags, 0, precision, type);
  }
  if (width > 0 && body.size() < static_cast<std::size_t>(width)) {
    const std::size_t pad = static_cast<std::size_t>(width) - body.size();
    if (align == 0) align = (v.is_number() && !v.is_bool()) ? '>' : '<';
    if (align == '<') body.append(pad, fill);
    else if (align == '>') body.insert(0, pad, fill);
    else if (align == '^') {
      body.insert(0, pad / 2, fill);
      body.append(pad - pad / 2, fill);
    } else {
      const std::size_t sign = (!body.empty() && (body[0] == '-' || body[0] == '+' || body[0] == ' ')) ? 1 : 0;
      body.insert(sign, pad, fill);
    }
  }
  return body;
}

}  // namespace mechsim::description::pyexpr
