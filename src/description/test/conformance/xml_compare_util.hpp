#pragma once
// XML tree comparison with the rules of xacro's own test suite (see
// ../shared/conformance/xacro/README.md, "How to compare"), used by the xacro conformance,
// golden PR2 and robot reference suites.

#include <string>

namespace mechsim::description::test {

struct XmlCompareOptions {
  bool compare_comments = true;
  double abs_tolerance = 1e-9;  // numbers match when |a-b| <= abs_tolerance ...
  double rel_tolerance = 0.0;   // ... or |a-b| <= rel_tolerance * max(|a|, |b|)
};

// Compares two documents from their root elements. Returns "" when they match, otherwise a
// description of the first difference with its element path.
std::string compare_xml(const std::string& actual, const std::string& expected, const XmlCompareOptions& options);

// The text rule alone (exposed for its unit test).
bool text_matches(const std::string& a, const std::string& b, const XmlCompareOptions& options);

}  // namespace mechsim::description::test
