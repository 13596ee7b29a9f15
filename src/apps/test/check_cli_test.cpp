// `mechsim check` on valid descriptions: the summary, --lenient, xacro arguments, --package, and
// command-line mistakes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kShared = MECHSIM_SHARED_DIR;
const fs::path kReference = kShared / "robots" / "reference";
const std::string kPr2Package = (kShared / "robots" / "pr2_description").string();

ProcessResult check(std::vector<std::string> args) {
  args.insert(args.begin(), {MECHSIM_EXE, "check"});
  return run_process(args, 60.0);
}

// The number after `label` in the summary, e.g. "links:" -> 27.
double summary_number(const std::string& out, const std::string& label) {
  std::smatch m;
  const std::regex re(label + R"(\s+([-0-9.]+))");
  if (!std::regex_search(out, m, re)) return -1.0;
  return std::stod(m[1].str());
}

// The count of `<tag ` or `<tag>` elements directly in the text (a rough independent count for
// URDF files, which hold no nested elements of these names).
std::size_t count_tags(const fs::path& file, const std::string& tag) {
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t n = 0;
  for (std::size_t at = text.find("<" + tag + " "); at != std::string::npos; at = text.find("<" + tag + " ", at + 1)) ++n;
  return n;
}

// This program's scratch folder, removed when the program ends.
const fs::path& scratch() {
  struct Folder {
    fs::path path = fs::path(::testing::TempDir()) / ("mechsim_check_cli_" + std::to_string(getpid()));
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

std::string temp_file(const std::string& name, const std::string& content) {
  const fs::path& dir = scratch();
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  write_file(path, content);
  return path;
}

TEST(CheckCli, Cc8ReferenceSummary) {
  const fs::path cc8 = kReference / "cc8.urdf";
  if (!fs::exists(cc8)) GTEST_SKIP() << "no shared data at " << cc8;
  const ProcessResult r = check({cc8.string()});
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("robot 'cc8'"));
  EXPECT_EQ(summary_number(r.out, "links:"), static_cast<double>(count_tags(cc8, "link")));
  // Each of cc8's transmissions names one <joint>.
  EXPECT_EQ(summary_number(r.out, "joints:"),
            static_cast<double>(count_tags(cc8, "joint") - count_tags(cc8, "transmission")));
  EXPECT_NEAR(summary_number(r.out, "total mass:"), 64.0, 1.0);
  EXPECT_THAT(r.out, HasSubstr("14 transmission_interface/SimpleTransmission"));
  EXPECT_THAT(r.out, HasSubstr("rocker_differential (libleo_gazebo_differential_plugin.so)"));
  EXPECT_THAT(r.out, HasSubstr("jointA=rocker_joint_L"));
  EXPECT_THAT(r.out, HasSubstr("robotNamespace=/cc8"));
  EXPECT_THAT(r.out, HasSubstr("OK: "));
  // cc8's meshes name package cc8_description, not given here: a warning, not an error.
  EXPECT_THAT(r.err, HasSubstr("warning: "));
  EXPECT_THAT(r.err, HasSubstr("package://cc8_description"));
}

TEST(CheckCli, Pr2ReferenceNeedsLenient) {
  const fs::path pr2 = kReference / "pr2.urdf";
  if (!fs::exists(pr2)) GTEST_SKIP() << "no shared data at " << pr2;
  const ProcessResult strict = check({pr2.string(), "--package", "pr2_description=" + kPr2Package});
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_THAT(strict.err, HasSubstr("link 'sensor_mount_link': inertia breaks the triangle inequality"));
  EXPECT_THAT(strict.err, HasSubstr("pr2.urdf:"));
  EXPECT_EQ(strict.out, "");

  const ProcessResult lenient = check({"--lenient", pr2.string(), "--package", "pr2_description=" + kPr2Package});
  ASSERT_EQ(lenient.exit_code, 0) << lenient.err;
  EXPECT_THAT(lenient.out, HasSubstr("robot 'pr2'"));
  EXPECT_THAT(lenient.out, HasSubstr("2 pr2_mechanism_model/WristTransmission"));
  EXPECT_THAT(lenient.out, HasSubstr("2 pr2_mechanism_model/PR2GripperTransmission"));
  EXPECT_EQ(summary_number(lenient.out, "transmissions:"), static_cast<double>(count_tags(pr2, "transmission")));
  EXPECT_THAT(lenient.err, HasSubstr("(accepted: lenient)"));
  EXPECT_THAT(lenient.err, Not(HasSubstr("mesh URI")));  // every mesh resolved through --package
}

// Expanding pr2.urdf.xacro gives the same robot as the reference expansion.
TEST(CheckCli, Pr2XacroMatchesTheReference) {
  const fs::path xacro = fs::path(kPr2Package) / "robots" / "pr2.urdf.xacro";
  if (!fs::exists(xacro)) GTEST_SKIP() << "no shared data at " << xacro;
  const ProcessResult from_xacro = check({xacro.string(), "--package", "pr2_description=" + kPr2Package, "--lenient"});
  const ProcessResult reference =
      check({(kReference / "pr2.urdf").string(), "--package", "pr2_description=" + kPr2Package, "--lenient"});
  ASSERT_EQ(from_xacro.exit_code, 0) << from_xacro.err;
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  // Everything but the first line (the source) and the final OK line is the same.
  auto body = [](const std::string& out) {
    const std::size_t first = out.find('\n');
    const std::size_t ok = out.rfind("OK: ");
    return out.substr(first, ok - first);
  };
  EXPECT_EQ(body(from_xacro.out), body(reference.out));
  EXPECT_THAT(from_xacro.out, HasSubstr("pr2.urdf.xacro (expanded)"));
}

TEST(CheckCli, PassesXacroArguments) {
  const std::string path = temp_file("args.urdf.xacro", R"x(<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="argbot">
  <xacro:arg name="with_arm" default="false"/>
  <link name="base"/>
  <xacro:if value="$(arg with_arm)">
    <joint name="shoulder" type="continuous"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/></joint>
    <link name="arm"/>
  </xacro:if>
</robot>
)x");
  const ProcessResult plain = check({path});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(summary_number(plain.out, "links:"), 1.0);
  const ProcessResult with_arm = check({path, "with_arm:=true"});
  ASSERT_EQ(with_arm.exit_code, 0) << with_arm.err;
  EXPECT_EQ(summary_number(with_arm.out, "links:"), 2.0);
  EXPECT_EQ(summary_number(with_arm.out, "degrees of freedom:"), 1.0);
}

TEST(CheckCli, RelativePackageDirectoriesWork) {
  const fs::path dir = scratch() / "pkg";
  fs::create_directories(dir / "mypkg" / "urdf");
  write_file((dir / "mypkg" / "urdf" / "part.xacro").string(), R"(<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="part"/></robot>)");
  write_file((dir / "main.urdf.xacro").string(), R"(<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="pkgbot">
  <xacro:include filename="$(find mypkg)/urdf/part.xacro"/>
</robot>)");
  // Run from the temp dir, naming the package relative to it.
  const fs::path previous = fs::current_path();
  fs::current_path(dir);
  const ProcessResult r = check({"main.urdf.xacro", "--package", "mypkg=mypkg"});
  fs::current_path(previous);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("robot 'pkgbot'"));
  EXPECT_EQ(summary_number(r.out, "links:"), 1.0);
}

