// The tokenizer of the Python expression subset: numbers (int, float, hex/octal/binary,
// underscores), strings (quotes, triple quotes, u/r/b prefixes, escapes), names and operators.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <charconv>
#include <cstdlib>

#include "description/pyexpr/pyexpr_lex.hpp"
#include "description/utf8.hpp"

namespace mechsim::description::pyexpr {
namespace {

bool is_name_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         (static_cast<unsigned char>(c) >= 0x80);
}
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
 public:
  explicit Lexer(std::string_view s) : s_(s) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    int depth = 0;
    while (true) {
      while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' ||
                                  s_[pos_] == '\r' || s_[pos_] == '\f')) {
        ++pos_;
      }
      if (pos_ >= s_.size()) break;
      const char c = s_[pos_];
      if (c == '\\' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '\n') {
        pos_ += 2;
        continue;
      }
      if (is_name_start(c)) {
        // string prefixes: u, r, b, and combinations
        std::size_t p = pos_;
        while (p < s_.size() && (is_name_start(s_[p]) || is_digit(s_[p]))) ++p;
        std::string word(s_.substr(pos_, p - pos_));
        if (p < s_.size() && (s_[p] == '\'' || s_[p] == '"') && word.size() <= 2) {
          bool raw = false;
          bool ok = true;
          for (char w : word) {
            const char lw = static_cast<char>(w | 0x20);
            if (lw == 'r') raw = true;
            else if (lw != 'u' && lw != 'b') ok = false;
          }
          if (ok) {
            pos_ = p;
            out.push_back(string_token(raw));
            continue;
          }
        }
        pos_ = p;
        Token t;
        t.type = Tok::Name;
        t.text = std::move(word);
        out.push_back(std::move(t));
        continue;
      }
      if (is_digit(c) || (c == '.' && pos_ + 1 < s_.size() && is_digit(s_[pos_ + 1]))) {
        out.push_back(number_token());
        continue;
      }
      if (c == '\'' || c == '"') {
        out.push_back(string_token(false));
        continue;
      }
      static constexpr std::string_view three[] = {"**=", "//=", ">>=", "<<="};
      static constexpr std::string_view two[] = {"**", "//", "<<", ">>", "<=", ">=", "==", "!=", "->"};
      Token t;
      t.type = Tok::Op;
      for (auto op : three) {
        if (s_.substr(pos_, 3) == op) t.text = op;
      }
      if (t.text.empty()) {
        for (auto op : two) {
          if (s_.substr(pos_, 2) == op) t.text = op;
        }
      }
      if (t.text.empty()) {
        if (std::string_view("+-*/%&|^~<>()[]{},:.=@;").find(c) == std::string_view::npos) {
          syntax_error(std::string("invalid character '") + c + "'");
        }
        t.text = std::string(1, c);
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') --depth;
      }
      pos_ += t.text.size();
      out.push_back(std::move(t));
    }
    out.push_back(Token{});
    return out;
  }

 private:
  Token number_token() {
    const std::size_t start = pos_;
    std::string digits;
    Token t;
    t.type = Tok::Number;
    if (s_[pos_] == '0' && pos_ + 1 < s_.size() &&
        std::string_view("xXoObB").find(s_[pos_ + 1]) != std::string_view::npos) {
      const char kind = static_cast<char>(s_[pos_ + 1] | 0x20);
      const int base = kind == 'x' ? 16 : kind == 'o' ? 8 : 2;
      pos_ += 2;
      while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) {
        if (s_[pos_] != '_') digits += s_[pos_];
        ++pos_;
      }
      std::int64_t v = 0;
      auto res = std::from_chars(digits.data(), digits.data() + digits.size(), v, base);
      if (res.ec != std::errc() || res.ptr != digits.data() + digits.size() || digits.empty()) {
        syntax_error("invalid number literal '" + std::string(s_.substr(start, pos_ - start)) + "'");
      }
      t.value = Value::integer(v);
      return t;
    }
    bool is_float = false;
    auto take_digits = [&] {
      while (pos_ < s_.size() && (is_digit(s_[pos_]) || s_[pos_] == '_')) {
        if (s_[pos_] != '_') digits += s_[pos_];
        ++pos_;
      }
    };
    take_digits();
    if (pos_ < s_.size() && s_[pos_] == '.') {
      is_float = true;
      digits += '.';
      ++pos_;
      take_digits();
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      std::size_t p = pos_ + 1;
      if (p < s_.size() && (s_[p] == '+' || s_[p] == '-')) ++p;
      if (p < s_.size() && is_digit(s_[p])) {
        is_float = true;
        digits += 'e';
        digits.append(s_.substr(pos_ + 1, p - pos_ - 1));
        pos_ = p;
        take_digits();
      }
    }
    if (pos_ < s_.size() && (s_[pos_] == 'j' || s_[pos_] == 'J')) {
      syntax_error("complex numbers are not supported");
    }
    if (pos_ < s_.size() && is_name_start(s_[pos_])) {
      syntax_error("invalid decimal literal");
    }
    if (is_float) {
      t.value = Value::real(std::strtod(digits.c_str(), nullptr));
    } else {
      std::int64_t v = 0;
      auto res = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (res.ec == std::errc::result_out_of_range) {
        t.value = Value::real(std::strtod(digits.c_str(), nullptr));
      } else {
        t.value = Value::integer(v);
      }
    }
    return t;
  }

  Token string_token(bool raw) {
    const char q = s_[pos_];
    const bool triple = s_.substr(pos_, 3) == std::string(3, q);
    pos_ += triple ? 3 : 1;
    std::string out;
    while (true) {
      if (pos_ >= s_.size()) syntax_error("unterminated string literal");
      const char c = s_[pos_];
      if (c == q) {
        if (!triple) {
          ++pos_;
          break;
        }
        if (s_.substr(pos_, 3) == std::string(3, q)) {
          pos_ += 3;
          break;
        }
      }
      if (c == '\n' && !triple) syntax_error("unterminated string literal");
      if (c == '\\' && pos_ + 1 < s_.size()) {
        const char e = s_[pos_ + 1];
        if (raw) {
          out += c;
          out += e;
          pos_ += 2;
          continue;
        }
        pos_ += 2;
        switch (e) {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'r': out += '\r'; break;
          case '0': out += '\0'; break;
          case 'a': out += '\a'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'v': out += '\v'; break;
          case '\\': out += '\\'; break;
          case '\'': out += '\''; break;
          case '"': out += '"'; break;
          case '\n': break;
          case 'x':
          case 'u':
          case 'U': {
            const std::size_t n = e == 'x' ? 2 : e == 'u' ? 4 : 8;
            if (pos_ + n > s_.size()) syntax_error("truncated \\" + std::string(1, e) + " escape");
            unsigned long cp = 0;
            auto res = std::from_chars(s_.data() + pos_, s_.data() + pos_ + n, cp, 16);
            if (res.ptr != s_.data() + pos_ + n) syntax_error("truncated escape");
            append_utf8(out, cp);
            pos_ += n;
            break;
          }
          default:
            out += '\\';
            out += e;
        }
        continue;
      }
      out += c;
      ++pos_;
    }
    Token t;
    t.type = Tok::String;
    t.value = Value::str(std::move(out));
    return t;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<Token> tokenize(std::string_view source) { return Lexer(source).run(); }

}  // namespace mechsim::description::pyexpr
