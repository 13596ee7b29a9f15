// The example controller plugin (examples/controller_plugin) as a user meets it: its type loads by
// name in `mechsim check --controllers` and in `mechsim run` through MECHSIM_CONTROLLER_PLUGINS or
// a package on ROS_PACKAGE_PATH; without its library the error is one line naming the library and
// the type; every unsupported type of a YAML is listed at once.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include <unistd.h>

#include "run_process.hpp"

namespace {

using mechsim::apps::test::ProcessResult;
using mechsim::apps::test::run_process;

namespace fs = std::filesystem;

const fs::path kSource = MECHSIM_SOURCE_DIR;
const fs::path kPackage = fs::path(MECHSIM_BINARY_DIR) / "plugin_packages/mechsim_example_controllers";
const fs::path kExample = kSource / "examples/controller_plugin";
constexpr const char* kType = "mechsim_example_controllers/BangBangController";

class ControllerPluginCli : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_ctl_plugin_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    save("MECHSIM_CONTROLLER_PLUGINS");
    save("ROS_PACKAGE_PATH");
    ::unsetenv("MECHSIM_CONTROLLER_PLUGINS");
    ::unsetenv("ROS_PACKAGE_PATH");
  }
  void TearDown() override {
    for (const auto& [name, value] : saved_) {
      if (value) ::setenv(name.c_str(), value->c_str(), 1);
      else ::unsetenv(name.c_str());
    }
    fs::remove_all(dir_);
  }
  void save(const std::string& name) {
    const char* v = std::getenv(name.c_str());
    saved_.emplace_back(name, v != nullptr ? std::optional<std::string>(v) : std::nullopt);
  }
  ProcessResult check(const std::string& yaml) {
    return run_process({MECHSIM_EXE, "check", (kSource / "robots/testbots/urdf/gripper.urdf.xacro").string(), "interface:=EffortJointInterface",
                        "--package", "mechsim_testbots=" + (kSource / "robots/testbots").string(), "--controllers", yaml});
  }
  fs::path dir_;
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

TEST_F(ControllerPluginCli, CheckLoadsThePluginTypeThroughTheEnvironmentVariable) {
  ::setenv("MECHSIM_CONTROLLER_PLUGINS", (kPackage / "controller_plugins.xml").c_str(), 1);
  const auto r = check((kExample / "config/gripper_bang_bang.yaml").string());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("controller plugins (1 types from 1 descriptions)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(std::string("/gripper/finger_bang_bang (") + kType + "): effort [left_finger_joint]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 of 2 controllers load"), std::string::npos) << r.out;
}

TEST_F(ControllerPluginCli, CheckFindsThePluginThroughAPackageExport) {
  ::setenv("ROS_PACKAGE_PATH", kPackage.parent_path().c_str(), 1);
  const auto r = check((kExample / "config/gripper_bang_bang.yaml").string());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("2 of 2 controllers load"), std::string::npos) << r.out;
}

TEST_F(ControllerPluginCli, WithoutItsLibraryTheErrorIsOneLineNamingLibraryAndType) {
  fs::copy(kPackage, dir_ / "pkg", fs::copy_options::recursive);
  fs::remove(dir_ / "pkg/lib/libmechsim_example_controllers.so");
  ::setenv("MECHSIM_CONTROLLER_PLUGINS", (dir_ / "pkg/controller_plugins.xml").c_str(), 1);
  const auto r = check((kExample / "config/gripper_bang_bang.yaml").string());
  EXPECT_EQ(r.exit_code, 1);
  std::string line;
  for (std::istringstream in(r.out); std::getline(in, line);) {
    if (line.find("/gripper/finger_bang_bang") != std::string::npos) break;
  }
  EXPECT_NE(line.find(std::string("controller type '") + kType + "'"), std::string::npos) << r.out;
  EXPECT_NE(line.find("cannot load library libmechsim_example_controllers.so"), std::string::npos) << r.out;
  EXPECT_NE(line.find("cannot open shared object file"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 of 2 controllers load"), std::string::npos) << r.out;
}

TEST_F(ControllerPluginCli, EveryUnsupportedTypeIsListedAtOnce) {
  std::ofstream(dir_ / "u.yaml") << "gripper:\n"
                                    "  a: {type: my_pkg/First, joint: left_finger_joint}\n"
                                    "  b: {type: effort_controllers/JointEffortController, joint: left_finger_joint}\n"
                                    "  c: {type: my_pkg/Second, joint: left_finger_joint}\n"
                                    "  d: {type: my_pkg/First, joint: left_finger_joint}\n"
                                 << "  e: {type: " << kType << ", joint: left_finger_joint, effort: 1.0}\n";
  const auto r = check((dir_ / "u.yaml").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find(std::string("unsupported types (3): my_pkg/First my_pkg/Second ") + kType), std::string::npos) << r.out;
}

TEST_F(ControllerPluginCli, AScenarioRunsThePluginController) {
  ::setenv("MECHSIM_CONTROLLER_PLUGINS", (kPackage / "controller_plugins.xml").c_str(), 1);
  const auto r = run_process({MECHSIM_EXE, "run", (kExample / "scenarios/gripper_bang_bang.yaml").string(), "-o",
                              (dir_ / "out").string(), "--no-plots"},
                             120.0);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("PASSED"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir_ / "out/summary.json"));
}

}  // namespace
