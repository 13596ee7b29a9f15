// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include "description/xacro/xacro_dom.hpp"
#include "description/utf8.hpp"

#include <algorithm>
#include <charconv>

namespace mechsim::description::xacro {

const std::string* Node::attr(std::string_view key) const {
  for (const auto& [k, v] : attrs) {
    if (k == key) return &v;
  }
  return nullptr;
}

void Node::set_attr(std::string_view key, std::string value) {
  for (auto& [k, v] : attrs) {
    if (k == key) {
      v = std::move(value);
      return;
    }
  }
  attrs.emplace_back(std::string(key), std::move(value));
}

bool Node::remove_attr(std::string_view key) {
  for (auto it = attrs.begin(); it != attrs.end(); ++it) {
    if (it->first == key) {
      attrs.erase(it);
      return true;
    }
  }
  return false;
}

Node* Node::first_element() const {
  for (Node* c = first; c != nullptr; c = c->next) {
    if (c->is_element()) return c;
  }
  return nullptr;
}

Node* Node::next_element() const {
  for (Node* c = next; c != nullptr; c = c->next) {
    if (c->is_element()) return c;
  }
  return nullptr;
}

Node* NodeArena::create(Node::Kind kind) {
  Node& n = nodes_.emplace_back();
  n.kind = kind;
  return &n;
}

Node* NodeArena::clone(const Node* node) {
  Node* copy = create(node->kind);
  copy->name = node->name;
  copy->data = node->data;
  copy->attrs = node->attrs;
  copy->line = node->line;
  copy->file = node->file;
  // Iterative over siblings, recursive over depth (bounded by the parser's depth limit).
  for (const Node* c = node->first; c != nullptr; c = c->next) append_child(copy, clone(c));
  return copy;
}

void append_child(Node* parent, Node* child) { insert_before(parent, child, nullptr); }

void insert_before(Node* parent, Node* child, Node* ref) {
  if (child->parent != nullptr) remove_node(child);
  child->parent = parent;
  if (ref == nullptr) {
    child->prev = parent->last;
    child->next = nullptr;
    if (parent->last != nullptr) parent->last->next = child;
    else parent->first = child;
    parent->last = child;
    return;
  }
  child->next = ref;
  child->prev = ref->prev;
  if (ref->prev != nullptr) ref->prev->next = child;
  else parent->first = child;
  ref->prev = child;
}

void remove_node(Node* node) {
  Node* parent = node->parent;
  if (parent == nullptr) return;
  if (node->prev != nullptr) node->prev->next = node->next;
  else parent->first = node->next;
  if (node->next != nullptr) node->next->prev = node->prev;
  else parent->last = node->prev;
  node->parent = node->prev = node->next = nullptr;
}

namespace {

constexpr int kMaxDepth = 256;  // element nesting; expansion recurses once per level

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

bool is_name_char(char c) {
  return !is_space(c) && c != '/' && c != '>' && c != '<' && c != '=' && c != '"' && c != '\'' &&
         c != '\0' && c != '&' && c != '!' && c != '?';
}

class XmlReader {
 public:
  XmlReader(NodeArena& arena, std::string_view text, int file) : arena_(arena), file_(file) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    if (text.find('\r') == std::string_view::npos) {
      s_ = text;
    } else {  // XML end-of-line handling: \r\n and lone \r become \n
      normalized_.reserve(text.size());
      for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\r') {
          normalized_ += '\n';
          if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
        } else {
          normalized_ += text[i];
        }
      }
      s_ = normalized_;
    }
  }

  Node* run() {
    Node* doc = arena_.create(Node::Kind::Document);
    doc->file = file_;
    doc->line = 1;
    Node* parent = doc;
    int depth = 0;
    bool root_seen = false;
    while (p_ < s_.size()) {
      if (s_[p_] != '<') {
        const std::size_t start = p_;
        const int line = line_at(start);
        std::string text;
        while (p_ < s_.size() && s_[p_] != '<') {
          if (s_[p_] == '&') {
            read_entity(text);
          } else {
            if (s_[p_] == ']' && s_.substr(p_, 3) == "]]>") fail("not well-formed (invalid token)", p_);
            text += s_[p_++];
          }
        }
        if (parent == doc) {
          if (std::all_of(text.begin(), text.end(), is_space)) continue;
          fail(root_seen ? "junk after document element" : "syntax error", start);
        }
        Node* t = arena_.create(Node::Kind::Text);
        t->data = std::move(text);
        t->line = line;
        t->file = file_;
        append_child(parent, t);
        continue;
      }
      const std::size_t start = p_;
      if (s_.substr(p_, 4) == "<!--") {
        const std::size_t end = s_.find("-->", p_ + 4);
        if (end == std::string_view::npos) fail("unclosed token", start);
        Node* c = arena_.create(Node::Kind::Comment);
        c->data = std::string(s_.substr(p_ + 4, end - p_ - 4));
        c->line = line_at(start);
        c->file = file_;
        append_child(parent, c);
        p_ = end + 3;
        continue;
      }
      if (s_.substr(p_, 9) == "<![CDATA[") {
        if (parent == doc) fail("syntax error", start);
        const std::size_t end = s_.find("]]>", p_ + 9);
        if (end == std::string_view::npos) fail("unclosed CDATA section", start);
        Node* c = arena_.create(Node::Kind::CData);
        c->data = std::string(s_.substr(p_ + 9, end - p_ - 9));
        c->line = line_at(start);
        c->file = file_;
        append_child(parent, c);
        p_ = end + 3;
        continue;
      }
      if (s_.substr(p_, 2) == "<?") {
        const std::size_t end = s_.find("?>", p_ + 2);
        if (end == std::string_view::npos) fail("unclosed token", start);
        std::string_view body = s_.substr(p_ + 2, end - p_ - 2);
        std::size_t name_end = 0;
        while (name_end < body.size() && !is_space(body[name_end])) ++name_end;
        std::string target(body.substr(0, name_end));
        if (target.empty()) fail("not well-formed (invalid token)", start);
        std::string_view rest = body.substr(name_end);
        while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
        p_ = end + 2;
        if (target == "xml" || target == "XML") {
          if (start != 0) fail("XML or text declaration not at start of entity", start);
          continue;  // the XML declaration is not a node
        }
        Node* pi = arena_.create(Node::Kind::PI);
        pi->name = std::move(target);
        pi->data = std::string(rest);
        pi->line = line_at(start);
        pi->file = file_;
        append_child(parent, pi);
        continue;
      }
      if (s_.substr(p_, 2) == "<!") {
        if (parent != doc || root_seen || s_.substr(p_, 9) != "<!DOCTYPE") fail("syntax error", start);
        skip_doctype();
        continue;
      }
      if (s_.substr(p_, 2) == "</") {
        p_ += 2;
        const std::string_view name = read_name();
        skip_space();
        if (p_ >= s_.size() || s_[p_] != '>') fail("not well-formed (invalid token)", p_);
        ++p_;
        if (parent == doc || name != parent->name) fail("mismatched tag", start);
        parent = parent->parent;
        --depth;
        continue;
      }
      // start tag
      if (parent == doc && root_seen) fail("junk after document element", start);
      ++p_;
      Node* e = arena_.create(Node::Kind::Element);
      e->name = std::string(read_name());
      e->line = line_at(start);
      e->file = file_;
      bool self_closing = false;
      while (true) {
        const bool had_space = skip_space();
        if (p_ >= s_.size()) fail("unclosed token", start);
        if (s_[p_] == '>') {
          ++p_;
          break;
        }
        if (s_[p_] == '/') {
          if (p_ + 1 >= s_.size() || s_[p_ + 1] != '>') fail("not well-formed (invalid token)", p_);
          p_ += 2;
          self_closing = true;
          break;
        }
        if (!had_space) fail("not well-formed (invalid token)", p_);
        std::string key(read_name());
        skip_space();
        if (p_ >= s_.size() || s_[p_] != '=') fail("not well-formed (invalid token)", p_);
        ++p_;
        skip_space();
        if (p_ >= s_.size() || (s_[p_] != '"' && s_[p_] != '\'')) fail("not well-formed (invalid token)", p_);
        const char q = s_[p_++];
        std::string value;
        while (true) {
          if (p_ >= s_.size()) fail("unclosed token", start);
          const char c = s_[p_];
          if (c == q) {
            ++p_;
            break;
          }
          if (c == '<') fail("not well-formed (invalid token)", p_);
          if (c == '&') {
            read_entity(value);
            continue;
          }
          value += (c == '\n' || c == '\t') ? ' ' : c;  // attribute-value normalization
          ++p_;
        }
        if (e->attr(key) != nullptr) fail("duplicate attribute", start);
        e->attrs.emplace_back(std::move(key), std::move(value));
      }
      append_child(parent, e);
      if (parent == doc) root_seen = true;
      if (!self_closing) {
        if (++depth > kMaxDepth) fail("document nested too deeply", start);
        parent = e;
      }
    }
    if (parent != doc) fail(root_seen ? "no element found" : "no element found", s_.size());
    if (!root_seen) fail("no element found", s_.size());
    return doc;
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::size_t pos) {
    const int line = line_at(pos);
    const std::size_t line_start = s_.rfind('\n', pos == 0 ? 0 : pos - 1);
    const std::size_t col = (line_start == std::string_view::npos || pos == 0) ? pos : pos - line_start - 1;
    throw XmlSyntaxError(what + ": line " + std::to_string(line) + ", column " + std::to_string(col), line,
                         static_cast<int>(col));
  }

  int line_at(std::size_t pos) {
    if (pos < counted_pos_) {  // only on error paths
      return 1 + static_cast<int>(std::count(s_.begin(), s_.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    }
    counted_line_ += static_cast<int>(std::count(s_.begin() + static_cast<std::ptrdiff_t>(counted_pos_),
                                                 s_.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    counted_pos_ = pos;
    return counted_line_;
  }

  bool skip_space() {
    const std::size_t start = p_;
    while (p_ < s_.size() && is_space(s_[p_])) ++p_;
    return p_ != start;
  }

  std::string_view read_name() {
    const std::size_t start = p_;
    while (p_ < s_.size() && is_name_char(s_[p_])) ++p_;
    if (p_ == start) fail("not well-formed (invalid token)", p_);
    return s_.substr(start, p_ - start);
  }

  void read_entity(std::string& out) {
    const std::size_t start = p_;
    const std::size_t semi = s_.find(';', p_);
    if (semi == std::string_view::npos || semi - p_ > 12) fail("not well-formed (invalid token)", start);
    const std::string_view name = s_.substr(p_ + 1, semi - p_ - 1);
    p_ = semi + 1;
    if (name == "lt") out += '<';
    else if (name == "gt") out += '>';
    else if (name == "amp") out += '&';
    else if (name == "quot") out += '"';
    else if (name == "apos") out += '\'';
    else if (name.starts_with('#')) {
      unsigned long cp = 0;
      const bool hex = name.size() > 1 && (name[1] == 'x' || name[1] == 'X');
      const char* b = name.data() + (hex ? 2 : 1);
      const char* e = name.data() + name.size();
      auto res = std::from_chars(b, e, cp, hex ? 16 : 10);
      if (res.ptr != e || b == e || cp == 0 || cp > 0x10FFFF) fail("reference to invalid character number", start);
      append_utf8(out, cp);
    } else {
      fail("undefined entity", start);
    }
  }

  void skip_doctype() {
    int bracket = 0;
    while (p_ < s_.size()) {
      const char c = s_[p_++];
      if (c == '[') ++bracket;
      else if (c == ']') --bracket;
      else if (c == '>' && bracket <= 0) return;
    }
    fail("unclosed token", p_);
  }

  NodeArena& arena_;
  int file_;
  std::string normalized_;
  std::string_view s_;
  std::size_t p_ = 0;
  std::size_t counted_pos_ = 0;
  int counted_line_ = 1;
};

void write_escaped(std::string& out, std::string_view s) {
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const char* rep = c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : nullptr;
    if (rep == nullptr) continue;
    out.append(s.data() + run, i - run);
    out += rep;
    run = i + 1;
  }
  out.append(s.data() + run, s.size() - run);
}

bool all_space(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return is_space(c) || c == '\f' || c == '\v'; });
}

