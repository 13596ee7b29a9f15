// Controller plugins (control/controller_plugins.hpp) with real shared libraries: the example
// plugin (examples/controller_plugin) found through MECHSIM_CONTROLLER_PLUGINS and through a
// package's export, loaded by type name into a controller manager and run; and every way a plugin
// can fail to load, each a one-line error naming what and where.

#include "control/controller_plugins.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include <unistd.h>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kPackage = MECHSIM_EXAMPLE_PLUGIN_PACKAGE;
const fs::path kTestPlugins = MECHSIM_TEST_PLUGIN_DIR;
constexpr const char* kType = "mechsim_example_controllers/BangBangController";

constexpr const char* kYaml = R"(robot:
  bang:
    type: mechsim_example_controllers/BangBangController
    joint: j0
    effort: 20.0
    braking_acceleration: 20.0
    deadband: 0.002
    setpoint: 0.5
  bang_no_effort:
    type: mechsim_example_controllers/BangBangController
    joint: j0
  bang_bad_joint:
    type: mechsim_example_controllers/BangBangController
    joint: j9
    effort: 1.0
)";

// Sets an environment variable for one test and puts back what was there.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

class ControllerPlugins : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_ctl_plugins_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  // The error of loading `name` from kYaml with `registry`.
  std::string load_error(const ControllerRegistry& registry, const std::string& name = "bang") {
    auto robot = testing::make_robot(2);
    ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(kYaml, "c.yaml").child("robot"), registry);
    ControlResult r = manager.load_controller(name);
    EXPECT_FALSE(r.ok) << name << " loaded";
    return r.error;
  }
  fs::path dir_;
};

TEST_F(ControllerPlugins, ExamplePackageIsBuilt) {
  EXPECT_TRUE(fs::exists(kPackage / "controller_plugins.xml")) << kPackage;
  EXPECT_TRUE(fs::exists(kPackage / "lib/libmechsim_example_controllers.so")) << kPackage;
}

TEST_F(ControllerPlugins, ReadsPluginlibsFormWithTheLibraryBesideTheDescription) {
  ControllerPluginSet set;
  read_controller_plugin_description((kPackage / "controller_plugins.xml").string(), set);
  EXPECT_THAT(set.errors, ::testing::IsEmpty());
  ASSERT_EQ(set.classes.size(), 1u);
  EXPECT_EQ(set.classes[0].name, kType);
  EXPECT_EQ(set.classes[0].type, "mechsim_example::BangBangController");
  EXPECT_EQ(fs::path(set.classes[0].library), fs::absolute(kPackage / "lib/libmechsim_example_controllers.so").lexically_normal());
  EXPECT_EQ(set.classes[0].origin, (kPackage / "controller_plugins.xml").string() + ":2");
}

TEST_F(ControllerPlugins, ClassLibrariesWithSeveralLibrariesAndATypeWithoutName) {
  const std::string xml = write("p.xml",
                                "<class_libraries>\n"
                                "  <library path=\"/opt/x/libone.so\"><class name=\"a/A\" type=\"a::A\"/></library>\n"
                                "  <library path=\"libtwo\">\n"
                                "    <class type=\"b::B\"/>\n"
                                "  </library>\n"
                                "</class_libraries>\n");
  ControllerPluginSet set;
  read_controller_plugin_description(xml, set);
  EXPECT_THAT(set.errors, ::testing::IsEmpty());
  ASSERT_EQ(set.classes.size(), 2u);
  EXPECT_EQ(set.classes[0].library, "/opt/x/libone.so");
  EXPECT_EQ(set.classes[1].name, "b::B");  // pluginlib: the lookup name defaults to the type
  EXPECT_EQ(set.classes[1].library, "libtwo.so");  // not beside the file: the loader's search path
  EXPECT_EQ(set.classes[1].origin, xml + ":4");
}

