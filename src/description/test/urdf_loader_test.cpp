// load_robot: plain URDF files, xacro files (by name or by content), xacro arguments and errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "description/robot_loader.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class RobotLoader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("mechsim_loader_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << content;
    return p.string();
  }
  fs::path dir_;
};

constexpr const char* kXacro = R"(<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="wheels">
  <xacro:arg name="count" default="1"/>
  <xacro:property name="mass" value="2.0"/>
  <xacro:macro name="wheel" params="side">
    <joint name="${side}_joint" type="continuous"><parent link="base"/><child link="${side}_wheel"/><axis xyz="0 1 0"/></joint>
    <link name="${side}_wheel"><inertial><mass value="${mass}"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  </xacro:macro>
  <link name="base"/>
  <xacro:wheel side="left"/>
  <xacro:if value="${$(arg count) > 1}"><xacro:wheel side="right"/></xacro:if>
</robot>
)";

TEST_F(RobotLoader, LoadsAPlainUrdf) {
  const std::string path = write("plain.urdf", R"(<robot name="plain"><link name="a"/></robot>)");
  const LoadedRobot r = load_robot(path, {});
  EXPECT_EQ(r.model.name, "plain");
  EXPECT_EQ(r.model.source, path);
  EXPECT_THAT(r.urdf, HasSubstr("<robot name=\"plain\">"));
}

// A URDF saved as Latin-1 (an accented link name) ran, and the run then failed writing its JSON
// with "[json.exception.type_error.316] invalid UTF-8 byte", naming no file. Now the reader says
// where, before anything runs.
TEST_F(RobotLoader, AUrdfThatIsNotUtf8IsRefusedWithItsLine) {
  const std::string path = write("latin1.urdf", "<robot name=\"r\">\n  <link name=\"t\xEAte\"/>\n</robot>\n");
  try {
    load_robot(path, {});
    FAIL() << "no error";
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("latin1.urdf:2"));
    EXPECT_THAT(e.what(), HasSubstr("not UTF-8 text (byte 0xEA)"));
  }
  const std::string utf8 = write("utf8.urdf", "<robot name=\"r\">\n  <link name=\"t\xC3\xAAte\"/>\n</robot>\n");
  EXPECT_EQ(load_robot(utf8, {}).model.links.at(0).name, "t\xC3\xAAte");
}

TEST_F(RobotLoader, ExpandsXacroFilesWithArguments) {
  const std::string path = write("wheels.urdf.xacro", kXacro);
  const LoadedRobot one = load_robot(path, {});
  EXPECT_EQ(one.model.links.size(), 2u);
  EXPECT_DOUBLE_EQ(one.model.total_mass(), 2.0);
  EXPECT_EQ(one.model.source, path + " (expanded)");
  EXPECT_THAT(one.urdf, Not(HasSubstr("xacro:")));
  LoadOptions options;
  options.xacro_args["count"] = "2";
  const LoadedRobot two = load_robot(path, options);
  EXPECT_EQ(two.model.links.size(), 3u);
  EXPECT_NE(two.model.joint("right_joint"), nullptr);
}

TEST_F(RobotLoader, ExpandsAUrdfFileHoldingXacroElements) {
  const std::string path = write("wheels.urdf", kXacro);
  EXPECT_EQ(load_robot(path, {}).model.links.size(), 2u);
}

TEST_F(RobotLoader, ReportsExpansionAndValidationErrors) {
  const std::string bad_macro = write("bad.urdf.xacro", R"(<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">
  <xacro:nope/></robot>)");
  try {
    load_robot(bad_macro, {});
    FAIL() << "no error";
  } catch (const XacroError& e) {
    EXPECT_THAT(e.what(), HasSubstr("nope"));
    EXPECT_THAT(e.what(), HasSubstr("bad.urdf.xacro"));
  }
  const std::string negative = write("negative.urdf.xacro", R"(<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">
  <link name="a"><inertial><mass value="${-1}"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
</robot>)");
  try {
    load_robot(negative, {});
    FAIL() << "no error";
  } catch (const DescriptionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("negative.urdf.xacro (expanded)"));
    EXPECT_THAT(e.what(), HasSubstr("link 'a': negative mass -1"));
  }
  LoadOptions lenient;
  lenient.lenient = true;
  const LoadedRobot loaded = load_robot(negative, lenient);
  ASSERT_FALSE(loaded.warnings.empty());
  EXPECT_THAT(loaded.warnings.back(), HasSubstr("negative mass"));
  EXPECT_THROW(load_robot((dir_ / "absent.urdf").string(), {}), DescriptionError);
}

}  // namespace
}  // namespace mechsim::description
