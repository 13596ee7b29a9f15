// xacro's in-order document processing (eval_all): properties, macros, blocks, includes,
// conditionals, xacro:element/attribute, and comment handling, editing the tree in place.
// GCC 12 reports a false -Wrestrict on `"literal" + std::string&&` at -O3 (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wrestrict"
#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "description/xacro/xacro_context.hpp"

namespace mechsim::description::xacro {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxMacroDepth = 200;  // nested macro calls (endless recursion guard)
constexpr std::size_t kMaxIncludeDepth = 100;  // nested includes (a file including itself)
// Elements, macro bodies and included documents nested in one another, counted together: each
// level is a recursion of eval_all, and 8 MiB of stack held ~5,000 of them in a release build
// (fewer with sanitizers). Each of the limits above and the parser's element depth alone stays
// under it, but they multiply (200 macros of 250-deep bodies overflowed the stack).
constexpr int kMaxNesting = 1000;

using SymbolsPtr = std::shared_ptr<Symbols>;
using MacrosPtr = std::shared_ptr<MacroTable>;

class Processor {
 public:
  explicit Processor(Context& ctx) : ctx_(ctx) {
    barrier_ = ctx_.arena.create(Node::Kind::Text);
    barrier_->data = "\n\n";
  }

  void eval_all(Node* node, const MacrosPtr& macros, const SymbolsPtr& symbols) {
    if (ctx_.nesting >= kMaxNesting) {
      fail("elements, macro calls and includes nested more than " + std::to_string(kMaxNesting) +
           " levels deep in all");
    }
    ++ctx_.nesting;
    struct Unnest {
      int& nesting;
      ~Unnest() { --nesting; }
    } unnest{ctx_.nesting};
    for (std::size_t i = 0; i < node->attrs.size();) {
      auto& [name, value] = node->attrs[i];
      if (name.starts_with("xacro:")) {
        node->attrs.erase(node->attrs.begin() + static_cast<std::ptrdiff_t>(i));
        continue;
      }
      if (value.find('$') != std::string::npos) value = ctx_.eval_text_str(value, *symbols);
      ++i;
    }
    node->remove_attr("xmlns:xacro");
    eval_children(node, macros, symbols);
  }

  void eval_children(Node* parent, const MacrosPtr& macros, const SymbolsPtr& symbols) {
    bool eval_comments = false;
    Node* n = parent->first;
    while (n != nullptr) {
      Node* next = n->next;
      try {
        if (n->is_element()) {
          eval_comments = false;
          if (eval_element(n, macros, symbols)) continue;  // re-process n (xacro:element)
        } else if (n->kind == Node::Kind::Text) {
          if (n->data.find('$') != std::string::npos) n->data = ctx_.eval_text_str(n->data, *symbols);
          if (has_non_space(n->data)) eval_comments = false;
        } else if (n->kind == Node::Kind::Comment) {
          const std::string data = trim(n->data);
          if (data == "xacro:eval-comments" || data == "xacro:eval-comments:on") {
            eval_comments = true;
            remove_node(n);
          } else if (data == "xacro:eval-comments:off") {
            eval_comments = false;
            remove_node(n);
          } else if (eval_comments) {
            n->data = ctx_.eval_text_str(n->data, *symbols);
          }
        }
      } catch (Failure& f) {
        if (!f.located) {
          f.located = true;
          f.where = ctx_.location(n->file, n->line);
        }
        throw;
      }
      n = next;
    }
  }

