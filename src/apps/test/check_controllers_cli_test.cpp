// `mechsim check ROBOT --controllers FILE.yaml`: every controller of a YAML is loaded against the
// robot and reported with its claims; unknown types and joints are clear errors (exit 1).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "run_process.hpp"

namespace {

using mechsim::apps::test::ProcessResult;
using mechsim::apps::test::run_process;

namespace fs = std::filesystem;

const fs::path kShared = MECHSIM_SHARED_DIR;
const fs::path kSource = MECHSIM_SOURCE_DIR;

TEST(CheckControllersCli, AllElevenControllersOfTheRealCc8Load) {
  if (!fs::exists(kShared / "robots/cc8_description")) GTEST_SKIP() << "shared data absent: " << kShared;
  const auto r = run_process({MECHSIM_EXE, "check", (kShared / "robots/cc8_description/urdf/cc8.xacro").string(),
                              "--package", "cc8_description=" + (kShared / "robots/cc8_description").string(),
                              "--controllers", (kShared / "robots/cc8_description/config/controller.yaml").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("11 of 11 controllers load"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("/cc8/steering_FL_position_controller (effort_controllers/JointPositionController): effort [steering_FL]"),
            std::string::npos)
      << r.out;
}

TEST(CheckControllersCli, MechsimsCc8ControllersIncludingTheRoverDriveLoad) {
  const auto r = run_process({MECHSIM_EXE, "check", (kSource / "robots/cc8/urdf/cc8.urdf.xacro").string(), "--package",
                              "mechsim_cc8=" + (kSource / "robots/cc8").string(), "--controllers",
                              (kSource / "robots/cc8/config/controllers.yaml").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("12 of 12 controllers load"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rover_drive_controller (mechsim/RoverDriveController): effort [steering_FL"), std::string::npos) << r.out;
}

class CheckControllersBadYaml : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_check_ctl_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  ProcessResult check(const std::string& yaml) {
    return run_process({MECHSIM_EXE, "check", (kSource / "robots/cc8/urdf/cc8.urdf.xacro").string(), "--package",
                        "mechsim_cc8=" + (kSource / "robots/cc8").string(), "--controllers", yaml});
  }
  fs::path dir_;
};

TEST_F(CheckControllersBadYaml, UnknownTypeIsNamed) {
  const auto r = check(write("t.yaml", "cc8:\n  c1:\n    type: effort_controllers/NoSuchController\n    joint: steering_FL\n"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("/cc8/c1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("NoSuchController"), std::string::npos) << r.out;
}

TEST_F(CheckControllersBadYaml, UnknownJointIsNamedWithItsParameter) {
  const auto r = check(write("j.yaml", "cc8:\n  c1:\n    type: effort_controllers/JointPositionController\n"
                                       "    joint: steering_XX\n    pid: {p: 1.0}\n"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("steering_XX"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("/cc8/c1/joint"), std::string::npos) << r.out;
}

TEST_F(CheckControllersBadYaml, MalformedYamlNamesFileAndLine) {
  const auto r = check(write("m.yaml", "cc8:\n  c1: {type: [unclosed\n"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("m.yaml:"), std::string::npos) << r.err;
}

}  // namespace