TEST_F(ControllerPlugins, MalformedAndIncompleteDescriptionsNameFileAndLine) {
  ControllerPluginSet set;
  const std::string broken = write("broken.xml", "<library path=\"lib/x\">\n  <class name=\"a/A\" type=\"a::A\">\n</library>\n");
  read_controller_plugin_description(broken, set);
  const std::string no_type = write("no_type.xml", "<library path=\"lib/x\">\n\n  <class name=\"a/A\"/>\n</library>\n");
  read_controller_plugin_description(no_type, set);
  const std::string no_path = write("no_path.xml", "<library>\n  <class name=\"a/A\" type=\"a::A\"/>\n</library>\n");
  read_controller_plugin_description(no_path, set);
  const std::string wrong_root = write("wrong_root.xml", "<robot name=\"r\"/>\n");
  read_controller_plugin_description(wrong_root, set);
  read_controller_plugin_description((dir_ / "absent.xml").string(), set);
  ASSERT_EQ(set.errors.size(), 5u);
  EXPECT_THAT(set.errors[0], HasSubstr(broken + ":2: malformed controller plugin description"));
  EXPECT_THAT(set.errors[1], HasSubstr(no_type + ":3: <class> has no 'type' attribute"));
  EXPECT_THAT(set.errors[2], HasSubstr(no_path + ":1: <library> has no 'path' attribute"));
  EXPECT_THAT(set.errors[3], HasSubstr(wrong_root + ":1: <robot> is not a controller plugin description"));
  EXPECT_THAT(set.errors[4], HasSubstr("absent.xml: cannot read"));
  EXPECT_TRUE(set.classes.empty());
  for (const std::string& e : set.errors) EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST_F(ControllerPlugins, FoundThroughTheEnvironmentVariableAndPackageExports) {
  {
    ScopedEnv env("MECHSIM_CONTROLLER_PLUGINS", (kPackage / "controller_plugins.xml").string() + ":");
    ScopedEnv rpp("ROS_PACKAGE_PATH", (dir_ / "none").string());
    const ControllerPluginSet set = find_controller_plugins();
    ASSERT_EQ(set.classes.size(), 1u);
    EXPECT_EQ(set.classes[0].name, kType);
  }
  {
    ScopedEnv env("MECHSIM_CONTROLLER_PLUGINS", "");
    ScopedEnv rpp("ROS_PACKAGE_PATH", kPackage.parent_path().string());
    const ControllerPluginSet set = find_controller_plugins();
    ASSERT_EQ(set.classes.size(), 1u) << "the package.xml's <controller_interface plugin=...> export";
    EXPECT_EQ(set.classes[0].name, kType);
    EXPECT_THAT(set.errors, ::testing::IsEmpty());
  }
  {  // both ways: one description, read once
    ScopedEnv env("MECHSIM_CONTROLLER_PLUGINS", (kPackage / "controller_plugins.xml").string());
    ScopedEnv rpp("ROS_PACKAGE_PATH", kPackage.parent_path().string());
    const ControllerPluginSet set = find_controller_plugins();
    EXPECT_EQ(set.files.size(), 1u);
    EXPECT_THAT(set.errors, ::testing::IsEmpty());
  }
}

// The example's bang-bang controller drives j0 (unit inertia, no gravity) from 0 to 0.5 rad with
// +-20 N m switching on the braking curve of 20 rad/s^2: the time-optimal move takes
// 2 sqrt(0.5 / 20) = 0.316 s, then it stays within the deadband (plus a tick's overshoot).
TEST_F(ControllerPlugins, ExampleLoadsByTypeNameAndReachesItsSetpoint) {
  ControllerPluginSet set;
  read_controller_plugin_description((kPackage / "controller_plugins.xml").string(), set);
  auto robot = testing::make_robot(2);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(kYaml, "c.yaml").child("robot"),
                            controller_registry_with_plugins(set));
  Controller* c = testing::load_and_start(manager, "bang");
  ASSERT_NE(c, nullptr);
  const auto info = manager.controller_info("bang");
  ASSERT_EQ(info->claims.size(), 1u);
  EXPECT_EQ(info->claims[0].interface, HardwareInterface::Effort);
  EXPECT_EQ(info->claims[0].joints, std::vector<std::string>{"j0"});
  double time = testing::run(manager, *robot, 0.0, 20);
  EXPECT_DOUBLE_EQ(robot->joint("j0").commanded_effort, 20.0);  // accelerating towards 0.5
  time = testing::run(manager, *robot, time, 480);
  EXPECT_NEAR(robot->joint("j0").position, 0.5, 0.01);
  EXPECT_NEAR(robot->joint("j0").velocity, 0.0, 0.1);
  auto* state = c->port_as<StatePort<JointControllerState>>("state");
  ASSERT_NE(state, nullptr);
  EXPECT_DOUBLE_EQ(state->read().set_point, 0.5);
  EXPECT_NEAR(state->read().process_value, 0.5, 0.01);
  // A new target through the command input: back to -0.2 rad.
  auto* command = c->port_as<ScalarCommandPort>("command");
  ASSERT_NE(command, nullptr);
  ASSERT_TRUE(command->write(-0.2));
  EXPECT_FALSE(command->write(std::nan("")));
  testing::run(manager, *robot, time, 800);
  EXPECT_NEAR(robot->joint("j0").position, -0.2, 0.01);
}