void write_node(const Node* n, std::string& out, int depth) {
  const auto indent = [&](int d) { out.append(static_cast<std::size_t>(2 * d), ' '); };
  switch (n->kind) {
    case Node::Kind::Text:
      indent(depth);
      write_escaped(out, n->data);
      out += '\n';
      return;
    case Node::Kind::CData:
      out += "<![CDATA[";
      out += n->data;
      out += "]]>";
      return;
    case Node::Kind::Comment:
      indent(depth);
      out += "<!--";
      out += n->data;
      out += "-->\n";
      return;
    case Node::Kind::PI:
      indent(depth);
      out += "<?";
      out += n->name;
      out += ' ';
      out += n->data;
      out += "?>\n";
      return;
    case Node::Kind::Document:
      for (const Node* c = n->first; c != nullptr; c = c->next) write_node(c, out, depth);
      return;
    case Node::Kind::Element: break;
  }
  indent(depth);
  out += '<';
  out += n->name;
  std::vector<const std::pair<std::string, std::string>*> attrs;
  attrs.reserve(n->attrs.size());
  for (const auto& a : n->attrs) attrs.push_back(&a);
  std::sort(attrs.begin(), attrs.end(), [](const auto* a, const auto* b) { return a->first < b->first; });
  for (const auto* a : attrs) {
    out += ' ';
    out += a->first;
    out += "=\"";
    write_escaped(out, a->second);
    out += '"';
  }
  if (n->first == nullptr) {
    out += "/>\n";
    return;
  }
  if (n->first == n->last && n->first->kind == Node::Kind::Text) {
    out += '>';
    write_escaped(out, n->first->data);
    out += "</";
    out += n->name;
    out += ">\n";
    return;
  }
  out += ">\n";
  for (const Node* c = n->first; c != nullptr; c = c->next) {
    if (c->kind == Node::Kind::Text && all_space(c->data)) continue;
    write_node(c, out, depth + 1);
  }
  indent(depth);
  out += "</";
  out += n->name;
  out += ">\n";
}

}  // namespace

Node* NodeArena::parse(std::string_view text, int file) {
  XmlReader reader(*this, text, file);
  return reader.run();
}

void write_pretty(const Node* document, std::string& out) {
  out += "<?xml version=\"1.0\" ?>\n";
  write_node(document, out, 0);
}

}  // namespace mechsim::description::xacro
