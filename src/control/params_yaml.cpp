// Reading Params from YAML with yaml-cpp.

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>
#include <string_view>

#include "control/params.hpp"
#include "control/params_node.hpp"
#include "control/params_yaml.hpp"
#include "description/utf8.hpp"

namespace mechsim::control {
namespace {

std::string where(const std::string& source, const YAML::Mark& mark) {
  return source + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

void require_utf8(const std::string& text, const YAML::Mark& mark, const std::string& source, const std::string& path,
                  const char* what) {
  const std::size_t at = description::invalid_utf8_at(text);
  if (at == std::string_view::npos) return;
  throw ParamsError(where(source, mark) + ": parameter " + path + ": the " + what + " is not UTF-8 text (" +
                        description::utf8_byte_name(text, at) + " at offset " + std::to_string(at) +
                        "); save the file as UTF-8",
                    path);
}

// Deeper than any parameter file: a YAML alias inside the node it names (`a: &x {c: *x}`) makes
// yaml-cpp's node graph a cycle, which only a bound stops.
constexpr int kMaxDepth = 128;

std::unique_ptr<Params::Node> convert(const YAML::Node& in, const std::string& source, const std::string& path,
                                      int depth = 0) {
  if (depth > kMaxDepth) {
    throw ParamsError(where(source, in.Mark()) + ": parameter " + path.substr(0, 200) + (path.size() > 200 ? "..." : "") +
                          ": nested more than " + std::to_string(kMaxDepth) +
                          " levels deep (a YAML alias inside the node its anchor names?)",
                      path.substr(0, 200));
  }
  auto out = std::make_unique<Params::Node>();
  out->line = in.Mark().line + 1;
  switch (in.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      out->kind = Params::Kind::Null;
      break;
    case YAML::NodeType::Scalar:
      out->kind = Params::Kind::Scalar;
      out->text = in.Scalar();
      require_utf8(out->text, in.Mark(), source, path, "value");
      // yaml-cpp tags plain scalars "?" and quoted ones "!".
      out->scalar = in.Tag() == "!" ? ScalarType::Quoted : ScalarType::Plain;
      break;
    case YAML::NodeType::Sequence: {
      out->kind = Params::Kind::List;
      std::size_t i = 0;
      for (const YAML::Node& item : in) {
        out->list.push_back(convert(item, source, path + "[" + std::to_string(i++) + "]", depth + 1));
      }
      break;
    }
    case YAML::NodeType::Map:
      out->kind = Params::Kind::Map;
      for (const auto& entry : in) {
        if (!entry.first.IsScalar()) {
          throw ParamsError(where(source, entry.first.Mark()) + ": parameter " + path +
                                ": map keys must be plain names",
                            path);
        }
        const std::string key = entry.first.Scalar();
        require_utf8(key, entry.first.Mark(), source, path, "key");
        const std::string child_path = join_param_path(path, key);
        if (key.empty() || key.find('/') != std::string::npos) {
          throw ParamsError(where(source, entry.first.Mark()) + ": parameter " + child_path +
                                ": a key must be non-empty and contain no '/'",
                            child_path);
        }
        for (const auto& existing : out->map) {
          if (existing.first == key) {
            throw ParamsError(where(source, entry.first.Mark()) + ": parameter " + child_path +
                                  ": duplicate key (first at line " + std::to_string(existing.second->line) + ")",
                              child_path);
          }
        }
        out->map.emplace_back(key, convert(entry.second, source, child_path, depth + 1));
      }
      break;
  }
  return out;
}

Params load(const std::string& text, const std::string& source) {
  YAML::Node doc;
  try {
    doc = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ParamsError(where(source, e.mark) + ": malformed YAML: " + e.msg, "/");
  }
  auto tree = std::make_shared<Params::Tree>();
  tree->source = source;
  if (doc.IsNull() || !doc.IsDefined()) {
    tree->root = std::make_unique<Params::Node>();
    tree->root->kind = Params::Kind::Map;  // an empty document is an empty parameter tree
  } else if (!doc.IsMap()) {
    throw ParamsError(where(source, doc.Mark()) + ": the top level of a parameter file must be a map", "/");
  } else {
    tree->root = convert(doc, source, "/");
  }
  return ParamsAccess::make(std::move(tree));
}

}  // namespace

std::string yaml_where(const std::string& source, const YAML::Mark& mark) { return where(source, mark); }

YAML::Node load_yaml_string(const std::string& yaml, const std::string& source_name) {
  try {
    return YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw ParamsError(where(source_name, e.mark) + ": malformed YAML: " + e.msg, "/");
  }
}

YAML::Node load_yaml_file(const std::string& file_path) {
  std::ifstream in(file_path, std::ios::binary);
  if (!in) throw ParamsError(file_path + ": cannot open the parameter file", "/");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ParamsError(file_path + ": error while reading the parameter file", "/");
  return load_yaml_string(text.str(), file_path);
}

Params params_from_yaml_map(const YAML::Node& node, const std::string& source) {
  auto tree = std::make_shared<Params::Tree>();
  tree->source = source;
  tree->root = convert(node, source, "/");
  return ParamsAccess::make(std::move(tree));
}

Params Params::from_yaml_string(std::string_view yaml, const std::string& source_name) {
  return load(std::string(yaml), source_name);
}

Params Params::from_yaml_file(const std::string& file_path) {
  std::ifstream in(file_path, std::ios::binary);
  if (!in) throw ParamsError(file_path + ": cannot open the parameter file", "/");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ParamsError(file_path + ": error while reading the parameter file", "/");
  return load(text.str(), file_path);
}

}  // namespace mechsim::control