 private:
  // Returns true when the same node must be processed again.
  bool eval_element(Node* n, const MacrosPtr& macros, const SymbolsPtr& symbols) {
    const std::string& tag = n->name;
    if (!tag.starts_with("xacro:")) {
      eval_all(n, macros, symbols);
      return false;
    }
    const std::string_view local = std::string_view(tag).substr(6);
    if (local == "insert_block") {
      insert_block(n, macros, symbols);
    } else if (local == "include") {
      process_include(n, macros, symbols);
    } else if (local == "property") {
      grab_property(n, symbols);
    } else if (local == "macro") {
      grab_macro(n, macros);
    } else if (local == "arg") {
      auto a = check_attrs(ctx_, n, {"name", "default"}, {});
      if (ctx_.args.find(*a.values[0]) == ctx_.args.end()) {
        ctx_.args[*a.values[0]] = ctx_.eval_text_str(*a.values[1], *symbols);
      }
      remove_previous_comments(n);
      remove_node(n);
    } else if (local == "element") {
      const std::string* name_attr = n->attr("xacro:name");
      if (name_attr == nullptr) fail("xacro:element: missing required attribute 'xacro:name'");
      std::string name = ctx_.eval_text_str(*name_attr, *symbols);
      if (name.empty()) fail("xacro:element: empty name");
      n->remove_attr("xacro:name");
      n->name = std::move(name);
      return true;
    } else if (local == "attribute") {
      auto a = check_attrs(ctx_, n, {"name", "value"}, {});
      std::string name = ctx_.eval_text_str(*a.values[0], *symbols);
      std::string value = ctx_.eval_text_str(*a.values[1], *symbols);
      if (name.empty()) fail("xacro:attribute: empty name");
      n->parent->set_attr(name, std::move(value));
      remove_node(n);
    } else if (local == "if" || local == "unless") {
      remove_previous_comments(n);
      auto a = check_attrs(ctx_, n, {"value"}, {});
      const std::string cond = *a.values[0];
      bool keep = boolean_value(ctx_.eval_text(cond, *symbols), cond);
      if (local == "unless") keep = !keep;
      if (keep) {
        eval_children(n, macros, symbols);
        Node* parent = n->parent;
        while (n->first != nullptr) insert_before(parent, n->first, n);
      }
      remove_node(n);
    } else {
      handle_macro_call(n, macros, symbols);
    }
    return false;
  }

  void remove_previous_comments(Node* node) {
    Node* next = node->next;
    Node* prev = node->prev;
    while (prev != nullptr) {
      if (prev->kind == Node::Kind::Text && is_space_text(prev->data) &&
          std::count(prev->data.begin(), prev->data.end(), '\n') <= 1) {
        prev = prev->prev;
      }
      if (prev != nullptr && prev->kind == Node::Kind::Comment) {
        Node* comment = prev;
        prev = prev->prev;
        remove_node(comment);
      } else {
        // A blank-line marker stops later calls from removing comments before this point.
        if (next != nullptr && next != barrier_) insert_before(node->parent, barrier_, next);
        return;
      }
    }
  }

  void insert_block(Node* n, const MacrosPtr& macros, const SymbolsPtr& symbols) {
    auto a = check_attrs(ctx_, n, {"name"}, {});
    const std::string& name = *a.values[0];
    bool content_only = true;
    Node* block = symbols->find_block("**" + name);
    if (block == nullptr) {
      block = symbols->find_block("*" + name);
      content_only = false;
    }
    if (block == nullptr) fail("Undefined block \"" + name + "\"");
    Node* copy = ctx_.arena.clone(block);
    eval_all(copy, macros, symbols);
    Node* parent = n->parent;
    if (content_only) {
      while (copy->first != nullptr) insert_before(parent, copy->first, n);
    } else {
      insert_before(parent, copy, n);
    }
    remove_node(n);
  }

