// Recursion in a description is bounded with a located error whatever its path (includes, macros,
// nested elements, properties, expressions), and the error stays readable: an endless recursion
// unwinds through hundreds of frames and a pathological expression can be megabytes long.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "xacro_test_util.hpp"

namespace mechsim::description {
namespace {
using ::testing::HasSubstr;
using ::testing::Not;
using test::expansion_error;

constexpr const char* kOpen = "<r xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";

std::string expand_file_error(const std::string& path) {
  std::ostringstream diag;
  XacroOptions options;
  options.diagnostics = &diag;
  try {
    expand_xacro_file(path, options);
  } catch (const XacroError& e) {
    return e.what();
  }
  return "";
}

TEST(XacroRecursion, FileIncludingItselfIsAnError) {
  test::TempDir dir;
  const auto self = dir.write("self.xacro", std::string(kOpen) + "<xacro:include filename=\"self.xacro\"/>\n</r>");
  const std::string e = expand_file_error(self.string());
  EXPECT_THAT(e, HasSubstr("includes nested more than 100 files deep (does " + self.parent_path().string()));
  EXPECT_THAT(e, HasSubstr("included from " + self.string() + ":2"));
  EXPECT_THAT(e, HasSubstr("more frames"));  // 100 include frames, shown by their two ends
  EXPECT_LT(e.size(), 4000u) << e;
}

TEST(XacroRecursion, TwoFilesIncludingEachOtherIsAnError) {
  test::TempDir dir;
  dir.write("b.xacro", std::string(kOpen) + "<xacro:include filename=\"a.xacro\"/>\n</r>");
  const auto a = dir.write("a.xacro", std::string(kOpen) + "<xacro:include filename=\"b.xacro\"/>\n</r>");
  const std::string e = expand_file_error(a.string());
  EXPECT_THAT(e, HasSubstr("includes nested more than 100 files deep"));
  EXPECT_THAT(e, HasSubstr("b.xacro:2"));
}

TEST(XacroRecursion, IncludingTheSameFileTwiceSideBySideIsFine) {
  test::TempDir dir;
  dir.write("part.xacro", std::string(kOpen) + "<xacro:property name=\"n\" value=\"1\"/><p/>\n</r>");
  const auto main = dir.write("main.xacro", std::string(kOpen) + "<xacro:include filename=\"part.xacro\"/>"
                                                                  "<xacro:include filename=\"part.xacro\"/>\n</r>");
  std::ostringstream diag;
  XacroOptions options;
  options.diagnostics = &diag;
  const std::string out = expand_xacro_file(main.string(), options);
  std::size_t parts = 0;
  for (auto at = out.find("<p/>"); at != std::string::npos; at = out.find("<p/>", at + 1)) ++parts;
  EXPECT_EQ(parts, 2u) << out;
}

TEST(XacroRecursion, NestingAcrossMacrosAndElementsIsBoundedInAll) {
  // 40 macros, each with its call 250 elements deep: 10,000 levels, under every single limit,
  // overflowed the stack before the combined bound.
  std::string open, close, d = kOpen;
  for (int i = 0; i < 250; ++i) open += "<a>", close += "</a>";
  for (int i = 0; i < 40; ++i) {
    d += "<xacro:macro name=\"m" + std::to_string(i) + "\">" + open +
         (i + 1 < 40 ? "<xacro:m" + std::to_string(i + 1) + "/>" : std::string("<b/>")) + close + "</xacro:macro>\n";
  }
  d += "<xacro:m0/>\n</r>";
  const std::string e = expansion_error(d);
  EXPECT_THAT(e, HasSubstr("nested more than 1000 levels deep in all"));
  EXPECT_THAT(e, HasSubstr("in macro 'm0'"));
  EXPECT_LT(e.size(), 4000u) << e;
}

TEST(XacroRecursion, HugeExpressionIsCutInTheMessage) {
  const std::string expr = std::string(100000, '(') + "1" + std::string(100000, ')');
  const std::string e = expansion_error(std::string(kOpen) + "<a v=\"${" + expr + "}\"/>\n</r>");
  EXPECT_THAT(e, HasSubstr("nested too deeply"));
  EXPECT_THAT(e, HasSubstr("(200001 characters)"));
  EXPECT_THAT(e, Not(HasSubstr(std::string(300, '('))));
  EXPECT_LT(e.size(), 2000u);
}

}  // namespace
}  // namespace mechsim::description