TEST_F(ControllerPlugins, ThePluginsConfigurationErrorsNameThePath) {
  ControllerPluginSet set;
  read_controller_plugin_description((kPackage / "controller_plugins.xml").string(), set);
  const ControllerRegistry registry = controller_registry_with_plugins(set);
  EXPECT_THAT(load_error(registry, "bang_no_effort"), HasSubstr("/robot/bang_no_effort/effort"));
  const std::string bad_joint = load_error(registry, "bang_bad_joint");
  EXPECT_THAT(bad_joint, HasSubstr("j9"));
  EXPECT_THAT(bad_joint, HasSubstr("/robot/bang_bad_joint/joint"));
}

TEST_F(ControllerPlugins, AMissingLibraryIsOneLineNamingLibraryTypeAndReason) {
  const std::string xml = write("pkg/controller_plugins.xml",
                                "<library path=\"lib/libmechsim_example_controllers\">\n"
                                "  <class name=\"mechsim_example_controllers/BangBangController\" type=\"mechsim_example::BangBangController\"/>\n"
                                "</library>\n");
  ControllerPluginSet set;
  read_controller_plugin_description(xml, set);
  const std::string error = load_error(controller_registry_with_plugins(set));
  EXPECT_THAT(error, HasSubstr("could not load controller 'bang'"));
  EXPECT_THAT(error, HasSubstr(std::string("controller type '") + kType + "' (declared at " + xml + ":2)"));
  EXPECT_THAT(error, HasSubstr("cannot load library libmechsim_example_controllers.so (not at " +
                               (dir_ / "pkg/lib/libmechsim_example_controllers.so").string() + ", so looked up by name)"));
  EXPECT_THAT(error, HasSubstr("cannot open shared object file"));  // dlerror's reason
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST_F(ControllerPlugins, ALibraryLackingTheTypeListsWhatItHas) {
  const std::string xml = write("x.xml", "<library path=\"" + (kPackage / "lib/libmechsim_example_controllers.so").string() +
                                             "\">\n  <class name=\"" + kType + "\" type=\"mechsim_example::NoSuch\"/>\n</library>\n");
  ControllerPluginSet set;
  read_controller_plugin_description(xml, set);
  const std::string error = load_error(controller_registry_with_plugins(set));
  EXPECT_THAT(error, HasSubstr("has no class 'mechsim_example::NoSuch' (it has: mechsim_example::BangBangController)"));
  EXPECT_THAT(error, HasSubstr(kType));
}

TEST_F(ControllerPlugins, ALibraryOfAnotherApiVersionOrWithoutEntryPointIsRefused) {
  const std::string xml = write("x.xml", "<class_libraries>\n<library path=\"" + (kTestPlugins / "libtest_wrong_version_plugin.so").string() +
                                             "\"><class name=\"" + kType + "\" type=\"t::T\"/></library>\n" +
                                             "<library path=\"" + (kTestPlugins / "libtest_no_entry_plugin.so").string() +
                                             "\"><class name=\"other/Type\" type=\"t::T\"/></library>\n</class_libraries>\n");
  ControllerPluginSet set;
  read_controller_plugin_description(xml, set);
  ASSERT_EQ(set.classes.size(), 2u);
  try {
    create_plugin_controller(set.classes[0]);
    FAIL() << "a library of API version 999 loaded";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("built against mechsim controller API version 999, this mechsim has version 1"));
  }
  try {
    create_plugin_controller(set.classes[1]);
    FAIL() << "a library without entry point loaded";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("has no mechsim_controller_library() entry point"));
    EXPECT_THAT(e.what(), HasSubstr("libtest_no_entry_plugin.so"));
  }
}

TEST_F(ControllerPlugins, AnUnknownTypeNamesTheDescriptionsThatFailedAndBuiltinsWin) {
  ControllerPluginSet set;
  read_controller_plugin_description(write("broken.xml", "<library path=\"x\">\n<class"), set);
  set.classes.push_back({"effort_controllers/JointEffortController", "x::Y", "libx.so", "", "y.xml:4"});
  const ControllerRegistry registry = controller_registry_with_plugins(set);
  EXPECT_TRUE(registry.has("effort_controllers/JointEffortController"));
  const std::string error = load_error(registry);
  EXPECT_THAT(error, HasSubstr("unknown type '" + std::string(kType) + "'"));
  EXPECT_THAT(error, HasSubstr("broken.xml:2: malformed controller plugin description"));
  EXPECT_THAT(error, HasSubstr("y.xml:4: 'effort_controllers/JointEffortController' is a built-in type"));
}

}  // namespace
}  // namespace mechsim::control
