// The lean `xacro` program (bin/xacro) is `mechsim xacro` under ROS's command line: the same
// document byte for byte, the same errors, and none of the simulator's libraries loaded.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kXacro = std::string(MECHSIM_BINARY_DIR) + "/bin/xacro";
const fs::path kShared = MECHSIM_SHARED_DIR;

TEST(XacroProgram, SameDocumentAsMechsimXacro) {
  const fs::path pr2 = kShared / "robots" / "pr2_description";
  const fs::path cc8 = kShared / "robots" / "cc8_description";
  if (!fs::exists(pr2) || !fs::exists(cc8)) GTEST_SKIP() << "no shared robots under " << kShared;
  const std::vector<std::vector<std::string>> cases = {
      {(pr2 / "robots" / "pr2.urdf.xacro").string(), "--package", "pr2_description=" + pr2.string()},
      {(cc8 / "urdf" / "cc8.xacro").string(), "--package", "cc8_description=" + cc8.string()},
  };
  for (const auto& args : cases) {
    std::vector<std::string> lean = {kXacro};
    std::vector<std::string> full = {MECHSIM_EXE, "xacro"};
    lean.insert(lean.end(), args.begin(), args.end());
    full.insert(full.end(), args.begin(), args.end());
    const ProcessResult a = run_process(lean, 60.0);
    const ProcessResult b = run_process(full, 60.0);
    ASSERT_EQ(a.exit_code, 0) << args[0] << ": " << a.err;
    ASSERT_EQ(b.exit_code, 0) << args[0] << ": " << b.err;
    EXPECT_GT(a.out.size(), 1000u);
    EXPECT_EQ(a.out, b.out) << args[0];
  }
}

TEST(XacroProgram, ErrorsAreNamedWithExitStatus1) {
  const ProcessResult missing = run_process({kXacro, "/nonexistent/robot.xacro"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("xacro: error: No such file or directory: /nonexistent/robot.xacro"));
  const ProcessResult mapping = run_process({kXacro, "/nonexistent/robot.xacro", "not_a_mapping"});
  EXPECT_EQ(mapping.exit_code, 1);
  EXPECT_THAT(mapping.err, HasSubstr("expected a mapping name:=value, got 'not_a_mapping'"));
  const ProcessResult none = run_process({kXacro});
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_THAT(none.err, HasSubstr("file is required"));
}

// What makes it lean: no MuJoCo, assimp or image codecs among the libraries it loads.
TEST(XacroProgram, LoadsNoSimulatorLibraries) {
  const ProcessResult ldd = run_process({"/usr/bin/ldd", kXacro});
  ASSERT_EQ(ldd.exit_code, 0) << ldd.err;
  for (const char* lib : {"libmujoco", "libassimp", "libpng", "libtiff", "liburdfdom"}) {
    EXPECT_THAT(ldd.out, Not(HasSubstr(lib)));
  }
}

// `mechsim` itself loads libsdformat (and its 28 ms of static initialisers) only to read SDF: not
// to expand xacro, whose speed roslaunch users feel (src/description/sdf/sdf_module.hpp).
TEST(XacroProgram, MechsimXacroLoadsNoSdformat) {
  const fs::path cc8 = kShared / "robots" / "cc8_description";
  if (!fs::exists(cc8)) GTEST_SKIP() << "no shared robots under " << kShared;
  const ProcessResult r = run_process({"/usr/bin/env", "LD_DEBUG=files", MECHSIM_EXE, "xacro",
                                       (cc8 / "urdf" / "cc8.xacro").string(), "--package", "cc8_description=" + cc8.string()},
                                      60.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(r.out.size(), 1000u);
  EXPECT_THAT(r.err, HasSubstr("libmujoco"));  // LD_DEBUG reports what the loader opens
  EXPECT_THAT(r.err, Not(HasSubstr("libsdformat")));
  EXPECT_THAT(r.err, Not(HasSubstr("libignition-math")));
}

}  // namespace
}  // namespace mechsim::apps::test
