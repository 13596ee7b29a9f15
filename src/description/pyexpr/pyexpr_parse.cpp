// A recursive-descent parser for Python expressions, following the grammar's precedence:
// lambda < if-else < or < and < not < comparisons < | < ^ < & < shifts < + - < * / // % <
// unary < ** < primary (call, subscript, attribute) < atom.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "description/pyexpr/pyexpr_ast.hpp"
#include "description/pyexpr/pyexpr_lex.hpp"

namespace mechsim::description::pyexpr {
namespace {

class Parser {
 public:
  explicit Parser(std::vector<Token> toks) : t_(std::move(toks)) {}

  ExprPtr parse_all() {
    ExprPtr e = testlist();
    if (peek().type != Tok::End) {
      syntax_error("invalid syntax near '" + describe(peek()) + "'");
    }
    if (!invalid_.empty()) {
      std::string names;
      for (const auto& n : invalid_) names += (names.empty() ? "" : ", ") + n;
      throw PyError("NameError", "Use of invalid name(s):  " + names);
    }
    return e;
  }

 private:
  static std::string describe(const Token& t) {
    if (t.type == Tok::End) return "end of expression";
    if (t.type == Tok::Name || t.type == Tok::Op) return t.text;
    return to_repr(t.value);
  }
  const Token& peek(std::size_t k = 0) const { return t_[std::min(i_ + k, t_.size() - 1)]; }
  bool is_op(std::string_view op, std::size_t k = 0) const {
    return peek(k).type == Tok::Op && peek(k).text == op;
  }
  bool is_kw(std::string_view kw, std::size_t k = 0) const {
    return peek(k).type == Tok::Name && peek(k).text == kw;
  }
  bool accept_op(std::string_view op) {
    if (!is_op(op)) return false;
    ++i_;
    return true;
  }
  bool accept_kw(std::string_view kw) {
    if (!is_kw(kw)) return false;
    ++i_;
    return true;
  }
  void expect_op(std::string_view op, std::string_view opener) {
    if (!accept_op(op)) {
      if (peek().type == Tok::End) syntax_error("'" + std::string(opener) + "' was never closed");
      syntax_error("expected '" + std::string(op) + "' but found '" + describe(peek()) + "'");
    }
  }

  // Records the node's height and rejects trees deep enough to exhaust the stack when evaluated
  // or destroyed (left-nested chains such as 1+1+1+... grow one level per operator).
  static ExprPtr seal(ExprPtr e) {
    int h = 0;
    for (const auto& a : e->args) {
      if (a) h = std::max(h, a->height);
    }
    for (const auto& c : e->clauses) {
      if (c.iter) h = std::max(h, c.iter->height);
      for (const auto& cond : c.conditions) h = std::max(h, cond->height);
    }
    e->height = h + 1;
    if (e->height > kMaxDepth) syntax_error("expression nested too deeply");
    return e;
  }

  static ExprPtr make(Expr::Kind k) {
    auto e = std::make_unique<Expr>();
    e->kind = k;
    return e;
  }

  // testlist: test (',' test)* [','] -> a tuple when there is a comma
  ExprPtr testlist() {
    ExprPtr first = test();
    if (!is_op(",")) return first;
    auto tup = make(Expr::Kind::Tuple);
    tup->args.push_back(std::move(first));
    while (accept_op(",")) {
      if (at_expr_end()) break;
      tup->args.push_back(test());
    }
    return seal(std::move(tup));
  }

  bool at_expr_end() const {
    const Token& t = peek();
    return t.type == Tok::End ||
           (t.type == Tok::Op && (t.text == ")" || t.text == "]" || t.text == "}" || t.text == ":"));
  }

