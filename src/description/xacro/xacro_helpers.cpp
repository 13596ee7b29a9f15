// Small helpers of the document processing: text tests, identifier rules, attribute checks and
// the parsing of macro parameter specs.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <algorithm>

#include "description/xacro/xacro_context.hpp"

namespace mechsim::description::xacro {

bool is_space_text(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  });
}

bool has_non_space(const std::string& s) {
  return std::any_of(s.begin(), s.end(), [](char c) {
    return !(c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v');
  });
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\n\r\f\v");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\n\r\f\v");
  return std::string(s.substr(b, e - b + 1));
}

bool is_identifier(const std::string& s) {
  static const char* const keywords[] = {"False", "None", "True", "and", "as", "assert", "async", "await",
                                         "break", "class", "continue", "def", "del", "elif", "else",
                                         "except", "finally", "for", "from", "global", "if", "import",
                                         "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise",
                                         "return", "try", "while", "with", "yield"};
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (!(std::isalnum(u) || c == '_' || u >= 0x80)) return false;
  }
  return std::none_of(std::begin(keywords), std::end(keywords), [&](const char* k) { return s == k; });
}

Attrs check_attrs(Context& ctx, const Node* n, std::initializer_list<const char*> required,
                  std::initializer_list<const char*> optional) {
  Attrs out;
  for (const char* r : required) {
    const std::string* v = n->attr(r);
    if (v == nullptr) fail(n->name + ": missing required attribute '" + r + "'");
    out.values.push_back(v);
  }
  for (const char* o : optional) out.values.push_back(n->attr(o));
  std::string extra;
  for (const auto& attr : n->attrs) {
    const std::string& k = attr.first;  // a structured binding cannot be captured by Clang 14's lambdas
    const bool known = std::any_of(required.begin(), required.end(), [&](const char* r) { return k == r; }) ||
                       std::any_of(optional.begin(), optional.end(), [&](const char* o) { return k == o; });
    if (!known && !k.starts_with("xmlns:")) extra += (extra.empty() ? "" : ", ") + k;
  }
  if (!extra.empty()) {
    ctx.warn() << n->name << ": unknown attribute(s): " << extra << "\n";
    ctx.print_location();
  }
  return out;
}

// parse_macro_arg: "<param>[:=|=][^|]<default>" (see Macro::Default); consumes from `s`.
std::string parse_macro_arg(std::string_view& s, Macro::Default& def, bool& has_spec) {
  auto is_ws = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  std::size_t i = 0;
  while (i < s.size() && is_ws(s[i])) ++i;
  std::size_t j = i;
  while (j < s.size() && !is_ws(s[j]) && s[j] != ':' && s[j] != '=') ++j;
  std::size_t k = j;
  while (k < s.size() && is_ws(s[k])) ++k;
  const bool spec = j > i && k < s.size() && (s[k] == '=' || (s[k] == ':' && k + 1 < s.size() && s[k + 1] == '='));
  if (!spec) {
    std::size_t e = i;
    while (e < s.size() && !is_ws(s[e])) ++e;
    std::string param(s.substr(i, e - i));
    while (e < s.size() && is_ws(s[e])) ++e;
    s.remove_prefix(e);
    has_spec = false;
    return param;
  }
  std::string param(s.substr(i, j - i));
  k += s[k] == ':' ? 2 : 1;
  while (k < s.size() && is_ws(s[k])) ++k;
  def.forward = false;
  if (k < s.size() && s[k] == '^') {
    def.forward = true;
    ++k;
    if (k < s.size() && s[k] == '|') ++k;
  }
  const std::size_t start = k;
  auto followed_ok = [&](std::size_t at) { return at >= s.size() || is_ws(s[at]); };
  std::size_t end = std::string_view::npos;
  if (s.substr(k, 2) == "${" || s.substr(k, 2) == "$(") {
    const std::size_t close = s.find(s[k + 1] == '{' ? '}' : ')', k + 2);
    if (close != std::string_view::npos && followed_ok(close + 1)) end = close + 1;
  }
  if (end == std::string_view::npos) {
    std::size_t p = k;
    while (p < s.size() && !is_ws(s[p])) {
      if (s[p] == '\'' || s[p] == '"') {
        const std::size_t close = s.find(s[p], p + 1);
        if (close == std::string_view::npos) break;
        p = close + 1;
      } else {
        ++p;
      }
    }
    end = p;
  }
  def.value = std::string(s.substr(start, end - start));
  def.has_default = !def.value.empty();
  std::size_t rest = end;
  while (rest < s.size() && is_ws(s[rest])) ++rest;
  s.remove_prefix(rest);
  has_spec = true;
  return param;
}

}  // namespace mechsim::description::xacro
