// xacro's text evaluation: ${expr}, $(substitution args), $$ escapes, literal conversion.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "description/package_path.hpp"
#include "description/xacro/xacro_context.hpp"

namespace mechsim::description::xacro {
namespace fs = std::filesystem;

namespace {
constexpr int kMaxEvalDepth = 300;  // nested expression evaluations (lazy property chains)
}

void fail(std::string message) { throw Failure{std::move(message)}; }

Context::Context(const XacroOptions& opts) : options(opts), args(opts.args.begin(), opts.args.end()) {
  pyexpr::add_builtins(globals);
  add_xacro_functions(*this);
}

std::ostream& Context::warn() { return options.diagnostics != nullptr ? *options.diagnostics : std::cerr; }

int Context::add_file(const std::string& path) {
  files.push_back(path);
  return static_cast<int>(files.size()) - 1;
}

std::string Context::current_file() const { return file_stack.empty() ? std::string() : files[file_stack.back()]; }

std::string Context::location(int file, int line) const {
  std::string where = file >= 0 && file < static_cast<int>(files.size()) ? files[file] : "???";
  if (line > 0) where += ":" + std::to_string(line);
  return where;
}

void Context::print_location() {
  std::ostream& out = warn();
  const char* msg = "when instantiating macro:";
  for (auto it = macro_stack.rbegin(); it != macro_stack.rend(); ++it) {
    out << msg << " " << it->macro->name << " (" << location(it->macro->file, 0) << ")\n";
    msg = "instantiated from:";
  }
  msg = macro_stack.empty() ? "when processing file:" : "in file:";
  for (auto it = file_stack.rbegin(); it != file_stack.rend(); ++it) {
    out << msg << " " << files[*it] << "\n";
    msg = "included from:";
  }
}

Value eval_literal(Value v) {
  if (!v.is_str()) return v;
  const std::string& s = v.as_str();
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') return Value::str(s.substr(1, s.size() - 2));
  if (s.find('_') != std::string::npos) return v;
  std::int64_t i = 0;
  if (pyexpr::parse_python_int(s, i)) return Value::integer(i);
  double d = 0;
  if (pyexpr::parse_python_float(s, d)) return Value::real(d);
  if (s == "true" || s == "True") return Value::boolean(true);
  if (s == "false" || s == "False") return Value::boolean(false);
  return v;
}

bool boolean_value(const Value& v, std::string_view condition) {
  if (v.is_str()) {
    const std::string& s = v.as_str();
    if (s == "true" || s == "True") return true;
    if (s == "false" || s == "False") return false;
    std::int64_t i = 0;
    if (pyexpr::parse_python_int(s, i)) return i != 0;
    fail("Xacro conditional \"" + std::string(condition) + "\" evaluated to \"" + s +
         "\", which is not a boolean expression.");
  }
  return pyexpr::truthy(v);
}

Value Context::eval_text(std::string_view text, Symbols& symbols) {
  if (text.find('$') == std::string_view::npos) return Value::str(std::string(text));
  std::vector<Value> results;
  const std::size_t n = text.size();
  std::size_t p = 0;
  auto invalid = [&](std::size_t at) { fail("invalid expression: " + std::string(text.substr(at))); };
  while (p < n) {
    if (text[p] != '$') {
      const std::size_t q = std::min(text.find('$', p), n);
      results.push_back(Value::str(std::string(text.substr(p, q - p))));
      p = q;
      continue;
    }
    std::size_t q = p + 1;
    while (q < n && text[q] == '$') ++q;
    if (q - p >= 2) {  // $$...${ or $$...$( : drop one '$'
      if (q < n && (text[q] == '{' || text[q] == '(')) {
        results.push_back(Value::str(std::string(text.substr(p + 1, q - p))));
        p = q + 1;
        continue;
      }
      invalid(p);
    }
    if (p + 1 == n) {
      results.push_back(Value::str("$"));
      ++p;
      continue;
    }
    if (text[p + 1] == '{') {
      const std::size_t close = text.find('}', p + 2);
      if (close == std::string_view::npos) invalid(p);
      results.push_back(eval_expression(text.substr(p + 2, close - p - 2), symbols));
      p = close + 1;
      continue;
    }
    if (text[p + 1] == '(') {
      const std::size_t close = text.find(')', p + 2);
      if (close == std::string_view::npos) invalid(p);
      results.push_back(Value::str(eval_extension(text.substr(p + 2, close - p - 2), symbols)));
      p = close + 1;
      continue;
    }
    q = p + 1;
    while (q < n && text[q] != '{' && text[q] != '(' && text[q] != '$') ++q;
    results.push_back(Value::str(std::string(text.substr(p, q - p))));
    p = q;
  }
  if (results.size() == 1) return std::move(results[0]);
  std::string joined;
  for (const Value& v : results) pyexpr::append_str(joined, v);
  return Value::str(std::move(joined));
}

std::string Context::eval_text_str(std::string_view text, Symbols& symbols) {
  if (text.find('$') == std::string_view::npos) return std::string(text);
  Value v = eval_text(text, symbols);
  if (v.is_str()) return std::move(v.as_str());
  return pyexpr::to_str(v);
}

Value Context::eval_expression(std::string_view inner, Symbols& symbols) {
  if (++eval_depth > kMaxEvalDepth) {
    --eval_depth;
    fail("maximum recursion depth exceeded while evaluating expressions (a property or argument "
         "refers to itself through too many levels)");
  }
  struct DepthGuard {
    int& d;
    ~DepthGuard() { --d; }
  } guard{eval_depth};
  // Built only on failure (this runs for every ${...}); a huge expression is cut in the message.
  const auto suffix = [inner] {
    constexpr std::size_t kShown = 200;
    return " \nwhen evaluating expression '" +
           (inner.size() <= kShown ? std::string(inner)
                                   : std::string(inner.substr(0, kShown)) + "...' (" + std::to_string(inner.size()) +
                                         " characters)") +
           (inner.size() <= kShown ? "'" : "");
  };
  try {
    std::string expr = inner.find('$') == std::string_view::npos ? std::string(inner) : eval_text_str(inner, symbols);
    // Python's compile() of the stripped text
    const auto b = expr.find_first_not_of(" \t\n\r");
    const auto e = expr.find_last_not_of(" \t\n\r");
    expr = b == std::string::npos ? std::string() : expr.substr(b, e - b + 1);
    auto it = expr_cache.find(expr);
    if (it == expr_cache.end()) {
      it = expr_cache.emplace(expr, std::shared_ptr<const pyexpr::Expr>(pyexpr::parse_expression(expr))).first;
    }
    const std::shared_ptr<const pyexpr::Expr> ast = it->second;  // keeps it alive
    ExprScope scope(*this, symbols);
    return pyexpr::evaluate(*ast, scope);
  } catch (const pyexpr::PyError& err) {
    std::string msg = err.what();
    if (err.type() == "KeyError" && msg.empty()) msg = "KeyError";
    fail(msg + suffix());
  } catch (Failure& f) {
    f.message += suffix();
    throw;
  } catch (const std::exception& e) {  // e.g. out-of-range numbers in library conversions
    fail(e.what() + suffix());
  }
}

namespace {

std::vector<std::string> split_words(std::string_view s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\n') ++j;
    if (j > i) out.emplace_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

// Names seen by $(eval ...): the substitution args, then roslaunch's helper functions.
class EvalArgScope : public pyexpr::Scope {
 public:
  EvalArgScope(Context& ctx, pyexpr::SymbolMap& functions) : ctx_(ctx), functions_(functions) {}
  bool lookup(std::string_view name, Value& out) override {
    auto it = ctx_.args.find(std::string(name));
    if (it != ctx_.args.end()) {
      out = Value::str(it->second);
      return true;
    }
    auto f = functions_.find(std::string(name));
    if (f == functions_.end()) return false;
    out = f->second;
    return true;
  }

 private:
  Context& ctx_;
  pyexpr::SymbolMap& functions_;
};

}  // namespace

std::string Context::eval_extension(std::string_view raw_inner, Symbols& symbols) {
  const std::string inner = eval_text_str(raw_inner, symbols);
  if (inner == "cwd") return fs::current_path().string();
  auto words = split_words(inner);
  if (words.empty()) fail("invalid substitution argument: $(" + inner + ")");
  const std::string& cmd = words[0];
  auto need = [&](std::size_t count, const char* usage) {
    if (words.size() != count + 1) fail(std::string(usage) + " (in $(" + inner + "))");
  };
  auto find_pkg = [&](const std::string& pkg) {
    // Once per package and expansion: a lookup walks ROS_PACKAGE_PATH and reads manifests, and
    // the PR2 asks for pr2_description dozens of times.
    if (auto it = found_packages.find(pkg); it != found_packages.end()) return it->second;
    auto dir = find_package(pkg, options.packages);
    if (!dir) fail("resource not found: " + pkg + " (package not given with --package and not on ROS_PACKAGE_PATH)");
    return found_packages.emplace(pkg, *dir).first->second;
  };
  if (cmd == "arg") {
    need(1, "$(arg var) must specify exactly one argument");
    auto it = args.find(words[1]);
    if (it == args.end()) fail("Undefined substitution argument " + words[1]);
    return it->second;
  }
  if (cmd == "env") {
    need(1, "$(env var) must specify exactly one argument");
    const char* v = std::getenv(words[1].c_str());
    if (v == nullptr) fail("environment variable '" + words[1] + "' is not set");
    return v;
  }
  if (cmd == "optenv") {
    if (words.size() < 2) fail("$(optenv var) must specify an environment variable");
    const char* v = std::getenv(words[1].c_str());
    if (v != nullptr) return v;
    std::string def;
    for (std::size_t i = 2; i < words.size(); ++i) def += (i > 2 ? " " : "") + words[i];
    return def;
  }
  if (cmd == "find") {
    need(1, "$(find pkg) must specify exactly one argument");
    return find_pkg(words[1]);
  }
  if (cmd == "dirname") {
    std::error_code ec;
    const fs::path abs = fs::absolute(current_file(), ec);
    return abs.parent_path().string();
  }
  if (cmd == "anon") {
    need(1, "$(anon var) must specify exactly one argument");
    return "$(" + inner + ")";  // xacro leaves anon unresolved (resolve_anon=False)
  }
  if (cmd == "eval") {
    const std::string expr = inner.substr(inner.find("eval") + 4);
    pyexpr::SymbolMap functions = globals;
    functions["true"] = Value::boolean(true);
    functions["false"] = Value::boolean(false);
    functions["arg"] = pyexpr::make_function("arg", [this](std::vector<Value>& a, pyexpr::Kwargs&) {
      if (a.size() != 1 || !a[0].is_str()) throw pyexpr::PyError("TypeError", "arg() takes one name");
      auto it = args.find(a[0].as_str());
      if (it == args.end()) throw pyexpr::PyError("ArgException", "Undefined substitution argument " + a[0].as_str());
      return Value::str(it->second);
    });
    functions["env"] = pyexpr::make_function("env", [](std::vector<Value>& a, pyexpr::Kwargs&) {
      const char* v = a.size() == 1 ? std::getenv(pyexpr::to_str(a[0]).c_str()) : nullptr;
      if (v == nullptr) throw pyexpr::PyError("SubstitutionException", "environment variable is not set");
      return Value::str(v);
    });
    functions["optenv"] = pyexpr::make_function("optenv", [](std::vector<Value>& a, pyexpr::Kwargs&) {
      const char* v = a.empty() ? nullptr : std::getenv(pyexpr::to_str(a[0]).c_str());
      if (v != nullptr) return Value::str(v);
      return a.size() > 1 ? a[1] : Value::str("");
    });
    functions["find"] = pyexpr::make_function("find", [&](std::vector<Value>& a, pyexpr::Kwargs&) {
      if (a.size() != 1) throw pyexpr::PyError("TypeError", "find() takes one package name");
      return Value::str(find_pkg(pyexpr::to_str(a[0])));
    });
    functions["dirname"] = pyexpr::make_function("dirname", [this](std::vector<Value>&, pyexpr::Kwargs&) {
      std::error_code ec;
      return Value::str(fs::absolute(current_file(), ec).parent_path().string());
    });
    EvalArgScope scope(*this, functions);
    try {
      auto ast = pyexpr::parse_expression(expr.substr(std::min(expr.find_first_not_of(" \t"), expr.size())));
      return pyexpr::to_str(pyexpr::evaluate(*ast, scope));
    } catch (const pyexpr::PyError& e) {
      fail(std::string(e.what()) + " \nwhen evaluating $(" + inner + ")");
    }
  }
  fail("Unknown substitution command [" + inner + "]. Valid commands are ['find', 'env', 'optenv', 'dirname', 'anon', 'arg', 'eval']");
}

}  // namespace mechsim::description::xacro