  void grab_property(Node* n, const SymbolsPtr& symbols) {
    remove_previous_comments(n);
    auto a = check_attrs(ctx_, n, {"name"}, {"value", "default", "remove", "scope", "lazy_eval"});
    const std::string name = ctx_.eval_text_str(*a.values[0], *symbols);
    const std::string* value = a.values[1];
    const std::string* def = a.values[2];
    const std::string* remove_attr = a.values[3];
    const std::string* scope = a.values[4];
    const std::string* lazy_attr = a.values[5];
    if (!is_identifier(name)) fail("Property names must be valid python identifiers: " + name);
    if (name.starts_with("__")) fail("Property names must not start with double underscore:" + name);
    const bool remove = boolean_value(ctx_.eval_text(remove_attr ? *remove_attr : "false", *symbols),
                                      remove_attr ? *remove_attr : "None");
    if ((value != nullptr) + (def != nullptr) + (remove ? 1 : 0) > 1) {
      fail("Property attributes default, value, and remove are mutually exclusive: " + name);
    }
    if (remove && symbols->contains_key(name)) {
      symbols->remove(name);
      remove_node(n);
      return;
    }
    if (def != nullptr) {
      if (scope != nullptr) ctx_.warn() << name << ": default property value can only be defined on local scope\n";
      if (symbols->contains_key(name)) {
        remove_node(n);
        return;
      }
      value = def;
    }
    remove_node(n);
    bool lazy = boolean_value(ctx_.eval_text(lazy_attr ? *lazy_attr : "true", *symbols),
                              lazy_attr ? *lazy_attr : "None");
    Symbols* target = symbols.get();
    if (scope != nullptr && *scope == "global") {
      target = symbols->top();
      lazy = false;
    } else if (scope != nullptr && *scope == "parent") {
      if (symbols->parent() == nullptr) {
        ctx_.warn() << name << ": no parent scope at global scope \n";
        return;
      }
      target = symbols->parent();
      // From a macro scope, the parent is the caller's scope, not a namespace holding the macro.
      if (!symbols->is_namespace()) {
        while (target->is_namespace() && target->parent() != nullptr) target = target->parent();
      }
      lazy = false;
    }
    if (value == nullptr) {
      target->set_block("**" + name, n);
      return;
    }
    Value v = lazy ? Value::str(*value) : ctx_.eval_text(*value, *symbols);
    target->set(name, std::move(v), lazy);
  }

  void grab_macro(Node* n, const MacrosPtr& macros) {
    remove_previous_comments(n);
    auto a = check_attrs(ctx_, n, {"name"}, {"params"});
    std::string name = *a.values[0];
    if (name == "call") fail("Invalid use of macro name 'call'");
    if (name.find('.') != std::string::npos) {
      fail("macro names must not contain '.' (reserved for namespaces): " + name);
    }
    if (name.starts_with("xacro:")) {
      ctx_.warn() << "macro names must not contain prefix 'xacro:': " << name << "\n";
      name = name.substr(6);
    }
    auto m = std::make_shared<Macro>();
    m->name = name;
    m->file = n->file;
    m->line = n->line;
    if (a.values[1] != nullptr) {
      std::string_view params = *a.values[1];
      while (!trim(params).empty()) {
        Macro::Default def;
        bool has_spec = false;
        std::string param = parse_macro_arg(params, def, has_spec);
        if (param.empty()) break;
        m->params.push_back(param);
        if (has_spec) m->defaults[param] = def;
      }
    }
    remove_node(n);
    m->body = n;
    macros->set(name, std::move(m));
  }

  void handle_macro_call(Node* n, const MacrosPtr& caller_macros, const SymbolsPtr& caller_symbols) {
    if (n->name == "xacro:call") {
      const std::string* spec = n->attr("macro");
      if (spec == nullptr || spec->empty()) fail("xacro:call is missing the 'macro' attribute");
      std::string name = ctx_.eval_text_str(*spec, *caller_symbols);
      n->remove_attr("macro");
      n->name = "xacro:" + name;
    }
    const std::string name = n->name.substr(6);
    MacrosPtr macros = caller_macros;
    SymbolsPtr symbols = caller_symbols;
    std::shared_ptr<Macro> m = macros->find(name);
    if (m == nullptr && name.find('.') != std::string::npos) {
      // ns1.ns2.macro: walk the include namespaces (macros and properties alike)
      std::string_view rest = name;
      while (macros != nullptr) {
        const std::size_t dot = rest.find('.');
        if (dot == std::string_view::npos) {
          m = macros->find(std::string(rest));
          break;
        }
        const std::string ns(rest.substr(0, dot));
        macros = macros->find_namespace(ns);
        Value v;
        if (symbols != nullptr && symbols->find(ns, v) && v.is_object()) {
          symbols = std::dynamic_pointer_cast<Symbols>(v.as_object());
        } else {
          symbols = nullptr;
        }
        rest.remove_prefix(dot + 1);
      }
      if (symbols == nullptr) m = nullptr;
    }
    if (m == nullptr) fail("unknown macro name: " + n->name);
    if (ctx_.macro_stack.size() >= kMaxMacroDepth) {
      fail("macro '" + m->name + "' nested more than " + std::to_string(kMaxMacroDepth) +
           " levels deep (endless recursion?)");
    }
    ctx_.macro_stack.push_back({m.get(), n->file, n->line});
    try {
      expand_macro(n, *m, macros, symbols);
    } catch (Failure& f) {
      if (!f.located) {
        f.located = true;
        f.where = ctx_.location(n->file, n->line);
      }
      f.trace.push_back("in macro '" + m->name + "' (defined at " + ctx_.location(m->file, m->line) +
                        ") called from " + ctx_.location(n->file, n->line));
      ctx_.macro_stack.pop_back();
      throw;
    }
    ctx_.macro_stack.pop_back();
  }