TEST(CheckCli, CommandLineMistakes) {
  const ProcessResult missing = check({"/nonexistent/robot.urdf"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("/nonexistent/robot.urdf: cannot open the file"));

  const ProcessResult directory = check({::testing::TempDir()});
  EXPECT_EQ(directory.exit_code, 1);
  EXPECT_THAT(directory.err, HasSubstr("is a directory, not a file"));

  const std::string ok = temp_file("ok.urdf", R"(<robot name="ok"><link name="a"/></robot>)");
  const ProcessResult bad_mapping = check({ok, "no_separator"});
  EXPECT_EQ(bad_mapping.exit_code, 1);
  EXPECT_THAT(bad_mapping.err, HasSubstr("'no_separator' is not a name:=value mapping"));

  const ProcessResult bad_package = check({ok, "--package", "nodir"});
  EXPECT_EQ(bad_package.exit_code, 1);
  EXPECT_THAT(bad_package.err, HasSubstr("--package 'nodir' is not NAME=DIR"));

  const ProcessResult no_file = check({});
  EXPECT_EQ(no_file.exit_code, 1);
  EXPECT_THAT(no_file.err, HasSubstr("file"));

  const ProcessResult fine = check({ok});
  EXPECT_EQ(fine.exit_code, 0) << fine.err;
  EXPECT_THAT(fine.out, HasSubstr("robot 'ok'"));
  EXPECT_EQ(fine.err, "");
}

TEST(CheckCli, UnknownSubcommandIsNamedWithTheClosestOne) {
  const ProcessResult typo = run_process({MECHSIM_EXE, "xacor", "robot.xacro"});
  EXPECT_EQ(typo.exit_code, 1);
  EXPECT_THAT(typo.err, HasSubstr("unknown subcommand 'xacor' (did you mean 'xacro'?)"));
  const ProcessResult help = run_process({MECHSIM_EXE, "nosuch", "--help"});
  EXPECT_EQ(help.exit_code, 1);  // was the main help with status 0
  EXPECT_THAT(help.err, HasSubstr("unknown subcommand 'nosuch'"));
  EXPECT_THAT(help.err, Not(HasSubstr("did you mean")));  // nothing is close
  EXPECT_EQ(help.out, "");
  const ProcessResult version = run_process({MECHSIM_EXE, "--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_THAT(version.out, HasSubstr("mechsim"));
}

// A collision mesh the physics cannot find is left out: check says so once per mesh, naming the
// link, the mesh as written and the path it tried (it used to say nothing about a missing file).
TEST(CheckCli, ALeftOutCollisionMeshIsNamedOnceWithItsLinkAndThePathTried) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("mechsim_check_meshes_" + std::to_string(getpid()));
  struct Cleanup {
    fs::path dir;
    ~Cleanup() { fs::remove_all(dir); }
  } cleanup{dir};
  fs::create_directories(dir);
  write_file((dir / "bot.urdf").string(), R"(<robot name="bot">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="meshes/base.stl"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <link name="arm"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="package://no_such_package_here/arm.stl"/></geometry></collision></link>
</robot>)");
  const ProcessResult r = check({(dir / "bot.urdf").string()});
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string base = "link 'base': collision mesh 'meshes/base.stl'";
  EXPECT_THAT(r.err, HasSubstr(base));
  EXPECT_THAT(r.err, HasSubstr("no such file (path tried: " + (dir / "meshes" / "base.stl").string() + ")"));
  EXPECT_EQ(r.err.find(base), r.err.rfind(base)) << "said once:\n" << r.err;
  EXPECT_THAT(r.err, HasSubstr("link 'arm': collision mesh 'package://no_such_package_here/arm.stl'"));
  EXPECT_THAT(r.out, HasSubstr("(3 warnings)")) << "the two meshes and the unknown package";
}

}  // namespace
}  // namespace mechsim::apps::test
