// Small tinyxml2 helpers shared by the URDF passes: numbers as URDF writes them, XmlNode copies,
// and the problem list with the element checks.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "description/urdf/urdf_reading.hpp"

namespace mechsim::description::detail {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  // Out of range still means "a number" (it is then reported as not finite or as a huge value).
  if (ec == std::errc::result_out_of_range) {
    return text.front() == '-' ? -HUGE_VAL : HUGE_VAL;
  }
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::vector<double>> parse_numbers(std::string_view text) {
  std::vector<double> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    std::size_t j = i;
    while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
    if (j > i) {
      auto v = parse_number(text.substr(i, j - i));
      if (!v) return std::nullopt;
      out.push_back(*v);
    }
    i = j;
  }
  return out;
}

std::optional<bool> parse_bool(std::string_view text) {
  const std::string t = lower(trim(text));
  if (t == "true" || t == "1") return true;
  if (t == "false" || t == "0") return false;
  return std::nullopt;
}

XmlNode to_xml_node(const tinyxml2::XMLElement& element) {
  XmlNode node;
  node.name = element.Name();
  node.line = element.GetLineNum();
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a != nullptr; a = a->Next())
    node.attributes[a->Name()] = a->Value();
  for (const tinyxml2::XMLNode* c = element.FirstChild(); c != nullptr; c = c->NextSibling()) {
    if (const tinyxml2::XMLText* t = c->ToText()) {
      node.text += t->Value();
    } else if (const tinyxml2::XMLElement* e = c->ToElement()) {
      node.children.push_back(to_xml_node(*e));
    }
  }
  node.text = std::string(trim(node.text));
  return node;
}

void Problems::error(int line, const std::string& message) {
  report_.errors.push_back(location(source_, line) + message);
}

void Problems::warning(int line, const std::string& message) {
  report_.warnings.push_back(location(source_, line) + message);
}

std::optional<std::string> Problems::text_attribute(const tinyxml2::XMLElement& e, const char* attr,
                                                    const std::string& what, bool required) {
  const char* v = e.Attribute(attr);
  if (v == nullptr) {
    if (required)
      error(e.GetLineNum(), what + ": <" + e.Name() + "> has no '" + attr + "' attribute");
    return std::nullopt;
  }
  return std::string(v);
}

std::optional<double> Problems::number_attribute(const tinyxml2::XMLElement& e, const char* attr,
                                                 const std::string& what, bool required) {
  auto text = text_attribute(e, attr, what, required);
  if (!text) return std::nullopt;
  auto v = parse_number(*text);
  const std::string where = what + ": <" + e.Name() + "> attribute '" + attr + "'";
  if (!v) {
    error(e.GetLineNum(), where + " is not a number: \"" + *text + "\"");
    return std::nullopt;
  }
  if (!std::isfinite(*v)) {
    error(e.GetLineNum(), where + " is not finite: \"" + *text + "\"");
    return std::nullopt;
  }
  return v;
}

std::optional<std::vector<double>> Problems::numbers_attribute(const tinyxml2::XMLElement& e,
                                                               const char* attr, std::size_t count,
                                                               const std::string& what,
                                                               bool required) {
  auto text = text_attribute(e, attr, what, required);
  if (!text) return std::nullopt;
  auto v = parse_numbers(*text);
  const std::string where = what + ": <" + e.Name() + "> attribute '" + attr + "'";
  if (!v || v->size() != count) {
    std::ostringstream msg;
    msg << where << " must hold " << count << " numbers, not \"" << *text << "\"";
    error(e.GetLineNum(), msg.str());
    return std::nullopt;
  }
  for (double x : *v) {
    if (!std::isfinite(x)) {
      error(e.GetLineNum(), where + " is not finite: \"" + *text + "\"");
      return std::nullopt;
    }
  }
  return v;
}

std::string value_text(const tinyxml2::XMLElement& e) {
  // Old descriptions (the PR2's) write <mu1 value="0.5"/> where newer ones write <mu1>0.5</mu1>.
  if (const char* v = e.Attribute("value")) return std::string(trim(v));
  const char* t = e.GetText();
  return t != nullptr ? std::string(trim(t)) : std::string();
}

std::optional<double> Problems::number_text(const tinyxml2::XMLElement& e, const std::string& what) {
  const std::string text = value_text(e);
  auto v = parse_number(text);
  const std::string where = what + ": <" + e.Name() + ">";
  if (!v) {
    error(e.GetLineNum(), where + " is not a number: \"" + text + "\"");
    return std::nullopt;
  }
  if (!std::isfinite(*v)) {
    error(e.GetLineNum(), where + " is not finite: \"" + text + "\"");
    return std::nullopt;
  }
  return v;
}

}  // namespace mechsim::description::detail
