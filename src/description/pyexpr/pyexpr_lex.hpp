#pragma once
// Tokens of the Python expression subset (names, numbers, strings, operators).

#include <string>
#include <string_view>
#include <vector>

#include "description/pyexpr/pyexpr_value.hpp"

namespace mechsim::description::pyexpr {

enum class Tok : std::uint8_t { Name, Number, String, Op, End };

struct Token {
  Tok type = Tok::End;
  std::string text;  // name or operator
  Value value;       // number or string literal
};

[[noreturn]] inline void syntax_error(const std::string& what) { throw PyError("SyntaxError", what); }

// Splits an expression into tokens, ending with Tok::End; throws PyError("SyntaxError") on bad
// literals or characters.
std::vector<Token> tokenize(std::string_view source);

}  // namespace mechsim::description::pyexpr
