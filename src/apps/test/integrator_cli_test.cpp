// `--integrator` of `mechsim run` and `mechsim bench`, and the scenario file's `integrator:` key,
// run as a user would: the chosen integrator is used and reported; a bad value is named.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A pendulum on a fixed base with a joint state controller: small enough to run in a blink.
constexpr const char* kUrdf = R"(<robot name="pendulum">
  <link name="world"/>
  <link name="arm"><inertial><mass value="1"/><origin xyz="0 0 -0.5"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="revolute"><parent link="world"/><child link="arm"/><origin xyz="0 0 1"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="5"/></joint>
</robot>
)";
constexpr const char* kControllers = "pendulum:\n  jsc: {type: joint_state_controller/JointStateController, publish_rate: 50}\n";

class IntegratorCli : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_integrator_cli_" + std::to_string(::getpid()) + "_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
    write_file((dir_ / "pendulum.urdf").string(), kUrdf);
    write_file((dir_ / "controllers.yaml").string(), kControllers);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string scenario(const std::string& extra) {
    const fs::path file = dir_ / "s.yaml";
    write_file(file.string(), "name: swing\nrobot: {description: pendulum.urdf}\n"
                              "controllers: {file: controllers.yaml, namespace: pendulum, start: [jsc]}\nduration: 0.05\n" +
                                  extra);
    return file.string();
  }
  ProcessResult mechsim(std::vector<std::string> args) {
    args.insert(args.begin(), MECHSIM_EXE);
    return run_process(args, 60.0);
  }
  fs::path dir_;
};

TEST_F(IntegratorCli, RunTakesTheScenarioIntegratorAndTheOverride) {
  const std::string file = scenario("integrator: rk4\n");
  const ProcessResult own = mechsim({"run", file, "--no-plots", "-o", (dir_ / "out").string()});
  ASSERT_TRUE(own.started);
  EXPECT_EQ(own.exit_code, 0) << own.out << own.err;
  EXPECT_THAT(own.out, HasSubstr("rk4 integrator"));
  const ProcessResult overridden = mechsim({"run", file, "--no-plots", "-o", (dir_ / "out").string(), "--integrator", "euler"});
  EXPECT_EQ(overridden.exit_code, 0) << overridden.out << overridden.err;
  EXPECT_THAT(overridden.out, HasSubstr("euler integrator"));
}

TEST_F(IntegratorCli, BadValuesAreNamed) {
  const ProcessResult option = mechsim({"run", scenario(""), "--integrator", "verlet"});
  EXPECT_NE(option.exit_code, 0);
  EXPECT_THAT(option.err + option.out, HasSubstr("--integrator"));
  EXPECT_THAT(option.err + option.out, HasSubstr("verlet"));
  const ProcessResult key = mechsim({"run", scenario("integrator: verlet\n"), "--no-plots", "-o", (dir_ / "out").string()});
  EXPECT_NE(key.exit_code, 0);
  EXPECT_THAT(key.err + key.out, HasSubstr("s.yaml"));
  EXPECT_THAT(key.err + key.out, HasSubstr("integrator: expected 'implicit', 'euler' or 'rk4', got 'verlet'"));
  const ProcessResult bench = mechsim({"bench", (dir_ / "pendulum.urdf").string(), "--integrator", "Euler"});
  EXPECT_NE(bench.exit_code, 0);
  EXPECT_THAT(bench.err + bench.out, HasSubstr("--integrator"));
}

TEST_F(IntegratorCli, BenchReportsTheIntegratorItMeasured) {
  const ProcessResult r = mechsim({"bench", (dir_ / "pendulum.urdf").string(), "--controllers", (dir_ / "controllers.yaml").string(),
                                   "--seconds", "0.05", "--integrator", "euler"});
  ASSERT_TRUE(r.started);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("euler integrator"));
  EXPECT_THAT(r.out, HasSubstr("real-time factor"));
}

}  // namespace
}  // namespace mechsim::apps::test
