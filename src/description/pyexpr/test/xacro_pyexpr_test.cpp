// The Python-subset expression evaluator behind xacro's ${...}: values print as Python prints them.
#include <gtest/gtest.h>

#include <cmath>

#include "description/pyexpr/pyexpr_ast.hpp"
#include "description/pyexpr/pyexpr_eval.hpp"

namespace mechsim::description::pyexpr {
namespace {

class Globals : public Scope {
 public:
  Globals() {
    add_builtins(table_);
    table_["x"] = Value::integer(3);
    table_["s"] = Value::str("AbC");
  }
  bool lookup(std::string_view name, Value& out) override {
    auto it = table_.find(std::string(name));
    if (it == table_.end()) return false;
    out = it->second;
    return true;
  }

 private:
  SymbolMap table_;
};

std::string eval(const std::string& expr) {
  Globals g;
  return to_str(evaluate(*parse_expression(expr), g));
}

std::string error_type(const std::string& expr) {
  try {
    Globals g;
    evaluate(*parse_expression(expr), g);
  } catch (const PyError& e) {
    return e.type();
  }
  return "no error";
}

TEST(PyExpr, FloatReprIsShortestRoundTrip) {
  EXPECT_EQ(float_repr(1.5707963267948966), "1.5707963267948966");
  EXPECT_EQ(float_repr(0.1), "0.1");
  EXPECT_EQ(float_repr(1e-05), "1e-05");
  EXPECT_EQ(float_repr(0.0001), "0.0001");
  EXPECT_EQ(float_repr(100.0), "100.0");
  EXPECT_EQ(float_repr(1e16), "1e+16");
  EXPECT_EQ(float_repr(1e15), "1000000000000000.0");
  EXPECT_EQ(float_repr(1.2345678901234568e17), "1.2345678901234568e+17");
  EXPECT_EQ(float_repr(-0.0), "-0.0");
  EXPECT_EQ(float_repr(5e-324), "5e-324");
  EXPECT_EQ(float_repr(1.7976931348623157e308), "1.7976931348623157e+308");
  EXPECT_EQ(float_repr(-2.5e-7), "-2.5e-07");
}

TEST(PyExpr, Arithmetic) {
  EXPECT_EQ(eval("1 + 2 * 3"), "7");
  EXPECT_EQ(eval("7 // 2"), "3");
  EXPECT_EQ(eval("-7 // 2"), "-4");
  EXPECT_EQ(eval("-7.0 // 2"), "-4.0");
  EXPECT_EQ(eval("7 % -3"), "-2");
  EXPECT_EQ(eval("-7.5 % 2"), "0.5");
  EXPECT_EQ(eval("2 ** 10"), "1024");
  EXPECT_EQ(eval("2 ** -1"), "0.5");
  EXPECT_EQ(eval("-2 ** 2"), "-4");
  EXPECT_EQ(eval("1 / 4"), "0.25");
  EXPECT_EQ(eval("1 / 3"), "0.3333333333333333");
  EXPECT_EQ(eval("0.1 + 0.2"), "0.30000000000000004");
  EXPECT_EQ(eval("0.9 / 2 - 0.2"), "0.25");
  EXPECT_EQ(eval("x * 14 * 2.1"), "88.2");
  EXPECT_EQ(eval("True + 1"), "2");
  EXPECT_EQ(eval("1."), "1.0");
  EXPECT_EQ(eval(".5e1"), "5.0");
  EXPECT_EQ(eval("0x1F + 0b11"), "34");
}

TEST(PyExpr, MathAndBuiltins) {
  EXPECT_EQ(eval("pi"), "3.141592653589793");
  EXPECT_EQ(eval("1. + sin(pi)"), "1.0000000000000002");
  EXPECT_EQ(eval("radians(90)"), "1.5707963267948966");
  EXPECT_EQ(eval("degrees(pi / 2)"), "90.0");
  EXPECT_EQ(eval("math.sqrt(2)"), "1.4142135623730951");
  EXPECT_EQ(eval("atan2(1, 1)"), "0.7853981633974483");
  EXPECT_EQ(eval("floor(2.7)"), "2");
  EXPECT_EQ(eval("ceil(2.1)"), "3");
  EXPECT_EQ(eval("abs(-2)"), "2");
  EXPECT_EQ(eval("abs(-2.5)"), "2.5");
  EXPECT_EQ(eval("min(1, 2.5)"), "1");
  EXPECT_EQ(eval("max([1, 5, 3])"), "5");
  EXPECT_EQ(eval("int('42')"), "42");
  EXPECT_EQ(eval("int(-3.9)"), "-3");
  EXPECT_EQ(eval("float('1.5')"), "1.5");
  EXPECT_EQ(eval("float(2)"), "2.0");
  EXPECT_EQ(eval("str(1.0) + str(2)"), "1.02");
  EXPECT_EQ(eval("len('abc') + len([1, 2])"), "5");
  EXPECT_EQ(eval("round(2.5)"), "2");
  EXPECT_EQ(eval("round(3.5)"), "4");
  EXPECT_EQ(eval("round(1.2345, 2)"), "1.23");
  EXPECT_EQ(eval("sum([1, 2, 3.5])"), "6.5");
}

TEST(PyExpr, StringsAndFormatting) {
  EXPECT_EQ(eval("'a' + \"b\""), "ab");
  EXPECT_EQ(eval("'ab' * 2"), "abab");
  EXPECT_EQ(eval("'%s-%d-%.3f' % ('x', 3, 1.23456)"), "x-3-1.235");
  EXPECT_EQ(eval("'%5.1f|%-3s|%03d' % (2.25, 'a', 7)"), "  2.2|a  |007");
  EXPECT_EQ(eval("'{}_{}'.format('a', 1)"), "a_1");
  EXPECT_EQ(eval("'{0:.2f} {name}'.format(pi, name='n')"), "3.14 n");
  EXPECT_EQ(eval("s.lower() + s.upper()"), "abcABC");
  EXPECT_EQ(eval("'a,b'.split(',')"), "['a', 'b']");
  EXPECT_EQ(eval("'-'.join(['a', 'b'])"), "a-b");
  EXPECT_EQ(eval("u'x' 'y'"), "xy");
  EXPECT_EQ(eval("'it\\'s'"), "it's");
  EXPECT_EQ(eval("['it\\'s', 'a']"), "[\"it's\", 'a']");
}

TEST(PyExpr, ContainersIndexingSlicing) {
  EXPECT_EQ(eval("[1, 2, 3][-1]"), "3");
  EXPECT_EQ(eval("[1, 2, 3][1:]"), "[2, 3]");
  EXPECT_EQ(eval("'hello'[::-1]"), "olleh");
  EXPECT_EQ(eval("'hello'[1:3]"), "el");
  EXPECT_EQ(eval("(1,)"), "(1,)");
  EXPECT_EQ(eval("(1, 2)"), "(1, 2)");
  EXPECT_EQ(eval("[1, 'a', 2.5, None, True]"), "[1, 'a', 2.5, None, True]");
  EXPECT_EQ(eval("{'a': 1, 'b': [2]}"), "{'a': 1, 'b': [2]}");
  EXPECT_EQ(eval("{'a': 1}['a']"), "1");
  EXPECT_EQ(eval("{'a': 1}.a"), "1");
  EXPECT_EQ(eval("dict(a=1, b=2)"), "{'a': 1, 'b': 2}");
  EXPECT_EQ(eval("[v * v for v in range(5) if v % 2 == 0]"), "[0, 4, 16]");
  EXPECT_EQ(eval("[a + b for a, b in zip([1, 2], [10, 20])]"), "[11, 22]");
}

TEST(PyExpr, LogicAndComparisons) {
  EXPECT_EQ(eval("1 < 2 < 3"), "True");
  EXPECT_EQ(eval("1 < 3 < 2"), "False");
  EXPECT_EQ(eval("1 == 1.0"), "True");
  EXPECT_EQ(eval("1 if False else 2"), "2");
  EXPECT_EQ(eval("not 0"), "True");
  EXPECT_EQ(eval("True and 0"), "0");
  EXPECT_EQ(eval("None or 'x'"), "x");
  EXPECT_EQ(eval("'b' in 'abc' and 3 not in [1, 2]"), "True");
  EXPECT_EQ(eval("None is None"), "True");
  EXPECT_EQ(eval("'a' < 'b'"), "True");
}

TEST(PyExpr, ErrorsArePythonExceptions) {
  EXPECT_EQ(error_type("1 / 0"), "ZeroDivisionError");
  EXPECT_EQ(error_type("1 // 0"), "ZeroDivisionError");
  EXPECT_EQ(error_type("undefined_name"), "NameError");
  EXPECT_EQ(error_type("'a' + 1"), "TypeError");
  EXPECT_EQ(error_type("[1][5]"), "IndexError");
  EXPECT_EQ(error_type("{'a': 1}['b']"), "KeyError");
  EXPECT_EQ(error_type("sqrt(-1)"), "ValueError");
  EXPECT_EQ(error_type("x.nope"), "AttributeError");
  EXPECT_EQ(error_type("1 +"), "SyntaxError");
  EXPECT_EQ(error_type("(1"), "SyntaxError");
  EXPECT_EQ(error_type("{"), "SyntaxError");
  EXPECT_EQ(error_type("__import__('os')"), "NameError");
  EXPECT_EQ(error_type("''.__class__"), "NameError");
}

TEST(PyExpr, DeepNestingIsAnErrorNotACrash) {
  const std::string deep = std::string(5000, '(') + "1" + std::string(5000, ')');
  EXPECT_EQ(error_type(deep), "SyntaxError");
  std::string minus(5000, '-');
  EXPECT_EQ(error_type(minus + "1"), "SyntaxError");
  std::string chain = "1";
  for (int i = 0; i < 5000; ++i) chain += "+1";
  EXPECT_EQ(error_type(chain), "SyntaxError");
  std::string sum = "1";
  for (int i = 0; i < 150; ++i) sum += "+1";
  EXPECT_EQ(eval(sum), "151");
}

TEST(PyExpr, LiteralParsing) {
  std::int64_t i = 0;
  double d = 0;
  EXPECT_TRUE(parse_python_int(" 42 ", i));
  EXPECT_EQ(i, 42);
  EXPECT_TRUE(parse_python_int("-1_000", i));
  EXPECT_EQ(i, -1000);
  EXPECT_FALSE(parse_python_int("1.0", i));
  EXPECT_FALSE(parse_python_int("0x10", i));
  EXPECT_TRUE(parse_python_float("1e-3", d));
  EXPECT_DOUBLE_EQ(d, 1e-3);
  EXPECT_TRUE(parse_python_float(" .5 ", d));
  EXPECT_DOUBLE_EQ(d, 0.5);
  EXPECT_TRUE(parse_python_float("-Infinity", d));
  EXPECT_TRUE(std::isinf(d) && d < 0);
  EXPECT_FALSE(parse_python_float("1 -2", d));
  EXPECT_FALSE(parse_python_float(".", d));
  EXPECT_FALSE(parse_python_float("1e", d));
}

}  // namespace
}  // namespace mechsim::description::pyexpr
