// The real robot descriptions expand to the reference URDFs (../shared/robots/reference), and the
// PR2 snapshot of xacro's own suite expands to its golden output (../shared/conformance/xacro/golden).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "description/xacro/xacro.hpp"
#include "xml_compare_util.hpp"

namespace mechsim::description {
namespace {
namespace fs = std::filesystem;

const fs::path kShared(MECHSIM_SHARED_DIR);

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct RobotCase {
  std::string name;   // reference/<name>.urdf
  std::string input;  // relative to the shared folder
};

void PrintTo(const RobotCase& c, std::ostream* os) { *os << c.name; }

class RobotReference : public ::testing::TestWithParam<RobotCase> {};

TEST_P(RobotReference, MatchesReference) {
  const RobotCase& c = GetParam();
  if (!fs::is_directory(kShared / "robots")) GTEST_SKIP() << "shared robots not found at " << kShared / "robots";
  XacroOptions options;
  options.packages["pr2_description"] = (kShared / "robots" / "pr2_description").string();
  options.packages["cc8_description"] = (kShared / "robots" / "cc8_description").string();
  std::ostringstream diagnostics;
  options.diagnostics = &diagnostics;
  const std::string output = expand_xacro_file((kShared / c.input).string(), options);
  test::XmlCompareOptions compare;
  compare.abs_tolerance = 0.0;
  compare.rel_tolerance = 1e-9;
  EXPECT_EQ(test::compare_xml(output, read_file(kShared / "robots" / "reference" / (c.name + ".urdf")), compare), "");
}

INSTANTIATE_TEST_SUITE_P(
    Robots, RobotReference,
    ::testing::Values(RobotCase{"pr2", "robots/pr2_description/robots/pr2.urdf.xacro"},
                      RobotCase{"pr2_no_arms", "robots/pr2_description/robots/pr2_no_arms.urdf.xacro"},
                      RobotCase{"pr2_no_kinect", "robots/pr2_description/robots/pr2_no_kinect.urdf.xacro"},
                      RobotCase{"pr2_se", "robots/pr2_description/robots/pr2_se.urdf.xacro"},
                      RobotCase{"cc8", "robots/cc8_description/urdf/cc8.xacro"}),
    [](const ::testing::TestParamInfo<RobotCase>& p) { return p.param.name; });

// The golden inputs include each other through $(find xacro)/test/robots/pr2/...: a temporary
// package `xacro` whose test/robots/pr2 links to the snapshot.
class GoldenPr2 : public ::testing::TestWithParam<bool> {};

TEST_P(GoldenPr2, MatchesGolden) {
  const fs::path golden = kShared / "conformance" / "xacro" / "golden" / "pr2_1.11.4";
  if (!fs::is_directory(golden)) GTEST_SKIP() << "golden PR2 not found at " << golden;
  const fs::path pkg = fs::temp_directory_path() / ("mechsim_xacro_golden_" + std::to_string(::getpid())) / "xacro";
  fs::create_directories(pkg / "test" / "robots");
  std::ofstream(pkg / "package.xml") << "<package><name>xacro</name></package>\n";
  std::error_code ec;
  fs::remove(pkg / "test" / "robots" / "pr2", ec);
  fs::create_directory_symlink(golden, pkg / "test" / "robots" / "pr2");
  XacroOptions options;
  options.packages["xacro"] = pkg.string();
  std::ostringstream diagnostics;
  options.diagnostics = &diagnostics;
  std::string output;
  try {
    output = expand_xacro_file((golden / "pr2.urdf.xacro").string(), options);
  } catch (...) {
    fs::remove_all(pkg.parent_path(), ec);
    throw;
  }
  fs::remove_all(pkg.parent_path(), ec);
  test::XmlCompareOptions compare;
  compare.compare_comments = GetParam();
  EXPECT_EQ(test::compare_xml(output, read_file(golden / "pr2_1.11.4.xml"), compare), "");
}

INSTANTIATE_TEST_SUITE_P(Comments, GoldenPr2, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& p) {
                           return std::string(p.param ? "compared" : "ignored");
                         });

}  // namespace
}  // namespace mechsim::description
