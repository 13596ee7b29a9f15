#include "xml_compare_util.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "description/pyexpr/pyexpr_ast.hpp"
#include "description/pyexpr/pyexpr_eval.hpp"

namespace mechsim::description::test {
namespace {

std::vector<std::string> split_ws(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  std::string tok;
  while (in >> tok) out.push_back(tok);
  return out;
}

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

class EmptyScope : public pyexpr::Scope {
 public:
  bool lookup(std::string_view, pyexpr::Value&) override { return false; }
};

bool as_dict(const std::string& s, pyexpr::Value& out) {
  const auto b = s.find_first_not_of(" \t\n\r");
  if (b == std::string::npos || s[b] != '{') return false;
  try {
    EmptyScope scope;
    out = pyexpr::evaluate(*pyexpr::parse_expression(s), scope);
    return out.is_dict();
  } catch (const std::exception&) {
    return false;
  }
}

bool skip(const tinyxml2::XMLNode* n, const XmlCompareOptions& o) {
  if (n->ToDeclaration() != nullptr || n->ToUnknown() != nullptr) return true;  // PIs, DOCTYPE
  if (n->ToComment() != nullptr) return !o.compare_comments;
  if (const auto* t = n->ToText()) {
    const std::string v = t->Value();
    return std::all_of(v.begin(), v.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
  }
  return false;
}

std::vector<const tinyxml2::XMLNode*> children(const tinyxml2::XMLNode* n, const XmlCompareOptions& o) {
  std::vector<const tinyxml2::XMLNode*> out;
  for (const auto* c = n->FirstChild(); c != nullptr; c = c->NextSibling()) {
    if (!skip(c, o)) out.push_back(c);
  }
  return out;
}

std::string kind(const tinyxml2::XMLNode* n) {
  if (n->ToElement() != nullptr) return "element";
  if (n->ToText() != nullptr) return "text";
  if (n->ToComment() != nullptr) return "comment";
  return "other";
}

std::string compare_nodes(const tinyxml2::XMLNode* a, const tinyxml2::XMLNode* b, const std::string& path,
                          const XmlCompareOptions& o) {
  if (kind(a) != kind(b)) return path + ": node kinds differ (" + kind(a) + " vs " + kind(b) + ")";
  if (a->ToText() != nullptr || a->ToComment() != nullptr) {
    if (!text_matches(a->Value(), b->Value(), o)) {
      return path + ": " + kind(a) + " differs: '" + a->Value() + "' vs '" + b->Value() + "'";
    }
    return {};
  }
  const auto* ea = a->ToElement();
  const auto* eb = b->ToElement();
  if (ea == nullptr) return {};
  const std::string here = path + "/" + ea->Name();
  if (std::string(ea->Name()) != eb->Name()) {
    return path + ": element names differ (" + ea->Name() + " vs " + eb->Name() + ")";
  }
  std::vector<std::pair<std::string, std::string>> aa;
  std::vector<std::pair<std::string, std::string>> ab;
  for (const auto* x = ea->FirstAttribute(); x != nullptr; x = x->Next()) aa.emplace_back(x->Name(), x->Value());
  for (const auto* x = eb->FirstAttribute(); x != nullptr; x = x->Next()) ab.emplace_back(x->Name(), x->Value());
  std::sort(aa.begin(), aa.end());
  std::sort(ab.begin(), ab.end());
  if (aa.size() != ab.size()) return here + ": attribute counts differ";
  for (std::size_t i = 0; i < aa.size(); ++i) {
    if (aa[i].first != ab[i].first) return here + ": attribute names differ (" + aa[i].first + " vs " + ab[i].first + ")";
    if (!text_matches(aa[i].second, ab[i].second, o)) {
      return here + "/@" + aa[i].first + ": '" + aa[i].second + "' vs '" + ab[i].second + "'";
    }
  }
  const auto ca = children(a, o);
  const auto cb = children(b, o);
  for (std::size_t i = 0; i < std::min(ca.size(), cb.size()); ++i) {
    std::string d = compare_nodes(ca[i], cb[i], here + "[" + std::to_string(i) + "]", o);
    if (!d.empty()) return d;
  }
  if (ca.size() != cb.size()) {
    return here + ": child counts differ (" + std::to_string(ca.size()) + " vs " + std::to_string(cb.size()) + ")";
  }
  return {};
}

}  // namespace

bool text_matches(const std::string& a, const std::string& b, const XmlCompareOptions& o) {
  const auto ta = split_ws(a);
  const auto tb = split_ws(b);
  if (ta == tb) return true;  // rule 1: equal after collapsing whitespace
  pyexpr::Value da;
  pyexpr::Value db;
  if (as_dict(a, da) && as_dict(b, db) && pyexpr::equals(da, db)) return true;  // rule 2
  if (ta.size() != tb.size()) return false;  // rule 3: token-wise, numbers within tolerance
  for (std::size_t i = 0; i < ta.size(); ++i) {
    if (ta[i] == tb[i]) continue;
    double x = 0;
    double y = 0;
    if (!parse_number(ta[i], x) || !parse_number(tb[i], y)) return false;
    const double diff = std::fabs(x - y);
    if (!(diff <= o.abs_tolerance || diff <= o.rel_tolerance * std::max(std::fabs(x), std::fabs(y)))) return false;
  }
  return true;
}

std::string compare_xml(const std::string& actual, const std::string& expected, const XmlCompareOptions& options) {
  tinyxml2::XMLDocument da;
  tinyxml2::XMLDocument db;
  if (da.Parse(actual.c_str(), actual.size()) != tinyxml2::XML_SUCCESS) {
    return std::string("actual document does not parse: ") + da.ErrorStr();
  }
  if (db.Parse(expected.c_str(), expected.size()) != tinyxml2::XML_SUCCESS) {
    return std::string("expected document does not parse: ") + db.ErrorStr();
  }
  if (da.RootElement() == nullptr || db.RootElement() == nullptr) return "missing root element";
  return compare_nodes(da.RootElement(), db.RootElement(), "", options);
}

}  // namespace mechsim::description::test