  void expand_macro(Node* n, const Macro& m, const MacrosPtr& macros, const SymbolsPtr& symbols) {
    Node* body = ctx_.arena.clone(m.body);
    auto scoped_symbols = ctx_.new_scope(symbols.get(), false);
    auto scoped_macros = ctx_.new_macro_table(macros.get());
    std::vector<std::string> params = m.params;
    for (auto& [name, value] : n->attrs) {
      auto it = std::find(params.begin(), params.end(), name);
      if (it == params.end()) fail("Invalid parameter \"" + name + "\"");
      params.erase(it);
      scoped_symbols->set(name, ctx_.eval_text(value, *symbols), false);
    }
    n->attrs.clear();
    eval_children(n, macros, symbols);
    Node* block = n->first_element();
    for (auto it = params.begin(); it != params.end();) {
      if ((*it)[0] != '*') {
        ++it;
        continue;
      }
      if (block == nullptr) fail("Not enough blocks");
      scoped_symbols->set_block(*it, block);
      block = block->next_element();
      it = params.erase(it);
    }
    if (block != nullptr) fail("Unused block \"" + block->name + "\"");
    for (auto it = params.begin(); it != params.end();) {
      auto d = m.defaults.find(*it);
      if (d == m.defaults.end() || (!d->second.forward && !d->second.has_default)) {
        ++it;
        continue;
      }
      Value v;
      bool found = false;
      if (d->second.forward) {
        ExprScope scope(ctx_, *symbols);
        found = scope.lookup(*it, v);
        if (!found && !d->second.has_default) fail("Undefined property to forward: " + *it);
      }
      if (!found) v = ctx_.eval_text(d->second.value, *symbols);
      scoped_symbols->set(*it, std::move(v), false);
      it = params.erase(it);
    }
    if (!params.empty()) {
      std::string list;
      for (const auto& p : params) list += (list.empty() ? "" : ",") + p;
      fail("Undefined parameters [" + list + "]");
    }
    eval_children(body, scoped_macros, scoped_symbols);
    remove_previous_comments(n);
    import_xml_namespaces(n->parent, body);
    Node* parent = n->parent;
    while (body->first != nullptr) insert_before(parent, body->first, n);
    remove_node(n);
  }

  void import_xml_namespaces(Node* parent, const Node* from) {
    for (const auto& [k, v] : from->attrs) {
      if (!k.starts_with("xmlns:")) continue;
      const std::string* old = parent->attr(k);
      if (old != nullptr && *old != v) {
        ctx_.warn() << "inconsistent namespace redefinitions for " << k << ":\n old: " << *old << "\n new: " << v
                    << " (" << ctx_.current_file() << ")\n";
      } else {
        parent->set_attr(k, v);
      }
    }
  }

