// The comparison rules themselves: the conformance suites are only as strict as this.
#include <gtest/gtest.h>

#include "xml_compare_util.hpp"

namespace mechsim::description::test {
namespace {

TEST(XmlCompare, TextRules) {
  XmlCompareOptions o;
  EXPECT_TRUE(text_matches("  a   b ", "a b", o));
  EXPECT_FALSE(text_matches("a b", "a c", o));
  EXPECT_TRUE(text_matches("{'a': 1, 'b': 2}", "{'b': 2, 'a': 1}", o));
  EXPECT_FALSE(text_matches("{'a': 1}", "{'a': 2}", o));
  EXPECT_TRUE(text_matches("1.57079632679 0", "1.5707963267948966 0", o));
  EXPECT_FALSE(text_matches("1.5708 0", "1.5707963267948966 0", o));
  EXPECT_FALSE(text_matches("1 2", "1 2 3", o));
  XmlCompareOptions rel;
  rel.abs_tolerance = 0;
  rel.rel_tolerance = 1e-9;
  EXPECT_TRUE(text_matches("1000000.0000001", "1000000", rel));
  EXPECT_FALSE(text_matches("0.0000001", "0.0000002", rel));
}

TEST(XmlCompare, Trees) {
  XmlCompareOptions o;
  EXPECT_EQ(compare_xml("<a x='1' y='2'>\n  <b/>\n</a>", "<?xml version='1.0'?><!-- banner --><a y='2' x='1'><b/></a>", o), "");
  EXPECT_NE(compare_xml("<a><b/></a>", "<a><c/></a>", o), "");
  EXPECT_NE(compare_xml("<a><b/></a>", "<a><b/><b/></a>", o), "");
  EXPECT_NE(compare_xml("<a x='1'/>", "<a x='1' y='2'/>", o), "");
  EXPECT_NE(compare_xml("<a><!-- c --></a>", "<a/>", o), "");
  o.compare_comments = false;
  EXPECT_EQ(compare_xml("<a><!-- c --></a>", "<a/>", o), "");
  EXPECT_NE(compare_xml("<a>text</a>", "<a>other</a>", o), "");
}

}  // namespace
}  // namespace mechsim::description::test