  ExprPtr test() {
    if (accept_kw("lambda")) {
      auto lam = make(Expr::Kind::Lambda);
      while (!is_op(":")) {
        if (peek().type != Tok::Name) syntax_error("invalid lambda parameter");
        lam->kwnames.push_back(peek().text);
        ++i_;
        if (!accept_op(",")) break;
      }
      expect_op(":", "lambda");
      lam->args.push_back(test());
      return seal(std::move(lam));
    }
    ExprPtr body = or_test();
    if (is_kw("if")) {
      ++i_;
      ExprPtr cond = or_test();
      if (!accept_kw("else")) syntax_error("expected 'else' after 'if' expression");
      ExprPtr other = test();
      auto e = make(Expr::Kind::IfExp);
      e->args.push_back(std::move(cond));
      e->args.push_back(std::move(body));
      e->args.push_back(std::move(other));
      return seal(std::move(e));
    }
    return body;
  }

  ExprPtr or_test() {
    ExprPtr left = and_test();
    while (accept_kw("or")) {
      auto e = make(Expr::Kind::BoolOp);
      e->op = Op::Or;
      e->args.push_back(std::move(left));
      e->args.push_back(and_test());
      left = seal(std::move(e));
    }
    return left;
  }

  ExprPtr and_test() {
    ExprPtr left = not_test();
    while (accept_kw("and")) {
      auto e = make(Expr::Kind::BoolOp);
      e->op = Op::And;
      e->args.push_back(std::move(left));
      e->args.push_back(not_test());
      left = seal(std::move(e));
    }
    return left;
  }

  ExprPtr not_test() {
    if (accept_kw("not")) {
      auto e = make(Expr::Kind::Unary);
      e->op = Op::Not;
      e->args.push_back(not_test());
      return seal(std::move(e));
    }
    return comparison();
  }

  bool comp_op(Op& op) {
    const Token& t = peek();
    if (t.type == Tok::Op) {
      static const std::pair<std::string_view, Op> ops[] = {
          {"<", Op::Lt}, {"<=", Op::Le}, {">", Op::Gt}, {">=", Op::Ge}, {"==", Op::Eq}, {"!=", Op::Ne}};
      for (const auto& [s, o] : ops) {
        if (t.text == s) {
          op = o;
          ++i_;
          return true;
        }
      }
      return false;
    }
    if (is_kw("in")) {
      op = Op::In;
      ++i_;
      return true;
    }
    if (is_kw("not") && is_kw("in", 1)) {
      op = Op::NotIn;
      i_ += 2;
      return true;
    }
    if (is_kw("is")) {
      ++i_;
      op = accept_kw("not") ? Op::IsNot : Op::Is;
      return true;
    }
    return false;
  }

  ExprPtr comparison() {
    ExprPtr left = bitor_expr();
    Op op;
    if (!comp_op(op)) return left;
    auto e = make(Expr::Kind::Compare);
    e->args.push_back(std::move(left));
    do {
      e->ops.push_back(op);
      e->args.push_back(bitor_expr());
    } while (comp_op(op));
    return seal(std::move(e));
  }

  ExprPtr binary(ExprPtr left, Op op, ExprPtr right) {
    auto e = make(Expr::Kind::Binary);
    e->op = op;
    e->args.push_back(std::move(left));
    e->args.push_back(std::move(right));
    return seal(std::move(e));
  }

