#pragma once
// The document tree that xacro expansion edits in place: a minimal DOM in the shape of Python's
// xml.dom.minidom (elements, text, CDATA, comments, processing instructions; ordered attributes;
// sibling links), which xacro's algorithms are written against. Unlike tinyxml2 9, whitespace-only
// text nodes are kept, because xacro's comment handling and output layout depend on them.

#include <deque>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mechsim::description::xacro {

struct Node {
  enum class Kind : std::uint8_t { Document, Element, Text, CData, Comment, PI };
  Kind kind = Kind::Element;
  std::string name;  // element tag, PI target
  std::string data;  // text, CDATA, comment or PI content
  std::vector<std::pair<std::string, std::string>> attrs;  // in document order
  Node* parent = nullptr;
  Node* first = nullptr;
  Node* last = nullptr;
  Node* prev = nullptr;
  Node* next = nullptr;
  int line = 0;  // 1-based source line
  int file = 0;  // index into the expansion's file table

  bool is_element() const { return kind == Kind::Element; }
  const std::string* attr(std::string_view key) const;
  void set_attr(std::string_view key, std::string value);
  bool remove_attr(std::string_view key);
  Node* first_element() const;
  Node* next_element() const;
};

// A malformed XML document: `line` is 1-based.
class XmlSyntaxError : public std::runtime_error {
 public:
  XmlSyntaxError(const std::string& message, int line, int column)
      : std::runtime_error(message), line_(line), column_(column) {}
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  int line_;
  int column_;
};

// Owns every node of one expansion; nodes live until the arena is destroyed, so detached nodes
// (macro bodies, blocks) stay valid while referenced.
class NodeArena {
 public:
  Node* create(Node::Kind kind);
  Node* clone(const Node* node);  // deep copy, detached
  // Parses a whole document; returns a Document node. Throws XmlSyntaxError.
  Node* parse(std::string_view text, int file);

 private:
  std::deque<Node> nodes_;
};

void append_child(Node* parent, Node* child);
void insert_before(Node* parent, Node* child, Node* ref);  // ref == nullptr: append
void remove_node(Node* node);                               // detach from its parent

// Writes the document as xacro does (minidom toprettyxml with 2-space indentation, attributes
// sorted, whitespace-only text dropped between elements).
void write_pretty(const Node* document, std::string& out);

}  // namespace mechsim::description::xacro
