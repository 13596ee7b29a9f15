// `mechsim soil` run as a user would: `soil fit` on the CMU sand's plate tests (from
// ../shared/soil/cmu_plate_sinkage, the shipped description) writes a soil file that `soil show`
// and a scenario read back, with its residuals and plot; bad input is named; `mechsim check` lists
// a rig's narrow wheel as a wheel and a sphere on a continuous joint as not one, with the reason.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "apps/test/run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path scratch() {
  struct Folder {
    fs::path path = fs::temp_directory_path() / ("mechsim_soil_cli_test_" + std::to_string(::getpid()));
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  fs::create_directories(folder.path);
  return folder.path;
}

ProcessResult mechsim(std::vector<std::string> args, double timeout_s = 60.0) {
  args.insert(args.begin(), MECHSIM_EXE);
  return run_process(args, timeout_s);
}

const fs::path kSpec = fs::path(MECHSIM_SOURCE_DIR) / "robots/single_wheel_rig/soil/cmu_sand_plates.yaml";

TEST(SoilCli, FitWritesASoilFileTheSimulationReadsWithItsResidualsAndPlot) {
  if (!fs::exists(fs::path(MECHSIM_SHARED_DIR) / "soil/cmu_plate_sinkage/samples"))
    GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/soil/cmu_plate_sinkage (MECHSIM_SHARED_DIR)";
  const fs::path out = scratch() / "fit";
  const ProcessResult r = mechsim({"soil", "fit", kSpec.string(), "-o", out.string(), "--name", "sand_cli"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("n      1.4765"));
  EXPECT_THAT(r.out, HasSubstr("k_c    -4.0647e+05"));
  EXPECT_THAT(r.out, HasSubstr("rms 936 Pa"));
  EXPECT_THAT(r.out, HasSubstr("not from these tests: cohesion, friction angle, shear modulus K"));
  for (const char* f : {"sand_cli.soil.yaml", "plate_fit.tsv", "plate_fit.png"}) EXPECT_TRUE(fs::exists(out / f)) << f;
  const ProcessResult show = mechsim({"soil", "show", (out / "sand_cli.soil.yaml").string()});
  ASSERT_EQ(show.exit_code, 0) << show.err;
  EXPECT_THAT(show.out, HasSubstr("name: \"sand_cli\""));
  EXPECT_THAT(show.out, HasSubstr("model: ding"));
  EXPECT_THAT(show.out, HasSubstr("k_c: -406474"));
  // The direct method, and the Wong-Reece model.
  const ProcessResult direct = mechsim({"soil", "fit", kSpec.string(), "-o", (scratch() / "direct").string(), "--method", "direct",
                                        "--model", "wong_reece", "--no-plots"});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  EXPECT_THAT(direct.out, HasSubstr("n      1.4164"));
  EXPECT_THAT(direct.out, HasSubstr("(wong_reece model)"));
  EXPECT_FALSE(fs::exists(scratch() / "direct/plate_fit.png"));
}

TEST(SoilCli, BadInputIsNamed) {
  const fs::path dir = scratch();
  write_file((dir / "one.tsv").string(), "z_m\tpressure_Pa\n0.001\t100\n0.002\t250\n");
  write_file((dir / "one_size.yaml").string(), "plates:\n  - {diameter: 0.06, files: [one.tsv, one.tsv]}\n");
  ProcessResult r = mechsim({"soil", "fit", (dir / "one_size.yaml").string(), "-o", (dir / "o").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("two plate sizes"));
  write_file((dir / "typo.yaml").string(), "plate:\n  - {diameter: 0.06, files: [one.tsv]}\n");
  r = mechsim({"soil", "fit", (dir / "typo.yaml").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("typo.yaml:"));
  EXPECT_THAT(r.err, HasSubstr("unknown key 'plate'"));
  r = mechsim({"soil", "show", "quicksand"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("no soil named 'quicksand'"));
}

TEST(SoilCli, CheckListsTheWheelsAndWhatIsNotOne) {
  const fs::path dir = scratch();
  write_file((dir / "rover.urdf").string(), R"(<robot name="rover">
  <link name="base"><inertial><mass value="5"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="narrow"><inertial><mass value="0.3"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963267948966 0 0"/><geometry><cylinder radius="0.058" length="0.05"/></geometry></collision></link>
  <link name="ball"><inertial><mass value="0.3"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <joint name="narrow_joint" type="continuous"><parent link="base"/><child link="narrow"/><origin xyz="0.2 0 0"/><axis xyz="0 1 0"/></joint>
  <joint name="ball_joint" type="continuous"><parent link="base"/><child link="ball"/><origin xyz="-0.2 0 0"/><axis xyz="0 1 0"/></joint>
</robot>)");
  const ProcessResult r = mechsim({"check", (dir / "rover.urdf").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wheel 'narrow' on joint 'narrow_joint': r 0.058 m, b 0.05 m (narrow: b <= r)"));
  EXPECT_THAT(r.out, HasSubstr("'ball' on joint 'ball_joint' is not a wheel: its collision is a sphere"));
}

}  // namespace
}  // namespace mechsim::apps::test
