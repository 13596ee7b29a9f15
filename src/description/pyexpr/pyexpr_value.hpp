#pragma once
// Values of the Python expression subset that xacro's ${...} expressions use: None, bool, int,
// float, str, list, tuple, dict and opaque objects (namespaces, functions). Printing follows
// Python's str()/repr() (floats as the shortest round-trip repr, True/False, 'quoted' strings
// inside containers).

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace mechsim::description::pyexpr {

// A Python-level exception (NameError, TypeError, ...): `type` is the Python class name.
class PyError : public std::runtime_error {
 public:
  PyError(std::string type, const std::string& message)
      : std::runtime_error(message), type_(std::move(type)) {}
  const std::string& type() const { return type_; }

 private:
  std::string type_;
};

class Value;
struct ListData;
struct DictData;
class Object;

class Value {
 public:
  enum class Kind : std::uint8_t { None, Bool, Int, Float, Str, List, Tuple, Dict, Object };

  Value() = default;
  static Value none() { return Value(); }
  static Value boolean(bool b) { Value v; v.data_ = b; return v; }
  static Value integer(std::int64_t i) { Value v; v.data_ = i; return v; }
  static Value real(double d) { Value v; v.data_ = d; return v; }
  static Value str(std::string s) { Value v; v.data_ = std::move(s); return v; }
  static Value list(std::vector<Value> items);
  static Value tuple(std::vector<Value> items);
  static Value dict(std::vector<std::pair<Value, Value>> items);
  static Value object(std::shared_ptr<Object> o) { Value v; v.data_ = std::move(o); return v; }

  Kind kind() const;
  bool is_none() const { return data_.index() == 0; }
  bool is_bool() const { return data_.index() == 1; }
  bool is_int() const { return data_.index() == 2; }
  bool is_float() const { return data_.index() == 3; }
  bool is_str() const { return data_.index() == 4; }
  bool is_list() const { return data_.index() == 5; }
  bool is_tuple() const { return data_.index() == 6; }
  bool is_dict() const { return data_.index() == 7; }
  bool is_object() const { return data_.index() == 8; }
  bool is_number() const { return is_bool() || is_int() || is_float(); }  // bool is an int in Python
  bool is_sequence() const { return is_list() || is_tuple(); }

  bool as_bool() const { return std::get<bool>(data_); }
  std::int64_t as_int() const;  // bool or int
  double as_float() const;      // bool, int or float
  const std::string& as_str() const { return std::get<std::string>(data_); }
  std::string& as_str() { return std::get<std::string>(data_); }
  const std::vector<Value>& items() const;  // list or tuple
  std::vector<Value>& items_mut();
  const DictData& as_dict() const { return *std::get<std::shared_ptr<DictData>>(data_); }
  DictData& as_dict_mut() { return *std::get<std::shared_ptr<DictData>>(data_); }
  const std::shared_ptr<Object>& as_object() const { return std::get<std::shared_ptr<Object>>(data_); }

  std::string type_name() const;  // Python's type name: 'int', 'str', ...

 private:
  std::variant<std::monostate, bool, std::int64_t, double, std::string, std::shared_ptr<ListData>,
               std::shared_ptr<ListData>, std::shared_ptr<DictData>, std::shared_ptr<Object>>
      data_;
};

struct ListData {
  std::vector<Value> items;
};

struct DictData {
  std::vector<std::pair<Value, Value>> items;  // insertion order, as Python 3.7+
  const Value* find(const Value& key) const;
  void set(Value key, Value value);
};

// Opaque objects: property namespaces, yaml wrappers, functions.
class Object {
 public:
  virtual ~Object() = default;
  virtual std::string type_name() const = 0;
  // Attribute access `obj.name`; false when there is no such attribute.
  virtual bool get_attr(std::string_view name, Value& out);
  // Item access `obj[key]`; false when unsupported or missing.
  virtual bool get_item(const Value& key, Value& out);
  virtual bool contains(const Value& key, bool& out);
  virtual bool callable() const { return false; }
  virtual Value call(std::vector<Value>& args, std::vector<std::pair<std::string, Value>>& kwargs);
  virtual std::string repr() const;
};

using Kwargs = std::vector<std::pair<std::string, Value>>;
using NativeFn = std::function<Value(std::vector<Value>& args, Kwargs& kwargs)>;

// A named native function (builtins, math, xacro.*, bound methods).
class Function : public Object {
 public:
  Function(std::string name, NativeFn fn) : name_(std::move(name)), fn_(std::move(fn)) {}
  std::string type_name() const override { return "builtin_function_or_method"; }
  bool callable() const override { return true; }
  Value call(std::vector<Value>& args, Kwargs& kwargs) override { return fn_(args, kwargs); }
  std::string repr() const override { return "<built-in function " + name_ + ">"; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  NativeFn fn_;
};

Value make_function(std::string name, NativeFn fn);

// Python's repr() of a float: shortest round-trip digits, exponent form outside [1e-4, 1e16).
std::string float_repr(double d);
// Python's str() and repr().
std::string to_str(const Value& v);
std::string to_repr(const Value& v);
void append_str(std::string& out, const Value& v);
std::string str_repr(std::string_view s);

bool truthy(const Value& v);
bool equals(const Value& a, const Value& b);
// Python's ordering (<); throws TypeError for unorderable types.
bool less_than(const Value& a, const Value& b);

}  // namespace mechsim::description::pyexpr
