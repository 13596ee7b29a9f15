#include "control/params_xml.hpp"

#include <memory>

#include "control/params_node.hpp"

namespace mechsim::control {
namespace {

std::unique_ptr<Params::Node> convert(const description::XmlNode& element) {
  auto out = std::make_unique<Params::Node>();
  out->line = element.line;
  if (element.children.empty()) {
    out->kind = Params::Kind::Scalar;
    out->scalar = ScalarType::Plain;
    out->text = element.text;
    return out;
  }
  out->kind = Params::Kind::Map;
  for (const description::XmlNode& child : element.children) {
    if (child.name.empty() || child.name.find('/') != std::string::npos) continue;
    bool seen = false;
    for (const auto& existing : out->map) seen = seen || existing.first == child.name;
    if (!seen) out->map.emplace_back(child.name, convert(child));
  }
  return out;
}

}  // namespace

Params params_from_xml(const description::XmlNode& element, const std::string& source, const std::string& root_name) {
  auto tree = std::make_shared<Params::Tree>();
  tree->source = source;
  tree->root = std::make_unique<Params::Node>();
  tree->root->kind = Params::Kind::Map;
  std::unique_ptr<Params::Node> node = convert(element);
  if (node->kind != Params::Kind::Map) {  // <plugin/> with no parameters: an empty map
    node->kind = Params::Kind::Map;
    node->text.clear();
  }
  tree->root->map.emplace_back(root_name, std::move(node));
  return ParamsAccess::make(std::move(tree)).child(root_name);
}

}  // namespace mechsim::control
