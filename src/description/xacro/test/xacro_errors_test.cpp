// Bad xacro input gives an error naming the problem, the file and line, and the macro/include
// stack; endless recursion is an error, not a hang or a crash.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "xacro_test_util.hpp"

namespace mechsim::description {
namespace {
using ::testing::HasSubstr;
using test::expansion_error;

constexpr const char* kOpen = "<r xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";

TEST(XacroErrors, UnknownMacroNamesFileAndLine) {
  const std::string e = expansion_error(std::string(kOpen) + "<a/>\n<xacro:nope/>\n</r>");
  EXPECT_THAT(e, HasSubstr("unknown macro name: xacro:nope"));
  EXPECT_THAT(e, HasSubstr("at test.xacro:3"));
}

TEST(XacroErrors, MacroStackIsReported) {
  const std::string e = expansion_error(std::string(kOpen) +
                                        "<xacro:macro name=\"inner\">${undefined_name}</xacro:macro>\n"
                                        "<xacro:macro name=\"outer\"><xacro:inner/></xacro:macro>\n"
                                        "<xacro:outer/>\n</r>");
  EXPECT_THAT(e, HasSubstr("name 'undefined_name' is not defined"));
  EXPECT_THAT(e, HasSubstr("when evaluating expression 'undefined_name'"));
  EXPECT_THAT(e, HasSubstr("in macro 'inner' (defined at test.xacro:2) called from test.xacro:3"));
  EXPECT_THAT(e, HasSubstr("in macro 'outer' (defined at test.xacro:3) called from test.xacro:4"));
}

TEST(XacroErrors, IncludeStackIsReported) {
  test::TempDir dir;
  dir.write("inc.xacro", std::string(kOpen) + "<bad v=\"${1/0}\"/>\n</r>");
  const auto main = dir.write("main.xacro", std::string(kOpen) + "\n<xacro:include filename=\"inc.xacro\"/>\n</r>");
  std::string e;
  try {
    std::ostringstream diag;
    XacroOptions options;
    options.diagnostics = &diag;
    expand_xacro_file(main.string(), options);
  } catch (const XacroError& err) {
    e = err.what();
  }
  EXPECT_THAT(e, HasSubstr("division by zero"));
  EXPECT_THAT(e, HasSubstr("inc.xacro:2"));
  EXPECT_THAT(e, HasSubstr("included from " + main.string() + ":3"));
}

TEST(XacroErrors, EndlessMacroRecursionIsAnError) {
  const std::string e = expansion_error(std::string(kOpen) +
                                        "<xacro:macro name=\"loop\" params=\"n\"><l/><xacro:loop n=\"${n+1}\"/></xacro:macro>\n"
                                        "<xacro:loop n=\"0\"/>\n</r>");
  EXPECT_THAT(e, HasSubstr("nested more than"));
  EXPECT_THAT(e, HasSubstr("in macro 'loop'"));
}

TEST(XacroErrors, SelfReferencingPropertyIsAnError) {
  EXPECT_THAT(expansion_error(std::string(kOpen) + "<xacro:property name=\"a\" value=\"${a}\"/>${a}</r>"),
              HasSubstr("circular variable definition: a -> a"));
  EXPECT_THAT(expansion_error(std::string(kOpen) + "<xacro:property name=\"a\" value=\"${b}\"/>"
                                                   "<xacro:property name=\"b\" value=\"${a+1}\"/><x v=\"${a}\"/></r>"),
              HasSubstr("circular variable definition: a -> b -> a"));
}

TEST(XacroErrors, VeryLongPropertyChainIsBounded) {
  std::string d = kOpen;
  for (int i = 0; i < 5000; ++i) {
    d += "<xacro:property name=\"p" + std::to_string(i) + "\" value=\"${p" + std::to_string(i + 1) + "}\"/>";
  }
  d += "<xacro:property name=\"p5000\" value=\"1\"/><x v=\"${p0}\"/></r>";
  EXPECT_THAT(expansion_error(d), HasSubstr("maximum recursion depth exceeded"));
}

TEST(XacroErrors, MalformedXmlIsAParseError) {
  try {
    expand_xacro_string("<r>\n<a>\n</b>\n</r>", "broken.xacro", {});
    FAIL() << "no error";
  } catch (const XacroError& e) {
    EXPECT_EQ(e.kind(), XacroError::Kind::Parse);
    EXPECT_THAT(std::string(e.what()), HasSubstr("mismatched tag"));
    EXPECT_THAT(std::string(e.what()), HasSubstr("broken.xacro:3"));
  }
}

TEST(XacroErrors, CommonMistakes) {
  const std::string o = kOpen;
  EXPECT_THAT(expansion_error(o + "<xacro:include filename=\"does-not-exist.xacro\"/></r>"),
              HasSubstr("No such file or directory: does-not-exist.xacro"));
  EXPECT_THAT(expansion_error(o + "<xacro:macro name=\"m\" params=\"x y:=1\"/><xacro:m/></r>"),
              HasSubstr("Undefined parameters [x]"));
  EXPECT_THAT(expansion_error(o + "<xacro:macro name=\"m\"/><xacro:m bogus=\"1\"/></r>"),
              HasSubstr("Invalid parameter \"bogus\""));
  EXPECT_THAT(expansion_error(o + "<xacro:if value=\"maybe\"/></r>"), HasSubstr("not a boolean expression"));
  EXPECT_THAT(expansion_error(o + "<a v=\"$(arg missing)\"/></r>"), HasSubstr("Undefined substitution argument missing"));
  EXPECT_THAT(expansion_error(o + "<a v=\"$(find no_such_package_xyz)\"/></r>"), HasSubstr("resource not found"));
  EXPECT_THAT(expansion_error(o + "<a v=\"${1 +}\"/></r>"), HasSubstr("when evaluating expression '1 +'"));
  EXPECT_THAT(expansion_error(o + "<xacro:insert_block name=\"nothing\"/></r>"), HasSubstr("Undefined block \"nothing\""));
  EXPECT_THAT(expansion_error(o + "<a>${unterminated</a></r>"), HasSubstr("invalid expression: ${unterminated"));
}

}  // namespace
}  // namespace mechsim::description
