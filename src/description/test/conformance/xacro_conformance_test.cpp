// xacro's own test cases (../shared/conformance/xacro/cases), one test per case, compared with the
// rules of the original suite (xml_compare_util). See that folder's README.md for the layout.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "description/xacro/xacro.hpp"
#include "xml_compare_util.hpp"

namespace mechsim::description {
namespace {
namespace fs = std::filesystem;

const fs::path kCases = fs::path(MECHSIM_SHARED_DIR) / "conformance" / "xacro" / "cases";

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> list_cases() {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(kCases, ec)) return out;
  for (const auto& e : fs::directory_iterator(kCases, ec)) {
    if (e.is_directory()) out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::multimap<std::string, std::string> read_meta(const fs::path& p) {
  std::multimap<std::string, std::string> out;
  std::istringstream in(read_file(p));
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(' '));
    out.emplace(line.substr(0, colon), value);
  }
  return out;
}

std::string meta_value(const std::multimap<std::string, std::string>& m, const std::string& key) {
  auto it = m.find(key);
  return it == m.end() ? std::string() : it->second;
}

// Runs a case from its own directory (relative includes and $(cwd) resolve from there) and
// restores the working directory and ROS_PACKAGE_PATH afterwards.
class CaseEnvironment {
 public:
  CaseEnvironment(const fs::path& dir, const std::optional<std::string>& package_path) : old_cwd_(fs::current_path()) {
    if (const char* p = std::getenv("ROS_PACKAGE_PATH")) old_rpp_ = p;
    if (package_path) ::setenv("ROS_PACKAGE_PATH", package_path->c_str(), 1);
    fs::current_path(dir);
  }
  ~CaseEnvironment() {
    fs::current_path(old_cwd_);
    if (old_rpp_) ::setenv("ROS_PACKAGE_PATH", old_rpp_->c_str(), 1);
    else ::unsetenv("ROS_PACKAGE_PATH");
  }
  CaseEnvironment(const CaseEnvironment&) = delete;
  CaseEnvironment& operator=(const CaseEnvironment&) = delete;

 private:
  fs::path old_cwd_;
  std::optional<std::string> old_rpp_;
};

class XacroConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(XacroConformance, Case) {
  const fs::path dir = kCases / GetParam();
  const auto meta = read_meta(dir / "meta.txt");
  if (meta_value(meta, "python_only") == "yes") RecordProperty("python_only", "yes");

  XacroOptions options;
  std::istringstream args(read_file(dir / "args.txt"));
  std::string line;
  while (std::getline(args, line)) {
    const auto pos = line.find(":=");
    if (pos != std::string::npos) options.args[line.substr(0, pos)] = line.substr(pos + 2);
  }
  std::ostringstream diagnostics;
  options.diagnostics = &diagnostics;

  std::optional<std::string> package_path;
  const std::string env = meta_value(meta, "env");
  if (env.starts_with("ROS_PACKAGE_PATH=")) package_path = (dir / "ros_pkgs").string();

  std::string output;
  std::optional<XacroError> error;
  {
    CaseEnvironment scope(dir, package_path);
    try {
      output = expand_xacro_file("input.xacro", options);
    } catch (const XacroError& e) {
      error = e;
    }
  }

  if (fs::exists(dir / "expected_error.txt")) {
    ASSERT_TRUE(error.has_value()) << "expansion should fail but produced:\n" << output;
    const std::string expected = read_file(dir / "expected_error.txt");
    const std::string kind = expected.substr(0, expected.find('\n'));
    const std::string message = expected.substr(expected.find('\n') + 1);
    EXPECT_EQ(error->kind() == XacroError::Kind::Parse ? "ParseError" : "XacroException", kind) << error->what();
    const std::string match = meta_value(meta, "error_message_match");
    const std::string actual = error->what();
    if (match.starts_with("exact")) {
      std::string want = message;
      while (!want.empty() && want.back() == '\n') want.pop_back();
      EXPECT_TRUE(actual.starts_with(want) && (actual.size() == want.size() || actual[want.size()] == '\n'))
          << "expected message: " << want << "\nactual: " << actual;
    } else if (match.starts_with("prefix")) {
      const auto first = message.find('\n');
      const std::string want = message.substr(0, message.find('\n', first + 1));
      EXPECT_TRUE(actual.starts_with(want)) << "expected prefix: " << want << "\nactual: " << actual;
    }
    return;
  }

  ASSERT_FALSE(error.has_value()) << error->what();
  std::string expected = read_file(dir / "expected.xml");
  const std::string placeholder = "@CASE_DIR@";
  for (auto pos = expected.find(placeholder); pos != std::string::npos; pos = expected.find(placeholder, pos)) {
    expected.replace(pos, placeholder.size(), dir.string());
  }
  test::XmlCompareOptions compare;
  compare.compare_comments = true;
  EXPECT_EQ(test::compare_xml(output, expected, compare), "");
  RecordProperty("byte_identical", output == expected ? "yes" : "no");
  // The diagnostics the original suite asserted (warnings and xacro.message output).
  const std::string diag = diagnostics.str();
  for (auto [it, end] = meta.equal_range("stderr_contains"); it != end; ++it) {
    EXPECT_NE(diag.find(it->second), std::string::npos)
        << "diagnostics should contain '" << it->second << "' but were:\n" << diag;
  }
  std::string exact;
  for (auto [it, end] = meta.equal_range("stderr_exact"); it != end; ++it) exact += it->second + "\n";
  if (!exact.empty()) {
    EXPECT_EQ(diag, exact);
  }
  if (meta_value(meta, "stderr_empty") == "yes") {
    EXPECT_EQ(diag, "");
  }
  if (meta_value(meta, "stderr_nonempty") == "yes") {
    EXPECT_NE(diag, "");
  }
}

std::string case_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = "c" + info.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, XacroConformance, ::testing::ValuesIn(list_cases()), case_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(XacroConformance);

TEST(XacroConformanceData, Present) {
  if (!fs::is_directory(kCases)) GTEST_SKIP() << "shared data not found at " << kCases << " (MECHSIM_SHARED_DIR)";
  EXPECT_EQ(list_cases().size(), 156u);
}

}  // namespace
}  // namespace mechsim::description