  ExprPtr bitor_expr() {
    ExprPtr left = bitxor_expr();
    while (accept_op("|")) left = binary(std::move(left), Op::BitOr, bitxor_expr());
    return left;
  }
  ExprPtr bitxor_expr() {
    ExprPtr left = bitand_expr();
    while (accept_op("^")) left = binary(std::move(left), Op::BitXor, bitand_expr());
    return left;
  }
  ExprPtr bitand_expr() {
    ExprPtr left = shift_expr();
    while (accept_op("&")) left = binary(std::move(left), Op::BitAnd, shift_expr());
    return left;
  }
  ExprPtr shift_expr() {
    ExprPtr left = arith_expr();
    while (true) {
      if (accept_op("<<")) left = binary(std::move(left), Op::LShift, arith_expr());
      else if (accept_op(">>")) left = binary(std::move(left), Op::RShift, arith_expr());
      else return left;
    }
  }
  ExprPtr arith_expr() {
    ExprPtr left = term();
    while (true) {
      if (accept_op("+")) left = binary(std::move(left), Op::Add, term());
      else if (accept_op("-")) left = binary(std::move(left), Op::Sub, term());
      else return left;
    }
  }
  ExprPtr term() {
    ExprPtr left = factor();
    while (true) {
      if (accept_op("*")) left = binary(std::move(left), Op::Mul, factor());
      else if (accept_op("/")) left = binary(std::move(left), Op::Div, factor());
      else if (accept_op("//")) left = binary(std::move(left), Op::FloorDiv, factor());
      else if (accept_op("%")) left = binary(std::move(left), Op::Mod, factor());
      else return left;
    }
  }
  ExprPtr factor() {
    Op op;
    if (accept_op("-")) op = Op::Neg;
    else if (accept_op("+")) op = Op::Pos;
    else if (accept_op("~")) op = Op::Invert;
    else return power();
    if (++depth_ > kMaxDepth) syntax_error("expression nested too deeply");
    auto e = make(Expr::Kind::Unary);
    e->op = op;
    e->args.push_back(factor());
    --depth_;
    return seal(std::move(e));
  }
  ExprPtr power() {
    ExprPtr base = primary();
    if (accept_op("**")) return binary(std::move(base), Op::Pow, factor());
    return base;
  }

  ExprPtr primary() {
    ExprPtr e = atom();
    while (true) {
      if (accept_op(".")) {
        if (peek().type != Tok::Name) syntax_error("invalid syntax after '.'");
        auto a = make(Expr::Kind::Attr);
        a->name = peek().text;
        if (a->name.starts_with("__")) invalid_.push_back(a->name);
        ++i_;
        a->args.push_back(std::move(e));
        e = seal(std::move(a));
      } else if (accept_op("(")) {
        auto c = make(Expr::Kind::Call);
        c->args.push_back(std::move(e));
        while (!is_op(")")) {
          if (peek().type == Tok::Name && is_op("=", 1)) {
            c->kwnames.push_back(peek().text);
            i_ += 2;
            c->args.push_back(test());
          } else {
            if (!c->kwnames.empty()) syntax_error("positional argument follows keyword argument");
            c->args.push_back(test());
          }
          if (!accept_op(",")) break;
        }
        expect_op(")", "(");
        e = seal(std::move(c));
      } else if (accept_op("[")) {
        auto s = make(Expr::Kind::Subscript);
        s->args.push_back(std::move(e));
        s->args.push_back(subscript());
        expect_op("]", "[");
        e = seal(std::move(s));
      } else {
        return e;
      }
    }
  }

  ExprPtr subscript() {
    ExprPtr lower;
    if (!is_op(":")) {
      lower = test();
      if (!is_op(":")) return lower;
    }
    auto s = make(Expr::Kind::Slice);
    ++i_;  // ':'
    ExprPtr upper;
    ExprPtr step;
    if (!is_op("]") && !is_op(":")) upper = test();
    if (accept_op(":")) {
      if (!is_op("]")) step = test();
    }
    s->args.push_back(std::move(lower));
    s->args.push_back(std::move(upper));
    s->args.push_back(std::move(step));
    return seal(std::move(s));
  }

  // [elt for ...] or (elt for ...)
  void comprehension(Expr& comp) {
    while (accept_kw("for")) {
      CompClause clause;
      do {
        if (accept_op("(")) {
          while (peek().type == Tok::Name) {
            clause.targets.push_back(peek().text);
            ++i_;
            if (!accept_op(",")) break;
          }
          expect_op(")", "(");
        } else {
          if (peek().type != Tok::Name) syntax_error("invalid comprehension target");
          clause.targets.push_back(peek().text);
          ++i_;
        }
      } while (accept_op(","));
      if (!accept_kw("in")) syntax_error("expected 'in' in comprehension");
      clause.iter = or_test();
      while (accept_kw("if")) clause.conditions.push_back(or_test());
      comp.clauses.push_back(std::move(clause));
    }
  }