  std::vector<std::string> include_files(const std::string& spec_text) {
    std::string spec = spec_text;
    if (!fs::path(spec).is_absolute()) {
      const std::string dir = fs::path(ctx_.current_file()).parent_path().string();
      if (!dir.empty()) spec = (fs::path(dir) / spec).string();
    }
    if (spec.find_first_of("*[?") == std::string::npos) return {spec};
    std::vector<std::string> out;
    glob_t g{};
    if (::glob(spec.c_str(), 0, nullptr, &g) == 0) {
      for (std::size_t i = 0; i < g.gl_pathc; ++i) out.emplace_back(g.gl_pathv[i]);
    }
    globfree(&g);
    std::sort(out.begin(), out.end());
    if (out.empty()) ctx_.warn() << "Include tag's filename spec \"" << spec << "\" matched no files.\n";
    return out;
  }

  void process_include(Node* n, const MacrosPtr& macros, const SymbolsPtr& symbols) {
    auto a = check_attrs(ctx_, n, {"filename"}, {"ns", "optional"});
    MacrosPtr ns_macros = macros;
    SymbolsPtr ns_symbols = symbols;
    if (a.values[1] != nullptr && !a.values[1]->empty()) {
      const std::string ns = ctx_.eval_text_str(*a.values[1], *symbols);
      ns_macros = ctx_.new_macro_table(macros.get());
      macros->set_namespace(ns, ns_macros);
      ns_symbols = ctx_.new_scope(symbols.get(), true);
      symbols->set(ns, Value::object(ns_symbols), false);
    }
    const bool optional = a.values[2] != nullptr && boolean_value(Value::str(*a.values[2]), *a.values[2]);
    if (n->first_element() != nullptr) {
      ctx_.warn() << "Child elements of a <xacro:include> tag are ignored\n";
    }
    std::vector<Node*> included;
    for (const std::string& file : include_files(ctx_.eval_text_str(*a.values[0], *symbols))) {
      if (ctx_.file_stack.size() >= kMaxIncludeDepth) {
        fail("includes nested more than " + std::to_string(kMaxIncludeDepth) + " files deep (does " + file +
             " include itself?)");
      }
      std::ifstream in(file, std::ios::binary);
      if (!in) {
        if (optional) continue;
        fail("No such file or directory: " + file + " [Errno 2] No such file or directory: '" + file + "'");
      }
      std::stringstream buffer;
      buffer << in.rdbuf();
      const int id = ctx_.add_file(file);
      ctx_.file_stack.push_back(id);
      try {
        Node* doc = nullptr;
        try {
          doc = ctx_.arena.parse(buffer.str(), id);
        } catch (const XmlSyntaxError& e) {
          Failure f(std::string("XML parsing error: ") + e.what(), XacroError::Kind::Parse,
                    ctx_.location(id, e.line()));
          throw f;
        }
        Node* root = doc->first_element();
        eval_all(root, ns_macros, ns_symbols);
        included.push_back(root);
        import_xml_namespaces(n->parent, root);
      } catch (Failure& f) {
        f.trace.push_back("in file " + file + " included from " + ctx_.location(n->file, n->line));
        ctx_.file_stack.pop_back();
        throw;
      }
      ctx_.file_stack.pop_back();
    }
    remove_previous_comments(n);
    Node* parent = n->parent;
    for (Node* root : included) {
      while (root->first != nullptr) insert_before(parent, root->first, n);
    }
    remove_node(n);
  }

  Context& ctx_;
  Node* barrier_;
};

}  // namespace

void process_document(Context& ctx, Node* document) {
  Node* root = document->first_element();
  if (const std::string* ns = root->attr("xacro:targetNamespace")) {
    std::string value = *ns;
    root->remove_attr("xacro:targetNamespace");
    root->set_attr("xmlns", std::move(value));
  }
  Processor p(ctx);
  auto symbols = ctx.new_scope(nullptr, false);
  auto macros = ctx.new_macro_table(nullptr);
  try {
    p.eval_all(root, macros, symbols);
  } catch (Failure& f) {
    if (!f.located) {
      f.located = true;
      f.where = ctx.location(root->file, root->line);
    }
    throw;
  }
}

}  // namespace mechsim::description::xacro