  ExprPtr atom() {
    if (++depth_ > kMaxDepth) syntax_error("expression nested too deeply");
    ExprPtr e = atom_inner();
    --depth_;
    return e;
  }

  ExprPtr atom_inner() {
    const Token& t = peek();
    if (t.type == Tok::Number) {
      auto e = make(Expr::Kind::Const);
      e->value = t.value;
      ++i_;
      return e;
    }
    if (t.type == Tok::String) {
      auto e = make(Expr::Kind::Const);
      std::string s;
      while (peek().type == Tok::String) {  // adjacent literals concatenate
        s += peek().value.as_str();
        ++i_;
      }
      e->value = Value::str(std::move(s));
      return e;
    }
    if (t.type == Tok::Name) {
      static constexpr std::string_view keywords[] = {"and", "or", "not", "if", "else", "for", "in",
                                                      "is", "lambda", "import", "def", "class",
                                                      "return", "while", "yield", "del", "pass"};
      for (auto kw : keywords) {
        if (t.text == kw) syntax_error("invalid syntax near '" + t.text + "'");
      }
      auto e = make(Expr::Kind::Const);
      if (t.text == "True") e->value = Value::boolean(true);
      else if (t.text == "False") e->value = Value::boolean(false);
      else if (t.text == "None") e->value = Value::none();
      else {
        e->kind = Expr::Kind::Name;
        e->name = t.text;
        if (e->name.starts_with("__")) invalid_.push_back(e->name);
      }
      ++i_;
      return e;
    }
    if (accept_op("(")) {
      if (accept_op(")")) return make(Expr::Kind::Tuple);
      ExprPtr first = test();
      if (is_kw("for")) {
        auto comp = make(Expr::Kind::ListComp);
        comp->args.push_back(std::move(first));
        comprehension(*comp);
        expect_op(")", "(");
        return seal(std::move(comp));
      }
      if (accept_op(")")) return first;
      auto tup = make(Expr::Kind::Tuple);
      tup->args.push_back(std::move(first));
      while (accept_op(",")) {
        if (is_op(")")) break;
        tup->args.push_back(test());
      }
      expect_op(")", "(");
      return seal(std::move(tup));
    }
    if (accept_op("[")) {
      auto list = make(Expr::Kind::List);
      if (accept_op("]")) return list;
      ExprPtr first = test();
      if (is_kw("for")) {
        list->kind = Expr::Kind::ListComp;
        list->args.push_back(std::move(first));
        comprehension(*list);
        expect_op("]", "[");
        return seal(std::move(list));
      }
      list->args.push_back(std::move(first));
      while (accept_op(",")) {
        if (is_op("]")) break;
        list->args.push_back(test());
      }
      expect_op("]", "[");
      return seal(std::move(list));
    }
    if (accept_op("{")) {
      auto dict = make(Expr::Kind::Dict);
      while (!is_op("}")) {
        if (peek().type == Tok::End) syntax_error("'{' was never closed");
        dict->args.push_back(test());
        expect_op(":", "{");
        dict->args.push_back(test());
        if (!accept_op(",")) break;
      }
      expect_op("}", "{");
      return seal(std::move(dict));
    }
    if (t.type == Tok::End) syntax_error("unexpected end of expression");
    syntax_error("invalid syntax near '" + describe(t) + "'");
  }

  static constexpr int kMaxDepth = 200;
  std::vector<Token> t_;
  std::size_t i_ = 0;
  int depth_ = 0;
  std::vector<std::string> invalid_;
};

}  // namespace

ExprPtr parse_expression(std::string_view source) {
  Parser parser(tokenize(source));
  return parser.parse_all();
}

}  // namespace mechsim::description::pyexpr
